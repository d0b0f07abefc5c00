//! What the design returns: [`DesignOutcome`], every pattern's result with its DEM runs, its
//! answer, the tolerance maps and the P_crit sweep, handed to the report.

use super::answer::Answer;
use super::answer_yield::AnswerYield;
use super::dem_entry::DemEntry;
use super::p_crit_sweep::PCritSweep;
use super::pattern_result::{AnswerMap, PatternResult};

/// What [`super::super::design`] found.
#[derive(Debug, Clone)]
pub struct DesignOutcome {
    /// Per pattern, in the order given; trimmed ([`PatternResult::trim`]) once handed to the
    /// design's hook.
    pub patterns: Vec<PatternResult>,
    /// The DEM runs (empty with `--no-dem`).
    pub dem: Vec<DemEntry>,
    /// Whether the DEM stage ran.
    pub dem_ran: bool,
    /// The answer per pattern (the ranking checked against the DEM, [`super::answer`]).
    pub answers: Vec<Answer>,
    /// Per pattern, the tolerance map around its answer (θ points per row, rows) when the
    /// design has a tolerance ([`super::super::report_data::tolerance_map()`]).
    pub maps: Vec<Option<AnswerMap>>,
    /// With recipes (`--vary`): the best named recipe's robust limit at each coating strength
    /// of [`super::p_crit_sweep::P_CRIT_SWEEP_GPA`].
    pub p_crit: Option<PCritSweep>,
    /// Per pattern, the yield of its answer over fabrication when the yield stage ran
    /// ([`super::super::yield_stage`]); empty when it did not.
    pub yields: Vec<Option<AnswerYield>>,
}

impl DesignOutcome {
    /// The outcome of a DEM shard (`--shard`): the patterns, no DEM entries, answers or report
    /// data (the shard's runs are in its `dem/`).
    pub fn without_report(patterns: Vec<PatternResult>) -> Self {
        DesignOutcome {
            patterns,
            dem: Vec::new(),
            dem_ran: false,
            answers: Vec::new(),
            maps: Vec::new(),
            p_crit: None,
            yields: Vec::new(),
        }
    }
}
