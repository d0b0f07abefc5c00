//! Stage 5 of a design, the ranking of a pattern's candidates ([`RankStage`], its knobs
//! [`RankParams`]): the score's order ([`crate::study::design::model::rank::compare`]), the
//! robust limits located below the ladder's first load where none holds it ([`below_ladder`])
//! and, with `--rank-by yield`, the top designs ranked by their yield ([`by_yield`]).

pub mod below_ladder;
pub mod by_yield;
mod params;
mod stage;

pub use params::RankParams;
pub use stage::{RankInput, RankStage};
