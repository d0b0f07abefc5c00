//! Stage 5 of a design, the robust search ([`RobustStage`], its knobs [`RobustParams`]): the
//! robust limits over the tolerance box, best first, with its state across a pattern's
//! shortlist levels ([`searches::Searches`]).

mod params;
pub mod searches;
mod stage;

pub use params::RobustParams;
pub use stage::{level_reach, RobustStage};

#[cfg(test)]
mod tests;
