//! Stage 3 of a design, the α scan, for one shortlisted orientation: its
//! contact line and the corrugation versus the pulling angle α (a coarse grid over one α
//! period, then finer grids around the minimum), and the best α's, which the estimate
//! ([`super::estimate`]) follows. [`super::EvaluateStage`] runs it on a shortlist level's
//! orientations side by side.
//!
//! - **Scan.** Corrugation (peak-to-peak slider height) along straight paths of `scan_length`
//!   sampled every `scan_step` (direct solves, [`surrogate::map::corrugation_direct`]), at the
//!   orientation's coating-intact load `W_c` (where the design has to work; the lowest load if
//!   none). Coarse: α = k·`alpha_step` over [0, P_α) (P_α the α period,
//!   [`crate::study::design::symmetry_words`]: 0 is along the contact line, 90° across it); each refinement step r
//!   scans the best α so far ± half the previous step in steps of r (folded into [0, P_α),
//!   angles already scanned not repeated). A full-turn period (P_α = 360°) is scanned as
//!   (−180°, 180°], the range of a pulling angle.
//! - **Best α's.** The `alphas_per_theta` lowest-corrugation angles at least one coarse step
//!   apart (circularly within the period); ties: the first in scan order.
use super::params::AlphaScanParams;
use crate::study::corrugation::contact_line;
use crate::study::design::symmetry_words::PairSymmetry;
use crate::study::rows::{clean, CorrugationRow};
use anyhow::Result;
use surrogate::map::{corrugation_direct, MapParams};
use surrogate::solver::Solver;
use surrogate::units::deg_to_rad;
use surrogate::Scene;

/// Path length (m) sharing one refresh of the α scan's pair lists: the maps' default, so the
/// design's corrugation rows are the `corrugation` command's (a chunk of twelve shares one
/// candidate search; docs/validation/path-solve.md).
const SEGMENT: f64 = 0.5e-6;

/// A degree value folded into [0, p) and cleaned to 1e-9°; with a full-turn period (p =
/// 360°: a pattern without a common rotation, or whose symmetry was not derived) into
/// (−180°, 180°], the range of a pulling angle.
fn fold_alpha(a: f64, p: f64) -> f64 {
    let v = clean(a.rem_euclid(p));
    let v = if v >= p - 1e-9 { 0.0 } else { v };
    signed(v, p)
}

/// `v` in [0, p) as a pulling angle: unchanged for p ≤ 180°, else above 180° one turn down.
fn signed(v: f64, p: f64) -> f64 {
    if p > 180.0 + 1e-9 && v > 180.0 + 1e-9 {
        clean(v - 360.0)
    } else {
        v
    }
}

/// Circular distance of two α (degrees) within the period `p`.
fn alpha_distance(a: f64, b: f64, p: f64) -> f64 {
    let d = (a - b).rem_euclid(p);
    d.min(p - d)
}

/// The coarse α grid (degrees) over [0, p) with step `step` (over (−180°, 180°] for p = 360°,
/// `fold_alpha`).
pub fn coarse_grid(p: f64, step: f64) -> Vec<f64> {
    let n = (p / step - 1e-9).ceil().max(1.0) as usize;
    (0..n).map(|k| signed(clean(k as f64 * step), p)).collect()
}

/// Number of corrugation paths the scan of one orientation solves (for progress and budgets):
/// the coarse grid plus each refinement's new angles (at most).
pub fn paths_per_scan(p: &AlphaScanParams, sym: &PairSymmetry) -> usize {
    let mut n = coarse_grid(sym.alpha_period_deg, p.alpha_step_deg).len();
    let mut prev = p.alpha_step_deg;
    for &r in &p.alpha_refine_deg {
        n += 2 * (0.5 * prev / r + 1e-9).floor() as usize;
        prev = r;
    }
    n
}

/// The α scan of one orientation (the stage before the estimate).
#[derive(Debug, Clone, PartialEq)]
pub struct AlphaScan {
    /// Contact line used (rad from x).
    pub line: f64,
    /// The scan rows, in scan order (coarse grid, then each refinement).
    pub scan: Vec<CorrugationRow>,
    /// The best α's (degrees), best first.
    pub alphas_deg: Vec<f64>,
}

/// One orientation of a pattern as the α scan and the estimate take it: the pattern's solver
/// (slider at θ = 0) and scene, θ (degrees) and the load of the scan (N: the orientation's
/// coating-intact load `W_c`).
#[derive(Clone, Copy)]
pub struct Target<'a> {
    /// The pattern's solver (each query rotates the slider to θ).
    pub solver: &'a Solver,
    /// The pattern's scene (SI).
    pub scene: &'a Scene,
    /// θ (degrees).
    pub theta_deg: f64,
    /// The load of the scan (N).
    pub scan_load: f64,
}

