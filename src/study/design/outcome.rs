//! What the design stages return: stored stages, each pattern's result, the DEM entries and
//! the outcome handed to the report.

use super::confirm::SlideOutcome;
use super::rank::Candidate;
use super::scan::ThetaEval;
use super::shortlist::{Level, Orientation};
use super::symmetry::PairSymmetry;
use super::DesignScene;
use crate::study::rows::ScreenRow;
use serde::{Deserialize, Serialize};

/// A stage's record of its own wall time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Timing {
    /// Wall time of the stage when it was computed (s).
    pub wall_s: f64,
}

/// An orientation's evaluation as stored (`stages/<pattern>/theta_<θ>.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EvalStage {
    /// The evaluation.
    pub eval: ThetaEval,
    /// Its wall time when computed (s).
    pub wall_s: f64,
}

/// Why a pattern's level-by-level evaluation stopped (with [`PatternResult::levels_skipped`]
/// and [`PatternResult::robust_floor_mn`], the levels skipped under a floor).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stop {
    /// Every level was taken (evaluated, or skipped under the floor).
    EveryLevel,
    /// Stopped before the level of load `level` (N): its orientations cannot be superlubric
    /// beyond `reach_mn` (mN), below the best limit found, `best_mn` (mN).
    Before {
        /// The level's load W_c (N).
        level: f64,
        /// The most its orientations can reach (mN).
        reach_mn: f64,
        /// The best superlubric limit found (mN).
        best_mn: f64,
    },
}

/// One evaluated orientation of a pattern.
#[derive(Debug, Clone)]
pub struct Evaluated {
    /// The screen's view of it.
    pub orientation: Orientation,
    /// Why it was shortlisted.
    pub reason: String,
    /// The α scan and friction estimate.
    pub eval: ThetaEval,
    /// Wall time when computed (s).
    pub wall_s: f64,
    /// Reused from an earlier run.
    pub reused: bool,
    /// α of each row of the scan (degrees, scan order): kept when [`PatternResult::trim`]
    /// drops `eval.scan`.
    pub scan_alphas_deg: Vec<f64>,
    /// Number of friction estimates (rows of `eval.friction`, kept when trimmed).
    pub estimates: usize,
}

/// Everything the design found for one pattern.
#[derive(Debug, Clone)]
pub struct PatternResult {
    /// The pattern.
    pub scene: DesignScene,
    /// Its symmetry.
    pub sym: PairSymmetry,
    /// θ screened (degrees, after the cut).
    pub thetas_deg: Vec<f64>,
    /// The screen rows (θ outer, loads inner).
    pub screen: Vec<ScreenRow>,
    /// Wall time of the screen when computed (s; `None` if not recorded).
    pub screen_wall_s: Option<f64>,
    /// The orientations (θ order) and the levels of the shortlist.
    pub orientations: Vec<Orientation>,
    /// The levels of the shortlist, highest first.
    pub levels: Vec<Level>,
    /// How many levels were taken (from the top): evaluated, or skipped (`levels_skipped`).
    pub levels_evaluated: usize,
    /// Levels (indices into `levels`) skipped with a robust floor: their orientations could not
    /// exceed it over the tolerance box (`super::design`, many patterns).
    pub levels_skipped: Vec<usize>,
    /// Why the evaluation stopped.
    pub stop: Stop,
    /// The evaluated orientations, in evaluation order.
    pub evaluated: Vec<Evaluated>,
    /// The candidates, best first (below the top few, each with its lowest-load friction
    /// row only once trimmed: [`PatternResult::trim`]).
    pub ranking: Vec<Candidate>,
    /// Candidates with a load whose failed contacts sit on a mount in resonance (counted over
    /// every friction row before the rows are trimmed; [`super::trim::resonance_flagged`]).
    pub resonance_flagged: usize,
    /// The robust search's floor for this pattern (mN; 0: none): its candidates whose nominal
    /// limit is at most this were not searched over the tolerance box, since they cannot
    /// exceed the best patterns' robust limits (`super::design`, many patterns).
    pub robust_floor_mn: f64,
    /// Whether [`PatternResult::trim`] dropped the bulky rows (screen, orientations, α scans,
    /// friction rows below the top few).
    pub trimmed: bool,
}

/// One DEM confirmation run and what it is compared with.
#[derive(Debug, Clone)]
pub struct DemEntry {
    /// Which design the run checks, where and how.
    pub run: super::confirm::ConfirmEntry,
    /// The run.
    pub outcome: SlideOutcome,
}

/// What [`super::design`] found.
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
    pub answers: Vec<super::answer::Answer>,
    /// Per pattern, the tolerance map around its answer (θ points per row, rows) when the
    /// design has a tolerance ([`super::answer_map`]).
    pub maps: Vec<Option<AnswerMap>>,
    /// With recipes (`--vary`): the best named recipe's robust limit at each coating strength
    /// of [`super::p_crit::P_CRIT_SWEEP_GPA`] ([`super::p_crit`]).
    pub p_crit: Option<super::p_crit::PCritSweep>,
}

/// The tolerance map around a pattern's answer (`tolerance_<pattern>.csv/.png`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AnswerMap {
    /// θ (degrees) and pulling direction (degrees from x) of the answer.
    pub nominal: (f64, f64),
    /// Grid points along θ (the rows run direction outer, θ inner).
    pub theta_points: usize,
    /// The map's rows.
    pub rows: Vec<crate::study::tolerance::ToleranceRow>,
}

impl PatternResult {
    /// A result holding only `ranking` (nothing screened or evaluated): for the tests of the
    /// stages after the ranking (answer, confirmation, report).
    #[cfg(test)]
    pub(crate) fn of_ranking(
        scene: DesignScene,
        sym: PairSymmetry,
        ranking: Vec<Candidate>,
    ) -> Self {
        PatternResult {
            scene,
            sym,
            thetas_deg: vec![],
            screen: vec![],
            screen_wall_s: None,
            orientations: vec![],
            levels: vec![],
            levels_evaluated: 0,
            levels_skipped: vec![],
            stop: Stop::EveryLevel,
            evaluated: vec![],
            ranking,
            resonance_flagged: 0,
            robust_floor_mn: 0.0,
            trimmed: false,
        }
    }
}
