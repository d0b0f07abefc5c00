//! A robust limit below the ladder's first load: where no design of a pattern holds the first
//! load over its tolerance box (robust limit 0), the best designs' limits are located below it
//! by bisection, down to a stated floor, so that the answer is a load, not 0.
//!
//! For each of the pattern's best [`BELOW_LADDER_DESIGNS`] designs (ranking order) with an
//! exact robust limit of 0: "holds at W" is every sample of the tolerance box (θ offsets ×
//! direction offsets × substrate seeds, corners first) superlubric at W, the ladder's own rule
//! ([`crate::study::verdict::superlubric`]). The search starts at the floor `W_1 ·`
//! [`FLOOR_FRACTION`]: a design failing there is reported below the floor; otherwise the
//! interval (floor, W_1) is halved until its width is [`RESOLUTION`] of its upper end and the
//! lower end (a load that holds) is the limit. Cost: one friction path per sample per load
//! tried, about (1 + log2(1/RESOLUTION · …)) ≈ 8 loads per design, each stopping at the first
//! failing sample.

use crate::study::design::limit::LimitKnobs;
use crate::study::design::model::Candidate;
use crate::study::tolerance::{rows_at, LimitParams};
use crate::study::verdict::superlubric;
use anyhow::Result;
use surrogate::solver::Solver;

/// The floor of the search as a fraction of the ladder's first load (0.35 mN: 0.0035 mN).
pub const FLOOR_FRACTION: f64 = 0.01;

/// The bisection's stopping width, relative to the upper end of the interval.
pub const RESOLUTION: f64 = 0.02;

/// Designs per pattern whose limit is located below the ladder (the best, ranking order).
pub const BELOW_LADDER_DESIGNS: usize = 3;

/// The result of the search for one design: the highest load found to hold over the box (N),
/// `0` when not even the floor holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BelowLadder {
    /// The load (N) the design holds over the whole box (the bisection's lower end); 0: below
    /// the floor.
    pub holds_to: f64,
    /// The floor searched down to (N).
    pub floor: f64,
    /// The first load of the ladder (N): the limit is below it.
    pub first: f64,
}

/// Whether every (θ offset, direction offset, seed) sample of `c`'s box is superlubric at the
/// load `w` (N) on `solvers` (the design's substrate first). Stops at the first failure.
fn holds(
    c: &Candidate,
    w: f64,
    offsets: &[(f64, f64)],
    solvers: &[Solver],
    p: &LimitKnobs,
) -> Result<bool> {
    let lp = LimitParams {
        loads: vec![w],
        ..p.limit()
    };
    for s in solvers {
        let p_crit = s.scene().coating.p_crit;
        for &(dt, dd) in offsets {
            let rows = rows_at(s, c.theta_deg + dt, c.direction_deg + dd, &[0], &lp)?;
            if !rows
                .iter()
                .all(|r| superlubric(r, p_crit, p.mu_superlubric))
            {
                return Ok(false);
            }
        }
    }
    Ok(true)
}

/// The samples of the box, corners first (the likeliest to fail), then the rest in order.
fn box_offsets(p: &LimitKnobs) -> Vec<(f64, f64)> {
    let bx = p.tolerance_box();
    let mut out: Vec<(f64, f64)> = bx.corners();
    for &dd in &bx.direction_offsets_deg {
        for &dt in &bx.theta_offsets_deg {
            if !out.contains(&(dt, dd)) {
                out.push((dt, dd));
            }
        }
    }
    out
}

/// Locates the limit of `c` below the ladder's first load (module docs). O(8 loads × samples).
pub fn locate(c: &Candidate, solvers: &[Solver], p: &LimitKnobs) -> Result<BelowLadder> {
    let first = p.loads.first().copied().unwrap_or(0.0);
    let floor = first * FLOOR_FRACTION;
    let offsets = box_offsets(p);
    if !holds(c, floor, &offsets, solvers, p)? {
        return Ok(BelowLadder {
            holds_to: 0.0,
            floor,
            first,
        });
    }
    let (mut lo, mut hi) = (floor, first);
    while hi - lo > RESOLUTION * hi {
        let mid = 0.5 * (lo + hi);
        if holds(c, mid, &offsets, solvers, p)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(BelowLadder {
        holds_to: lo,
        floor,
        first,
    })
}

/// Whether the pattern of `ranking` (sorted) has no design holding the ladder's first load
/// over its box: its best design's robust limit is exactly 0.
pub fn needed(ranking: &[Candidate]) -> bool {
    ranking
        .first()
        .is_some_and(|c| c.score.exact && c.score.superlubric_to_mn == 0.0)
}
