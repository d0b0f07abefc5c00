//! [`AnswerYield`]: what the yield stage ([`super::super::yield_stage`]) found for one
//! pattern's answer.

use crate::study::fab_yield::YieldOutcome;

/// The yield of one pattern's answer.
#[derive(Debug, Clone)]
pub struct AnswerYield {
    /// The answer's θ (degrees).
    pub theta_deg: f64,
    /// The answer's pull direction from the substrate x axis (degrees).
    pub direction_deg: f64,
    /// What the yield found (rows per device and the summary).
    pub outcome: YieldOutcome,
}
