//! [`RobustParams`]: the knobs of one robust search of a pattern, set by the design's plan.

/// The knobs of one robust stage: the floor and how many designs must be exact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RobustParams {
    /// A candidate whose nominal limit is at most this (mN; 0: none) is not searched, and one
    /// whose bound falls to it is searched no further (the pipeline's plan, many patterns).
    pub floor_mn: f64,
    /// How many of the best designs must be exact (at least 1; `max(confirm, 3)` for one
    /// pattern).
    pub keep: usize,
}
