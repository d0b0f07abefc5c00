//! How a pass of the pipeline searches the tolerance box ([`Search`]) and the order it takes
//! the patterns in ([`Order`]); types only.

use crate::study::design::robust::RobustParams;

/// How [`Pipeline::pattern`](super::Pipeline::pattern) searches the tolerance box.
#[derive(Debug, Clone, Copy)]
pub enum Search {
    /// No robust search: the nominal limits only (the first pass of [`Pipeline::order`](super::Pipeline::order)).
    Nominal,
    /// The robust search ([`crate::study::design::robust::RobustStage`]) with these knobs:
    /// above the floor, until the best `keep` designs of the pattern are exact.
    Robust(RobustParams),
}

/// The order [`Pipeline::run`](super::Pipeline::run) takes the patterns in, and whether a robust floor applies
/// across them.
#[derive(Debug, Clone, PartialEq)]
pub struct Order {
    /// Indices into the patterns, in the order taken.
    pub patterns: Vec<usize>,
    /// Whether the patterns are taken best nominal design first, each robust search above the
    /// floor of the best
    /// [`BEST_PATTERNS`](crate::study::design::report_data::best::BEST_PATTERNS) found so far.
    pub cross: bool,
}
