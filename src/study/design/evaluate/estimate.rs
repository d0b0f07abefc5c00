//! Stage 4 of a design, the friction estimate, for one shortlisted orientation: the
//! friction estimate μ_est (`surrogate::friction`) along the best α's of its α scan
//! ([`super::alpha_scan`]) at every load that can count. [`super::EvaluateStage`] runs it on a
//! shortlist level's orientations side by side; [`ThetaEval`] is the orientation's stored
//! evaluation (scan and estimate).
//!
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

use super::alpha_scan::{AlphaScan, Target};
pub use crate::study::design::model::ThetaEval;
use crate::study::rows::FrictionRow;
use crate::study::tolerance::LimitParams;
use anyhow::Result;
use surrogate::friction::estimate_friction_loads;
use surrogate::units::deg_to_rad;

/// Loads per friction path after the lowest (they share the path's candidate searches and pair
/// lists; the estimate stops after the chunk holding the first load whose coating fails): a
/// cost knob only, the rows kept are bit-identical for any value.
const LOAD_CHUNK: usize = 3;

/// The friction estimate of the orientation `t` along each best α of `scan` (see the module
/// docs): the lowest load, then, while superlubric, the loads up to the scan load (N) until
/// the coating fails on the path. `tick` is called once per α. Cost: one friction path per α
/// and chunk of loads. Its knobs: the limit's (the loads, μ_sl, the estimate's knobs).
pub fn estimate(
    t: &Target,
    scan: &AlphaScan,
    p: &LimitParams,
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<FrictionRow>> {
    let Target {
        solver,
        scene,
        theta_deg,
        scan_load,
    } = *t;
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