/// The α scan of the orientation `t` and its best α's (see the module docs). `tick` is called
/// once per scanned path. Cost: the coarse grid plus each refinement's new angles, one
/// corrugation path each ([`paths_per_scan`]).
pub fn scan_alpha(
    t: &Target,
    p: &AlphaScanParams,
    sym: &PairSymmetry,
    tick: &(dyn Fn() + Sync),
) -> Result<AlphaScan> {
    let Target {
        solver,
        scene,
        theta_deg,
        scan_load,
    } = *t;
    let theta = deg_to_rad(theta_deg);
    let line = contact_line(&scene.with_theta(theta), p.line);
    let map = MapParams {
        distance: p.scan_length,
        step: p.scan_step,
        segment: SEGMENT,
        ..MapParams::default()
    };
    let period = sym.alpha_period_deg;
    let mut scan: Vec<CorrugationRow> = Vec::new();
    let run = |alphas: &[f64], scan: &mut Vec<CorrugationRow>| -> Result<()> {
        let todo: Vec<f64> = alphas
            .iter()
            .copied()
            .filter(|a| !scan.iter().any(|r| (r.alpha_deg - a).abs() < 1e-9))
            .collect();
        for a in todo {
            let pts = corrugation_direct(
                solver,
                theta,
                scan_load,
                line.angle,
                &[deg_to_rad(a)],
                &map,
                &|| {},
            )?;
            let mut row = CorrugationRow::new(theta, scan_load, line.angle, &pts[0]);
            row.alpha_deg = a; // the decimal meant (exact in reproduction commands)
            scan.push(row);
            tick();
        }
        Ok(())
    };
    let best_of = |scan: &[CorrugationRow]| -> f64 {
        scan.iter()
            .min_by(|a, b| a.corrugation_nm.total_cmp(&b.corrugation_nm))
            .map_or(0.0, |r| r.alpha_deg)
    };
    run(&coarse_grid(period, p.alpha_step_deg), &mut scan)?;
    let mut prev = p.alpha_step_deg;
    for &r in &p.alpha_refine_deg {
        let best = best_of(&scan);
        let k = (0.5 * prev / r + 1e-9).floor() as i64;
        let fine: Vec<f64> = (-k..=k)
            .filter(|&j| j != 0)
            .map(|j| fold_alpha(best + j as f64 * r, period))
            .collect();
        run(&fine, &mut scan)?;
        prev = r;
    }
    // best α's: lowest corrugation, at least one coarse step apart
    let mut order: Vec<&CorrugationRow> = scan.iter().collect();
    order.sort_by(|a, b| a.corrugation_nm.total_cmp(&b.corrugation_nm));
    let mut alphas: Vec<f64> = Vec::new();
    for r in order {
        if alphas.len() >= p.alphas_per_theta {
            break;
        }
        if alphas
            .iter()
            .all(|&a| alpha_distance(a, r.alpha_deg, period) >= p.alpha_step_deg - 1e-9)
        {
            alphas.push(r.alpha_deg);
        }
    }
    Ok(AlphaScan {
        line: line.angle,
        scan,
        alphas_deg: alphas,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grids_and_folding() {
        assert_eq!(coarse_grid(180.0, 15.0).len(), 12);
        assert_eq!(coarse_grid(180.0, 15.0)[6], 90.0);
        assert_eq!(coarse_grid(60.0, 15.0), vec![0.0, 15.0, 30.0, 45.0]);
        assert_eq!(coarse_grid(60.0, 25.0), vec![0.0, 25.0, 50.0]);
        assert_eq!(fold_alpha(-89.0, 180.0), 91.0);
        assert_eq!(fold_alpha(180.0, 180.0), 0.0);
        assert_eq!(fold_alpha(-0.5, 60.0), 59.5);
        // a full-turn period: pulling angles in (−180°, 180°]
        assert_eq!(fold_alpha(225.0, 360.0), -135.0);
        assert_eq!(fold_alpha(180.0, 360.0), 180.0);
        assert_eq!(fold_alpha(-0.5, 360.0), -0.5);
        assert_eq!(
            coarse_grid(360.0, 90.0),
            vec![0.0, 90.0, 180.0, -90.0],
            "every grid angle a valid α"
        );
        assert_eq!(alpha_distance(89.0, -89.0, 180.0), 2.0);
    }
}
