//! The data that flows between the design's stages, below every stage: the pattern
//! ([`DesignScene`]), what the screen and shortlist find of it ([`Orientation`], [`Level`],
//! [`Stop`]), each orientation's evaluation ([`ThetaEval`]), the candidates and their ranking
//! ([`rank`]), a pattern's result ([`PatternResult`]), the DEM runs ([`DemEntry`]), the answers
//! ([`answer`]), the yields and the outcome ([`DesignOutcome`]). Types and the pure rules on
//! them only: no stage, no store, no observer.

pub mod answer;
mod answer_yield;
mod dem_entry;
mod design_scene;
mod level;
mod outcome;
mod p_crit_sweep;
mod pattern_result;
pub mod rank;
mod stop;
mod theta_eval;
pub mod trim;

pub use answer::{Answer, AnswerRule, Check, Contradiction};
pub use answer_yield::AnswerYield;
pub use dem_entry::{ConfirmEntry, DemEntry, DemProtocol};
pub use design_scene::DesignScene;
pub use level::{Level, Orientation};
pub use outcome::DesignOutcome;
pub use p_crit_sweep::{PCritLimit, PCritSweep, P_CRIT_SWEEP_GPA};
pub use pattern_result::{AnswerMap, EvalStage, Evaluated, PatternResult};
pub use rank::{Candidate, CornerEstimate, Pick, Score};
pub use stop::Stop;
pub use theta_eval::ThetaEval;

#[cfg(test)]
pub mod fixtures;
