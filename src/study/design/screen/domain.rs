//! The θ list of a pattern: the symmetry cut of `--theta` to the pair's domain, the default
//! list over a whole domain, and the notes that say what was (not) screened.

use super::params::ScreenStageParams;
use crate::study::design::model::DesignScene;
use crate::study::design::symmetry_words::{Domain, PairSymmetry};
use crate::study::input::Input;

/// Default θ step (degrees) over a domain up to [`WIDE_DOMAIN_DEG`] wide (the study's 0.1°).
pub const THETA_STEP_DEG: f64 = 0.1;
/// Width (degrees) above which a domain is screened at [`WIDE_THETA_STEP_DEG`] by default.
pub const WIDE_DOMAIN_DEG: f64 = 60.0;
/// Default θ step (degrees) over a wider domain (the full 360° of an underived symmetry: 1 440
/// θ, about 1.7 s of screen for a 3 500-sphere slider at 1.2 ms per θ × 11 loads,
/// `docs/validation/screen.md`).
pub const WIDE_THETA_STEP_DEG: f64 = 0.25;

/// Without `--theta` (`s.theta_default`) and with the cut: the θ list of the whole fundamental
/// domain of `sym` at the default step ([`THETA_STEP_DEG`], [`WIDE_THETA_STEP_DEG`] over a
/// domain wider than [`WIDE_DOMAIN_DEG`]) when the default list `0:30:0.1` does not span the
/// domain (a pattern whose symmetry was not derived, or a domain wider than 30°); `None` where
/// the default list spans it (the presets: their cut default list, unchanged). Also the step.
pub fn default_domain(sym: &PairSymmetry, s: &ScreenStageParams) -> Option<(Vec<f64>, f64)> {
    if !s.theta_default || !s.symmetry_cut {
        return None;
    }
    let cut: Vec<f64> = s
        .thetas_deg
        .iter()
        .copied()
        .filter(|&t| sym.contains(t))
        .collect();
    if !cut.is_empty() && sym.unscreened(&cut).is_empty() {
        return None;
    }
    let Domain {
        lo_deg: lo,
        hi_deg: hi,
        closed,
    } = sym.domain();
    let step = if hi - lo > WIDE_DOMAIN_DEG + 1e-9 {
        WIDE_THETA_STEP_DEG
    } else {
        THETA_STEP_DEG
    };
    let text = format!(
        "{}:{}:{}",
        crate::study::design::symmetry_words::fmt(lo),
        crate::study::design::symmetry_words::fmt(hi),
        step
    );
    let mut v = crate::study::range::parse_list_or_range(&text, "θ").ok()?;
    if !closed {
        v.retain(|&t| t < hi - 1e-9);
    }
    Some((v, step))
}

/// What the log and the report note of a pattern's θ list beside its symmetry
/// (`crate::present` words it).
#[derive(Debug, Clone, PartialEq)]
pub enum ThetaNote {
    /// The θ list leaves part of the domain out (the report puts that in bold).
    Uncovered {
        /// The parts left out ([`PairSymmetry::unscreened`]; degrees).
        gaps: Vec<(f64, f64)>,
        /// `--theta` was not given (else the note also says leaving it out screens the whole
        /// domain).
        theta_default: bool,
    },
    /// `--theta` was not given: the whole domain is screened at the default step.
    WholeDomain {
        /// The step (degrees).
        step: f64,
        /// θ screened.
        thetas: usize,
    },
}

impl ThetaNote {
    /// Whether the θ list leaves part of the domain out.
    pub fn uncovered(&self) -> bool {
        matches!(self, ThetaNote::Uncovered { .. })
    }
}

/// The [`ThetaNote`] of a pattern's θ list: which part of the domain the θ list leaves out
/// ([`PairSymmetry::unscreened`]), or that `--theta` was not given and the whole domain is
/// screened at the default step (when [`default_domain`] applies); `None` when the list spans
/// the domain as asked.
pub fn theta_note(
    sym: &PairSymmetry,
    thetas_deg: &[f64],
    s: &ScreenStageParams,
) -> Option<ThetaNote> {
    let gaps = sym.unscreened(thetas_deg);
    if !gaps.is_empty() {
        return Some(ThetaNote::Uncovered {
            gaps,
            theta_default: s.theta_default,
        });
    }
    let (_, step) = default_domain(sym, s)?;
    Some(ThetaNote::WholeDomain {
        step,
        thetas: thetas_deg.len(),
    })
}

/// Without `--line-deg`, for a pattern with a site file: that α is measured from the substrate
/// x axis, since the file's body has no lattice for the moiré contact-line estimate
/// ([`crate::study::corrugation::contact_line`]); `None` otherwise.
pub fn line_note(ds: &DesignScene, line: Option<f64>) -> Option<String> {
    if line.is_some() {
        return None;
    }
    let why = crate::study::corrugation::site_file_body(&ds.scene)?;
    Some(format!(
        "{why}, which has no lattice for the moiré contact-line estimate: α is measured from the substrate x axis (0°; {} sets the line), and the α scan covers a whole α period from it",
        Input::LineDeg
    ))
}

/// None of the θ given lies in a pattern's fundamental domain: what [`cut`] refuses (worded
/// by `crate::present`, which names `--theta` and the way out).
#[derive(Debug, Clone)]
pub struct OutsideDomain {
    /// The pattern.
    pub pattern: String,
    /// The θ given (degrees).
    pub thetas_deg: Vec<f64>,
    /// The pair's symmetry (its domain, its description, the fold of a θ into it).
    pub sym: PairSymmetry,
}

impl std::error::Error for OutsideDomain {}

/// The θ values (degrees) of `ds` after the symmetry cut, and the pair's symmetry. Without
/// `--theta`, the whole domain where the default list does not span it ([`default_domain`]).
/// Errors ([`OutsideDomain`]) when none is left.
pub fn cut(
    ds: &DesignScene,
    s: &ScreenStageParams,
) -> Result<(Vec<f64>, PairSymmetry), OutsideDomain> {
    let sym = PairSymmetry::of_scene(&ds.scene);
    if let Some((v, _)) = default_domain(&sym, s) {
        return Ok((v, sym));
    }
    if !s.symmetry_cut {
        return Ok((s.thetas_deg.clone(), sym));
    }
    let kept: Vec<f64> = s
        .thetas_deg
        .iter()
        .copied()
        .filter(|&t| sym.contains(t))
        .collect();
    if kept.is_empty() {
        return Err(OutsideDomain {
            pattern: ds.name.clone(),
            thetas_deg: s.thetas_deg.clone(),
            sym,
        });
    }
    Ok((kept, sym))
}
