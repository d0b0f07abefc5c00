//! The θ list of a pattern: the symmetry cut of `--theta` to the pair's domain, the default
//! list over a whole domain, and the notes that say what was (not) screened.

use super::symmetry_words::{Domain, PairSymmetry, SymmetryWords};
use super::{DesignParams, DesignScene};
use crate::study::input::Input;
use anyhow::{bail, Result};

/// Default θ step (degrees) over a domain up to [`WIDE_DOMAIN_DEG`] wide (the study's 0.1°).
pub const THETA_STEP_DEG: f64 = 0.1;
/// Width (degrees) above which a domain is screened at [`WIDE_THETA_STEP_DEG`] by default.
pub const WIDE_DOMAIN_DEG: f64 = 60.0;
/// Default θ step (degrees) over a wider domain (the full 360° of an underived symmetry: 1 440
/// θ, about 1.7 s of screen for a 3 500-sphere slider at 1.2 ms per θ × 11 loads,
/// `docs/validation/screen.md`).
pub const WIDE_THETA_STEP_DEG: f64 = 0.25;

/// Without `--theta` (`p.theta_default`) and with the cut: the θ list of the whole fundamental
/// domain of `sym` at the default step ([`THETA_STEP_DEG`], [`WIDE_THETA_STEP_DEG`] over a
/// domain wider than [`WIDE_DOMAIN_DEG`]) when the default list `0:30:0.1` does not span the
/// domain (a pattern whose symmetry was not derived, or a domain wider than 30°); `None` where
/// the default list spans it (the presets: their cut default list, unchanged). Also the step.
pub fn default_domain(sym: &PairSymmetry, p: &DesignParams) -> Option<(Vec<f64>, f64)> {
    if !p.theta_default || !p.symmetry_cut {
        return None;
    }
    let cut: Vec<f64> = p
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
        super::symmetry_words::fmt(lo),
        super::symmetry_words::fmt(hi),
        step
    );
    let mut v = crate::study::range::parse_list_or_range(&text, "θ").ok()?;
    if !closed {
        v.retain(|&t| t < hi - 1e-9);
    }
    Some((v, step))
}

/// What the log and the report say of a pattern's θ list beside its symmetry.
#[derive(Debug, Clone, PartialEq)]
pub struct ThetaNote {
    /// The sentence.
    pub text: String,
    /// Whether the θ list leaves part of the domain out (the report puts that in bold).
    pub uncovered: bool,
}

/// The [`ThetaNote`] of a pattern's θ list: which part of the domain the θ list leaves out
/// ([`PairSymmetry::unscreened`]), or that `--theta` was not given and the whole domain is
/// screened at the default step (when [`default_domain`] applies); `None` when the list spans
/// the domain as asked.
pub fn theta_note(sym: &PairSymmetry, thetas_deg: &[f64], p: &DesignParams) -> Option<ThetaNote> {
    let gaps = sym.unscreened(thetas_deg);
    if !gaps.is_empty() {
        let Domain {
            lo_deg: lo,
            hi_deg: hi,
            closed,
        } = sym.domain();
        let text = format!(
            "the θ list does not cover the domain [{}°, {}°{}: {} not screened (give {} over the whole domain{})",
            super::symmetry_words::fmt(lo),
            super::symmetry_words::fmt(hi),
            if closed { "]" } else { ")" },
            sym.gaps_text(&gaps),
            Input::Theta,
            if p.theta_default {
                String::new()
            } else {
                format!(", or leave {} out to screen it at the default step", Input::Theta)
            }
        );
        return Some(ThetaNote {
            text,
            uncovered: true,
        });
    }
    let (_, step) = default_domain(sym, p)?;
    let text = format!(
        "no {} given: the whole domain at {step}° ({} θ{})",
        Input::Theta,
        thetas_deg.len(),
        if step == WIDE_THETA_STEP_DEG {
            format!(
                "; {step}° rather than {THETA_STEP_DEG}° for a domain wider than {WIDE_DOMAIN_DEG}°"
            )
        } else {
            String::new()
        }
    );
    Some(ThetaNote {
        text,
        uncovered: false,
    })
}

/// Without `--line-deg`, for a pattern with a site file: that α is measured from the substrate
/// x axis, since the file's body has no lattice for the moiré contact-line estimate
/// ([`crate::study::corrugation::contact_line`]); `None` otherwise.
pub fn line_note(ds: &DesignScene, p: &DesignParams) -> Option<String> {
    if p.line.is_some() {
        return None;
    }
    let why = crate::study::corrugation::site_file_body(&ds.scene)?;
    Some(format!(
        "{why}, which has no lattice for the moiré contact-line estimate: α is measured from the substrate x axis (0°; {} sets the line), and the α scan covers a whole α period from it",
        Input::LineDeg
    ))
}

/// The θ values (degrees) of `ds` after the symmetry cut, and the pair's symmetry. Without
/// `--theta`, the whole domain where the default list does not span it ([`default_domain`]).
/// Errors (naming `--theta`) when none is left.
pub fn cut(ds: &DesignScene, p: &DesignParams) -> Result<(Vec<f64>, PairSymmetry)> {
    let sym = PairSymmetry::of_scene(&ds.scene);
    if let Some((v, _)) = default_domain(&sym, p) {
        return Ok((v, sym));
    }
    if !p.symmetry_cut {
        return Ok((p.thetas_deg.clone(), sym));
    }
    let kept: Vec<f64> = p
        .thetas_deg
        .iter()
        .copied()
        .filter(|&t| sym.contains(t))
        .collect();
    if kept.is_empty() {
        let Domain {
            lo_deg: lo,
            hi_deg: hi,
            closed,
        } = sym.domain();
        let t = p.thetas_deg[0];
        bail!(
            "{}: none of `{}` lies in the fundamental domain [{}°, {}°{} of {} ({}); every orientation is equivalent to one in it (e.g. {}° ≡ {}°): give θ in [{}, {}], or pass {}",
            Input::Theta,
            p.theta_text,
            super::symmetry_words::fmt(lo),
            super::symmetry_words::fmt(hi),
            if closed { "]" } else { ")" },
            ds.name,
            sym.describe(),
            super::symmetry_words::fmt(t),
            super::symmetry_words::fmt(sym.fold(t)),
            super::symmetry_words::fmt(lo),
            super::symmetry_words::fmt(hi),
            Input::NoSymmetryCut
        );
    }
    Ok((kept, sym))
}
