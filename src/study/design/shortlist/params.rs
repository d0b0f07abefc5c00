//! [`ShortlistParams`]: the knobs of the design's shortlist ([`super::ShortlistStage`]).

/// The shortlist's knobs (the loads are the design's own).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShortlistParams {
    /// Orientations kept per lower load level.
    pub per_level: usize,
    /// Most orientations kept at the top level (all that survive the highest load, up to this).
    pub max_top: usize,
}
