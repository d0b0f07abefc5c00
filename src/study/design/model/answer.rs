//! The design's answer per pattern: the surrogate's ranking checked against the DEM.
//!
//! A DEM run **confirms superlubricity** at its load when it completed, did not lock in, kept
//! every contact's pressure at or below P_crit over its measuring window (max P_max ≤ P_crit)
//! and measured μ_DEM below the superlubric limit. A ranked design is
//!
//! - **confirmed** when every DEM run of the design's confirmation protocol at a confirmation
//!   load up to its superlubric load (`superlubric_to`, from the estimate) confirms
//!   superlubricity (at least one such run) and, with a fabrication tolerance, so does every
//!   run at the corners of its tolerance box at that load (the robust limit load: the centre
//!   AND the corners hold there);
//! - **contradicted** when one of them does not (the reason is kept: locked in, P_max above
//!   P_crit, μ_DEM above the limit, the run failed; for a corner, which corner);
//! - **unchecked** when it has no DEM run at such a load, or no corner run at its limit (not
//!   among the confirmed top K, or a superlubric load below the lowest confirmation load).
//!
//! **The answer** of a pattern is the best-ranked *confirmed* design among the DEM-checked top K;
//! when none is confirmed, the surrogate's best with what the DEM said about it; without the DEM
//! (`--no-dem`), the surrogate's best. Its load is the estimate's `superlubric_to` (the DEM
//! checks it at the confirmation loads up to that load and at that load itself, not in between).

use super::dem_entry::{DemEntry, DemProtocol};
use super::pattern_result::PatternResult;
use super::rank::Candidate;
use crate::study::recipe::Outside;
use surrogate::units::n_to_mn;

/// What an answer is decided by: how many of a pattern's designs the DEM checks, the
/// superlubric threshold and whether the tolerance box has corners to check. Copied from the
/// design's knobs once (`DesignParams::answer_rule`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnswerRule {
    /// Designs per pattern the DEM confirms (the top K).
    pub designs: usize,
    /// Friction coefficient below which a DEM run is superlubric.
    pub mu_superlubric: f64,
    /// The tolerance box has corners (a tolerance above 0): their runs must confirm too.
    pub corners: bool,
}

/// What the DEM says about one design.
#[derive(Debug, Clone, PartialEq)]
pub enum Check {
    /// The DEM did not run (`--no-dem`).
    NoDem,
    /// No DEM run at a confirmation load up to its superlubric load.
    Unchecked,
    /// Every such run confirms superlubricity; the loads (mN) checked.
    Confirmed(Vec<f64>),
    /// One of them does not: why.
    Contradicted(Contradiction),
}

/// Why the DEM contradicts a design (`crate::present` words it).
#[derive(Debug, Clone, PartialEq)]
pub struct Contradiction {
    /// Why the run is not superlubric ([`crate::study::verdict::dem_superlubric`]).
    pub why: String,
    /// The tolerance corner of the run (δθ, δdir; degrees), when it is a corner's.
    pub corner: Option<(f64, f64)>,
}

/// The answer of one pattern.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// Index into the pattern's ranking of the answer's design (`None`: no ranked design).
    pub index: Option<usize>,
    /// What the DEM says about it.
    pub check: Check,
    /// The other DEM-checked designs of the top K that were not confirmed: (rank, check).
    pub others: Vec<(usize, Check)>,
}

/// `Ok` if DEM run `e` confirms superlubricity, else why not
/// ([`crate::study::verdict::dem_superlubric`]).
pub fn dem_superlubric(e: &DemEntry, p_crit: f64, mu_sl: f64) -> Result<(), String> {
    crate::study::verdict::dem_superlubric(
        e.outcome.result.as_ref(),
        e.outcome.error.as_deref(),
        crate::study::rows::label(n_to_mn(e.run.load)),
        p_crit,
        mu_sl,
    )
}

