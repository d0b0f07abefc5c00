//! # `superlube design`: screen → shortlist → α scan and friction estimate → ranking → DEM
//!
//! For one or more pattern pairs, a range of orientations θ and a list of loads, the design
//! answers: *which orientation θ and pulling direction α keep friction ultra-low without coating
//! failure, up to which load, and how sure are we?* [`design`] runs the stages in order, in one
//! function: [`pipeline::Pipeline::run`] (each stage a named [`Stage`], told to the one
//! [`Observer`] the command passes in, with what it finds as typed [`Event`]s: no wording here):
//!
//! 1. **Symmetry cut** ([`symmetry`]): θ is cut to the pair's fundamental domain (square-tri
//!    0–15°, tri-tri 0–30°); the α scan covers one α period.
//! 2. **Screen** every θ × W ([`crate::study::screen`]): contacts, P_max, coating failure.
//! 3. **Shortlist** ([`shortlist`]): per θ the load `W_c` up to which the coating stays intact;
//!    every orientation that survives the highest load, plus the best few of each lower load
//!    level, evaluated level by level from the top until no lower level can reach the best
//!    superlubric load found.
//! 4. **α scan, then friction estimate** per shortlisted θ ([`scan::scan_alpha`],
//!    [`scan::estimate`]): contact line, corrugation versus α (coarse grid, then refined near
//!    the minimum), the friction estimate μ_est (`surrogate::friction`) along the best α's at
//!    every load.
//! 5. **Robust search and ranking** ([`rank`]): score = the robust limit, the highest load up to which
//!    superlubric (coating intact on the sliding path AND μ_est < 0.02 at every load up to it)
//!    at every sample of the tolerance box ([`robust`]), then the θ window, the direction
//!    window, μ_est, contacts.
//! 6. **DEM confirmation** ([`confirm`]): the top `confirm` designs of each pattern at the
//!    confirmation loads and at the corners of their tolerance boxes (borderline designs
//!    first), independent `slide` runs side by side, one thread each (plus, with a
//!    protocol shorter than the study's, the design the report recommends once with the study's
//!    protocol to measure the difference there: [`protocol_check_design`]).
//! 7. **Report data** ([`answer`]): each pattern's answer and tolerance map. [`design`] hands each pattern's result to the command's hook as soon as the
//!    pattern is complete (its own CSVs and PNGs are written then), keeps only what the later
//!    stages and the report need of it ([`PatternResult::trim`]: memory flat in the number of
//!    patterns) and returns the [`DesignOutcome`]; the command then writes `report.md` (the
//!    answer first) and the global CSVs with sidecars (`crate::present::design_report`, a
//!    layer above this one).
//!
//! Every stage is stored under the output directory with the inputs that made it
//! ([`store`]): a re-run with the same `--out-dir` reuses every finished stage and DEM run, and one
//! with other inputs is refused with the differences named.

pub mod answer;
pub mod best;
pub mod confirm;
mod domain;
pub mod observer;
mod outcome;
pub mod p_crit;
pub mod params;
pub mod pipeline;
pub mod rank;
pub mod recipe_answer;
pub mod robust;
pub mod scan;
pub mod shortlist;
mod stages;
pub mod store;
pub mod symmetry;
pub mod trim;

pub use domain::{
    cut, default_domain, line_note, theta_note, ThetaNote, THETA_STEP_DEG, WIDE_DOMAIN_DEG,
    WIDE_THETA_STEP_DEG,
};
pub use observer::{Event, Observer, Stage};
pub use outcome::{
    AnswerMap, DemEntry, DesignOutcome, EvalStage, Evaluated, PatternResult, Stop, Timing,
};
use stages::limit_record;
pub use stages::{answer_map, inputs, screen_params, tolerance_box};

pub use params::{DesignParams, DesignScene};

use super::rows::label;
use anyhow::Result;
pub use confirm::{dem_params, loads_to_confirm, protocol_check_design, run_name, ProtocolCheck};
use pipeline::Pipeline;
use store::Store;
use surrogate::solver::Solver;

/// File-name form of a number (`0.35`, `-15`).
pub fn tag(v: f64) -> String {
    format!("{}", label(v))
}

/// What [`design`] calls with each pattern's complete result (its friction estimates for the
/// DEM included), in pattern order, before trimming it: the command writes the pattern's own
/// files there. Not called in a DEM shard (`--shard`: no outputs).
pub type PatternHook<'a> = &'a dyn Fn(&PatternResult) -> Result<()>;

/// Runs the design (see the module docs) into `store`, telling `obs` each stage entered and
/// what it finds ([`observer`]); hands each pattern to `on_pattern` when complete, then trims
/// it ([`PatternResult::trim`]), so memory does not grow with the pattern's rows: the
/// outcome's patterns are trimmed. The stages in order: [`pipeline::Pipeline::run`].
pub fn design(
    scenes: &[DesignScene],
    p: &DesignParams,
    store: &Store,
    obs: &dyn Observer,
    on_pattern: PatternHook,
) -> Result<DesignOutcome> {
    Pipeline::new(p, store, obs).run(scenes, on_pattern)
}

/// The pattern's solver (slider at θ = 0, each query rotates it), built on first use in `slot`.
/// Cost: one scene build and pair-search setup, once.
pub(super) fn solver_of<'a>(slot: &'a mut Option<Solver>, ds: &DesignScene) -> Result<&'a Solver> {
    if slot.is_none() {
        let mut sc = ds.scene.clone();
        sc.slider.theta = 0.0;
        *slot = Some(Solver::new(&sc)?);
    }
    slot.as_ref().ok_or_else(|| anyhow::anyhow!("no solver"))
}

#[cfg(test)]
mod tests;
