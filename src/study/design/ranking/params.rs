//! [`RankParams`]: the knobs of the ranking stage ([`super::RankStage`]), set by the design's
//! plan.

use crate::study::design::yield_stage::YieldStageParams;

/// The ranking's knobs.
#[derive(Debug, Clone, PartialEq)]
pub struct RankParams {
    /// Designs per pattern ranked by their yield with `--rank-by yield` (`max(confirm, 3)`).
    pub keep: usize,
    /// The yield's knobs when the designs are ranked by their yield ([`super::by_yield`]);
    /// `None`: the worst case over the tolerance box alone.
    pub by_yield: Option<YieldStageParams>,
}
