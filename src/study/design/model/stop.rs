//! [`Stop`]: why a pattern's level-by-level evaluation stopped (the shortlist's level walk).

/// Why a pattern's level-by-level evaluation stopped (with [`super::PatternResult::levels_skipped`]
/// and [`super::PatternResult::robust_floor_mn`], the levels skipped under a floor).
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
