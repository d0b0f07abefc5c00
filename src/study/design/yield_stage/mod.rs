//! Stage 8 of a design, the yield of each pattern's answer over fabrication ([`YieldStage`],
//! its knobs [`YieldRunParams`]), and the devices it shares with the ranking by yield
//! ([`stored_devices`], [`yield_params`]).

mod devices;
mod params;
mod stage;

pub use crate::study::design::model::AnswerYield;
pub use devices::{stored_devices, yield_params};
pub use params::{RankBy, YieldDemParams, YieldStageParams};
pub use stage::{YieldRunParams, YieldStage};

#[cfg(test)]
mod tests;
