//! # `superlube design`: screen → shortlist → α scan and friction estimate → ranking → DEM
//!
//! For one or more pattern pairs, a range of orientations θ and a list of loads, the design
//! answers: *which orientation θ and pulling direction α keep friction ultra-low without coating
//! failure, up to which load, and how sure are we?* [`design`] runs the stages in order:
//! [`pipeline::Pipeline::run`], the flat list. Each stage is a folder with its own params and
//! a stage value holding only what it reads (its params and a [`StageEnv`]: the shared
//! [`LimitKnobs`], the store, the observer), all of one shape,
//! `XStage::new(env, &params).run(input)`, each telling the one [`Observer`] the command
//! passes in what it finds as typed [`Event`]s (no wording here). The data they pass on is
//! [`model`], below every stage; the cross-stage rules (designs kept, the floor across many
//! patterns) are the [`pipeline::Plan`], computed once.
//!
//! 1. **Screen** ([`screen::ScreenStage`]): θ cut to the pair's fundamental domain
//!    ([`symmetry_words`]; square-tri 0–15°, tri-tri 0–30°; the α scan covers one α period),
//!    then every θ × W screened ([`crate::study::screen`]): contacts, P_max, coating failure.
//! 2. **Shortlist** ([`shortlist::ShortlistStage`]): per θ the load `W_c` up to which the
//!    coating stays intact; every orientation that survives the highest load, plus the best few
//!    of each lower load level. The levels are taken from the top by a
//!    [`shortlist::walk::LevelWalk`] until no lower level can reach the best superlubric load
//!    found.
//! 3. **α scan** ([`evaluate::alpha_scan`]) and 4. **friction estimate**
//!    ([`evaluate::estimate`]) of a level's orientations ([`evaluate::EvaluateStage`]):
//!    contact line, corrugation versus α (coarse grid, then refined near the minimum), the
//!    friction estimate μ_est (`surrogate::friction`) along the best α's at every load.
//! 5. **Robust search** ([`robust::RobustStage`], with a tolerance): the robust limit, the
//!    highest load up to which superlubric (coating intact on the sliding path AND μ_est < 0.02
//!    at every load up to it) at every sample of the tolerance box; then the **ranking**
//!    ([`ranking::RankStage`]): by it, then the θ window, the direction window, μ_est, contacts
//!    ([`rank`]), the limits below the ladder where none holds its first load, and with
//!    `--rank-by yield` by the yield ([`ranking::by_yield`]).
//! 6. **DEM confirmation** ([`confirm::ConfirmStage`]): per pattern the estimates the DEM is
//!    compared with, then the top [`ConfirmParams::designs`] designs of each pattern at the
//!    confirmation loads and at the corners of their tolerance boxes (borderline designs
//!    first), independent `slide` runs side by side, one thread each (plus, with a protocol
//!    shorter than the study's, the design the report recommends once with the study's
//!    protocol to measure the difference there: [`protocol_check_design`]).
//! 7. **Report data** ([`report_data::ReportDataStage`]): each pattern's answer ([`answer`]),
//!    the tolerance maps around the answers and, with recipes, the P_crit sweep ([`p_crit`]).
//! 8. **Yield** ([`yield_stage::YieldStage`], on by default, `design --no-yield` off): per answer
//!    the fraction of fabricated devices (offsets over the tolerance box, fresh substrates)
//!    that stay superlubric at a load and the load at yield q with its confidence bound
//!    ([`crate::study::fab_yield`]), the DEM locating the devices that set them.
//!
//! [`design`] hands each pattern's result to the command's hook as soon as the pattern is
//! complete (its own CSVs and PNGs are written then), keeps only what the later stages and the
//! report need of it ([`PatternResult::trim`]: memory flat in the number of patterns) and
//! returns the [`DesignOutcome`]; the command then writes `report.md` (the answer first) and
//! the global CSVs with sidecars (`crate::present::design_report`, a layer above this one).
//!
//! Every stage is stored under the output directory with the inputs that made it
//! ([`store`]; the design's record: `inputs.rs`, each stage's beside it): a re-run with the
//! same `--out-dir` reuses every finished stage and DEM run, and one with other inputs is
//! refused with the differences named. Adding a stage: a folder with its stage value and its
//! params (a field of [`DesignParams`], or derived by the plan), the data it passes on in
//! [`model`], its events in [`observer`] (worded by `crate::present::design_report::log`),
//! one line in [`pipeline::Pipeline`], a unit test beside it.

pub mod confirm;
pub mod evaluate;
mod inputs;
pub mod limit;
pub mod model;
pub mod observer;
pub mod params;
pub mod pipeline;
pub mod ranking;
pub mod report_data;
pub mod robust;
pub mod screen;
pub mod shortlist;
mod stage_env;
pub mod store;
pub mod symmetry_words;
pub mod yield_stage;

pub use inputs::inputs;
pub use limit::LimitKnobs;
pub use model::{
    answer, rank, trim, AnswerMap, DemEntry, DesignOutcome, EvalStage, Evaluated, PatternResult,
    Stop,
};
pub use observer::{Event, Observer};
pub use params::{
    tolerance_box, AlphaScanParams, ConfirmParams, DesignParams, DesignScene, ScreenStageParams,
    ShortlistParams, ToleranceParams,
};
pub use pipeline::PatternHook;
pub use ranking::below_ladder;
pub use report_data::{best, p_crit, recipe_answer};
pub use screen::domain::{
    cut, default_domain, line_note, theta_note, OutsideDomain, ThetaNote, THETA_STEP_DEG,
    WIDE_DOMAIN_DEG, WIDE_THETA_STEP_DEG,
};
pub use screen::screen_params;
pub use stage_env::StageEnv;
pub use store::{tag, Timing};

use anyhow::Result;
pub use confirm::{dem_params, loads_to_confirm, protocol_check_design, run_name, ProtocolCheck};
use pipeline::Pipeline;
use store::Store;

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

#[cfg(test)]
pub(crate) mod test_design;
