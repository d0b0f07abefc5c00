//! The evaluation of one shortlisted orientation: its contact line, the corrugation versus the
//! pulling angle α (a coarse grid over one α period, then finer grids around the minimum), and
//! the friction estimate at every load along the best α's.
//!
//! - **Scan.** Corrugation (peak-to-peak slider height) along straight paths of `scan_length`
//!   sampled every `scan_step` (direct solves, [`surrogate::map::corrugation_direct`]), at the
//!   orientation's coating-intact load `W_c` (where the design has to work; the lowest load if
//!   none). Coarse: α = k·`alpha_step` over [0, P_α) (P_α the α period,
//!   [`super::symmetry`]: 0 is along the contact line, 90° across it); each refinement step r
//!   scans the best α so far ± half the previous step in steps of r (folded into [0, P_α),
//!   angles already scanned not repeated). A full-turn period (P_α = 360°) is scanned as
//!   (−180°, 180°], the range of a pulling angle.
//! - **Best α's.** The `alphas_per_theta` lowest-corrugation angles at least one coarse step
//!   apart (circularly within the period); ties: the first in scan order.
//! - **Friction.** [`surrogate::friction::estimate_friction_loads`] along each best α: first at
//!   the lowest load; if the candidate is superlubric there (coating intact on the path and
//!   μ_est below the limit), at the other loads up to the orientation's coating-intact load
//!   `W_c`, ascending, up to and including the first load whose coating fails on the sliding
//!   path (beyond it neither the score nor the intact-to load of the ranking can change;
//!   each estimate is bit-identical to one path for all loads). Loads above `W_c` are not
//!   estimated: the coating fails there at the screened placement, the first sample of every
//!   path, so the candidate cannot
//!   be superlubric there; nor are any loads above the lowest when it is not superlubric at the
//!   lowest (the score needs superlubricity from the lowest load up). The confirmation stage
//!   adds estimates at the DEM loads that lack one.

use super::params::DesignParams;
use super::symmetry::PairSymmetry;
use crate::study::corrugation::contact_line;
use crate::study::rows::{clean, CorrugationRow, FrictionRow};
use anyhow::Result;
use serde::{Deserialize, Serialize};
use surrogate::friction::estimate_friction_loads;
use surrogate::map::{corrugation_direct, MapParams};
use surrogate::solver::Solver;
use surrogate::units::deg_to_rad;
use surrogate::Scene;

/// The evaluation of one orientation (user units, as stored in the design's stage files).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ThetaEval {
    /// θ (degrees).
    pub theta_deg: f64,
    /// Load of the α scan (mN).
    pub scan_load_mN: f64,
    /// Contact line used (degrees from x).
    pub line_deg: f64,
    /// The α scan, in scan order (coarse grid, then each refinement).
    pub scan: Vec<CorrugationRow>,
    /// The best α's (degrees), best first.
    pub alphas_deg: Vec<f64>,
    /// The friction estimate along each best α (α outer, load inner): the loads up to `W_c`
    /// (ascending, up to the first whose coating fails on the path), or only the lowest when
    /// the candidate is not superlubric there.
    pub friction: Vec<FrictionRow>,
}

/// Loads per friction path after the lowest (they share the path's candidate searches and pair
/// lists; the estimate stops after the chunk holding the first load whose coating fails): a
/// cost knob only, the rows kept are bit-identical for any value.
const LOAD_CHUNK: usize = 3;

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
pub fn paths_per_scan(p: &DesignParams, sym: &PairSymmetry) -> usize {
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

/// The α scan of orientation `theta_deg` of `scene` at `scan_load` (N) and its best α's (see
/// the module docs). `tick` is called once per scanned path. Cost: the coarse grid plus each
/// refinement's new angles, one corrugation path each ([`paths_per_scan`]).
#[allow(clippy::too_many_arguments)]
pub fn scan_alpha(
    solver: &Solver,
    scene: &Scene,
    theta_deg: f64,
    scan_load: f64,
    p: &DesignParams,
    sym: &PairSymmetry,
    tick: &(dyn Fn() + Sync),
) -> Result<AlphaScan> {
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

/// The friction estimate of orientation `theta_deg` along each best α of `scan` (see the
/// module docs): the lowest load, then, while superlubric, the loads up to `scan_load` (N)
/// until the coating fails on the path. `tick` is called once per α. Cost: one friction path
/// per α and chunk of loads.
pub fn estimate(
    solver: &Solver,
    scene: &Scene,
    theta_deg: f64,
    scan_load: f64,
    scan: &AlphaScan,
    p: &DesignParams,
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<FrictionRow>> {
    let theta = deg_to_rad(theta_deg);
    let line_angle = scan.line;
    let mut friction = Vec::new();
    let p_crit = scene.coating.p_crit;
    for &a in &scan.alphas_deg {
        let alpha = deg_to_rad(a);
        let dir = line_angle + alpha;
        let row = |w: f64, r: &Result<_, _>| {
            let mut row = FrictionRow::new(&scene.pattern, theta, alpha, line_angle, w, r);
            row.alpha_deg = a;
            row
        };
        // loads up to the scan load (the screen's coating-intact load W_c): beyond it the
        // coating fails at the screened placement, the path's first sample
        let upto = p
            .loads
            .iter()
            .position(|&w| w >= scan_load * (1.0 - 1e-12))
            .map_or(p.loads.len(), |k| k + 1);
        let lowest = estimate_friction_loads(solver, theta, dir, &p.loads[..1], &p.friction)?;
        let first = row(p.loads[0], &lowest[0]);
        let go_on = crate::study::verdict::superlubric(&first, p_crit, p.mu_superlubric);
        friction.push(first);
        if go_on {
            // ascending, LOAD_CHUNK loads per path (bit-identical to one path for all), up to
            // and including the first load whose coating fails on the path: beyond it neither
            // the score nor the intact-to load can change
            'chunks: for chunk in p.loads[1..upto].chunks(LOAD_CHUNK) {
                let r = estimate_friction_loads(solver, theta, dir, chunk, &p.friction)?;
                for (&w, r) in chunk.iter().zip(&r) {
                    let next = row(w, r);
                    let failed = !crate::study::verdict::intact(&next, p_crit);
                    friction.push(next);
                    if failed {
                        break 'chunks;
                    }
                }
            }
        }
        tick();
    }
    Ok(friction)
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
