//! Tolerance of a design: how the superlubric limit load moves when the slider is rotated by
//! δθ and pulled δd off its nominal direction.
//!
//! A misaligned slider keeps the nominal pull direction **in the substrate frame** (the
//! tribometer's axis does not rotate with the slider): the sample (θ + δθ, d + δd) is pulled
//! along d + δd from the substrate's x axis, i.e. at α' = d + δd − line(θ + δθ) from its own
//! contact line.
//!
//! **Superlubric limit** of a sample: the highest load W_k of the list such that the friction
//! estimate is superlubric (coating intact on the path, μ_est < μ_sl) at every load W_1 … W_k
//! (the design's score, [`crate::study::design::rank`]). Pruning, exact: the screen's P_max at
//! the placement is the first sample of the path, so a load whose coating fails there cannot be
//! superlubric; no load at or above the first such load is estimated ([`placement_intact`]).
//!
//! Two uses: the map of `superlube tolerance` ([`map()`]: every grid point to its own limit) and
//! the robust limit of `design` ([`RobustSearch`]: the lowest limit over a tolerance box, found
//! by single-load disproofs from the top down and one verification path per sample).
//!
//! Cost: about 10–30 ms per (sample, load) estimated on the study scenes, plus 8–30 ms per
//! friction path (`cargo bench --bench friction`), plus one multi-load screen solve per θ.
//! Why the evaluation order is what it is: docs/validation/tolerance-cost.md.

mod map;
mod robust;
mod snapshot;

pub use map::{map, MapParams, ToleranceRow};
pub use robust::{Offset, Robust, RobustSearch, RobustState, ToleranceBox};
pub use snapshot::Snapshot;

use super::corrugation::contact_line;
use super::rows::{label, FrictionRow};
use super::verdict::superlubric;
use anyhow::Result;
use surrogate::friction::{estimate_friction_loads, FrictionParams};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::units::deg_to_rad;

/// Loads per friction path above a guess (a cost knob only: each estimate is bit-identical for
/// any grouping of loads into paths).
pub const LOAD_CHUNK: usize = 3;

/// What the limit of a sample is computed against (SI inside).
#[derive(Debug, Clone)]
pub struct LimitParams {
    /// Loads W (N), strictly increasing.
    pub loads: Vec<f64>,
    /// μ below which a row is superlubric (study: 0.02).
    pub mu_superlubric: f64,
    /// Contact line (rad from x) for every θ; `None`: the moiré estimate at each θ (for α).
    pub line: Option<f64>,
    /// The friction estimate's knobs.
    pub friction: FrictionParams,
}

/// The symmetric offsets (degrees) −tol … +tol in equal steps no larger than `step`, 0
/// included: `[0]` when `tol` is 0. Example: tol 0.1, step 0.02 → −0.1, −0.08, …, 0.1.
pub fn offsets(tol: f64, step: f64) -> Vec<f64> {
    if tol <= 0.0 {
        return vec![0.0];
    }
    let n = (tol / step - 1e-9).ceil().max(1.0) as i64;
    (-n..=n)
        .map(|k| super::rows::clean(tol * k as f64 / n as f64))
        .collect()
}

/// How many of the leading `loads` keep the coating intact at the placement of orientation θ
/// (rad): the screen's P_max ≤ P_crit (a load without equilibrium ends the count).
pub fn placement_intact(solver: &Solver, theta: f64, loads: &[f64]) -> usize {
    let p_crit = solver.scene().coating.p_crit;
    let pose = Pose {
        theta,
        shift: [0.0, 0.0],
    };
    solver
        .solve_loads(pose, loads, Model::Auto)
        .iter()
        .take_while(|r| r.as_ref().is_ok_and(|e| e.p_max <= p_crit))
        .count()
}

/// The friction rows of (θ, direction) (degrees; direction from the substrate's x axis) at the
/// loads `which` (indices into [`LimitParams::loads`], ascending), on one path.
pub fn rows_at(
    solver: &Solver,
    theta_deg: f64,
    direction_deg: f64,
    which: &[usize],
    p: &LimitParams,
) -> Result<Vec<FrictionRow>> {
    let scene = solver.scene();
    let theta = deg_to_rad(theta_deg);
    let line = contact_line(&scene.with_theta(theta), p.line).angle;
    let dir = deg_to_rad(direction_deg);
    let loads: Vec<f64> = which.iter().map(|&k| p.loads[k]).collect();
    let r = estimate_friction_loads(solver, theta, dir, &loads, &p.friction)?;
    Ok(loads
        .iter()
        .zip(&r)
        .map(|(&w, r)| {
            let mut row = FrictionRow::new(&scene.pattern, theta, dir - line, line, w, r);
            row.theta_deg = label(theta_deg);
            row.direction_deg = label(direction_deg);
            row
        })
        .collect())
}

/// The friction rows of (θ, direction) (degrees) at the first `cap` loads, ascending, up to and
/// including the first row that is not superlubric, and the number of rows estimated (paths
/// may run past that row). The first path runs the loads up to `guess + 1` (a neighbour's
/// limit: one path where the guess is right), the next ones [`LOAD_CHUNK`] loads each.
pub fn rows_upto(
    solver: &Solver,
    theta_deg: f64,
    direction_deg: f64,
    cap: usize,
    guess: usize,
    p: &LimitParams,
) -> Result<(Vec<FrictionRow>, usize)> {
    let p_crit = solver.scene().coating.p_crit;
    let cap = cap.min(p.loads.len());
    let mut rows = Vec::new();
    let mut estimated = 0;
    let mut from = 0;
    let mut width = (guess + 1).max(1);
    while from < cap {
        let to = (from + width).min(cap);
        let which: Vec<usize> = (from..to).collect();
        let got = rows_at(solver, theta_deg, direction_deg, &which, p)?;
        estimated += got.len();
        for row in got {
            let ok = superlubric(&row, p_crit, p.mu_superlubric);
            rows.push(row);
            if !ok {
                return Ok((rows, estimated));
            }
        }
        from = to;
        width = LOAD_CHUNK;
    }
    Ok((rows, estimated))
}

/// Number of leading superlubric rows.
pub fn superlubric_count(rows: &[FrictionRow], p_crit: f64, mu_sl: f64) -> usize {
    rows.iter()
        .take_while(|r| superlubric(r, p_crit, mu_sl))
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_are_symmetric_and_fine_enough() {
        assert_eq!(offsets(0.0, 0.02), vec![0.0]);
        let o = offsets(0.1, 0.02);
        assert_eq!(o.len(), 11);
        assert_eq!(o[0], -0.1);
        assert_eq!(o[5], 0.0);
        assert_eq!(o[10], 0.1);
        let o = offsets(0.5, 0.3);
        assert_eq!(o, vec![-0.5, -0.25, 0.0, 0.25, 0.5]);
    }
}
