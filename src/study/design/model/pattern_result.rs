//! What the stages of one pattern return: each pattern's result ([`PatternResult`]), its
//! evaluated orientations and stored evaluations, and the tolerance map around its answer.

use super::design_scene::DesignScene;
use super::level::{Level, Orientation};
use super::rank::{Candidate, Pick};
use super::stop::Stop;
use super::theta_eval::ThetaEval;
use crate::study::design::symmetry_words::PairSymmetry;
use crate::study::rows::ScreenRow;
use serde::{Deserialize, Serialize};

/// An orientation's evaluation as stored (`stages/<pattern>/theta_<θ>.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EvalStage {
    /// The evaluation.
    pub eval: ThetaEval,
    /// Its wall time when computed (s).
    pub wall_s: f64,
}

/// One evaluated orientation of a pattern.
#[derive(Debug, Clone)]
pub struct Evaluated {
    /// The screen's view of it.
    pub orientation: Orientation,
    /// Why it was shortlisted.
    pub reason: Pick,
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
    /// every friction row before the rows are trimmed; [`super::rank::resonance_flagged`]).
    pub resonance_flagged: usize,
    /// The robust search's floor for this pattern (mN; 0: none): its candidates whose nominal
    /// limit is at most this were not searched over the tolerance box, since they cannot
    /// exceed the best patterns' robust limits (`super::design`, many patterns).
    pub robust_floor_mn: f64,
    /// Whether [`PatternResult::trim`] dropped the bulky rows (screen, orientations, α scans,
    /// friction rows below the top few).
    pub trimmed: bool,
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