/// What the DEM runs `dem` (the design's protocol) say about the design at `rank` (1-based) of
/// `pr`: its own runs up to its superlubric load, then — with a tolerance — the runs at the
/// corners of its box at that load (`confirm::corner_jobs`); the first that does not
/// confirm says why (a corner's reason names the corner). Cost: O(runs).
pub fn check(pr: &PatternResult, rank: usize, dem: &[DemEntry], rule: &AnswerRule) -> Check {
    let Some(c) = pr.ranking.get(rank - 1) else {
        return Check::Unchecked;
    };
    let p_crit = pr.scene.scene.coating.p_crit;
    let w_mn = |e: &DemEntry| crate::study::load::Load::from_n(e.run.load).mn();
    let corner = |e: &DemEntry| e.run.theta_offset_deg != 0.0 || e.run.direction_offset_deg != 0.0;
    let mut runs: Vec<&DemEntry> = dem
        .iter()
        .filter(|e| {
            e.run.pattern == pr.scene.name
                && e.run.protocol == DemProtocol::Design
                && !corner(e)
                && e.run.theta_deg == c.theta_deg
                && e.run.alpha_deg == c.alpha_deg
                && w_mn(e) <= c.score.superlubric_to_mn
        })
        .collect();
    runs.sort_by(|a, b| a.run.load.total_cmp(&b.run.load));
    if runs.is_empty() {
        return Check::Unchecked;
    }
    for e in &runs {
        if let Err(why) = dem_superlubric(e, p_crit, rule.mu_superlubric) {
            return Check::Contradicted(Contradiction { why, corner: None });
        }
    }
    if rule.corners && c.score.superlubric_to_mn > 0.0 {
        let corners: Vec<&DemEntry> = dem
            .iter()
            .filter(|e| {
                e.run.pattern == pr.scene.name
                    && e.run.protocol == DemProtocol::Design
                    && corner(e)
                    && e.run.rank == rank
                    && e.run.theta_deg
                        == crate::study::rows::label(c.theta_deg + e.run.theta_offset_deg)
                    && w_mn(e) == c.score.superlubric_to_mn
            })
            .collect();
        if corners.is_empty() {
            return Check::Unchecked;
        }
        for e in corners {
            if let Err(why) = dem_superlubric(e, p_crit, rule.mu_superlubric) {
                return Check::Contradicted(Contradiction {
                    why,
                    corner: Some((e.run.theta_offset_deg, e.run.direction_offset_deg)),
                });
            }
        }
    }
    Check::Confirmed(runs.iter().map(|e| w_mn(e)).collect())
}

/// The answer of `pr` (see the module docs). Cost: O(designs × runs).
pub fn answer(pr: &PatternResult, dem: &[DemEntry], dem_ran: bool, rule: &AnswerRule) -> Answer {
    if pr.ranking.is_empty() {
        return Answer {
            index: None,
            check: Check::Unchecked,
            others: vec![],
        };
    }
    if !dem_ran {
        return Answer {
            index: Some(0),
            check: Check::NoDem,
            others: vec![],
        };
    }
    let mut passed = Vec::new();
    for rank in 1..=rule.designs.min(pr.ranking.len()) {
        match check(pr, rank, dem, rule) {
            c @ Check::Confirmed(_) => {
                return Answer {
                    index: Some(rank - 1),
                    check: c,
                    others: passed,
                }
            }
            c => passed.push((rank, c)),
        }
    }
    let first = passed.first().map_or(Check::Unchecked, |(_, c)| c.clone());
    Answer {
        index: Some(0),
        check: first,
        others: passed.into_iter().skip(1).collect(),
    }
}

/// Why the design `c` of `pr` lies outside the range the verdict band was measured at, when
/// `pr` is a recipe (`design --vary`): its scene's reasons
/// ([`crate::study::recipe::validated_range`]) and [`Outside::MountResonance`] where one of its
/// friction rows is in the mount's resonance band. Empty for a pattern that is not a recipe,
/// and for a recipe inside the range: then the surrogate's verdict stands as for any pattern;
/// otherwise the DEM decides (its runs first, `auto` for `reduced`: [`super::super::confirm`]).
/// O(rows of `c`).
pub fn outside_range(pr: &PatternResult, c: &Candidate) -> Vec<Outside> {
    let Some(r) = &pr.scene.recipe else {
        return Vec::new();
    };
    let mut v = r.outside.clone();
    if c.friction.iter().any(|r| r.mount_resonance == Some(true)) {
        v.push(Outside::MountResonance);
    }
    v
}
