//! Stages 3 and 4 of a design on one shortlist level ([`EvaluateStage`]): the α scan
//! ([`alpha_scan`]) and the friction estimate ([`estimate`]) of the level's orientations. Its
//! knobs: [`AlphaScanParams`]; the estimate's are the shared limit knobs.

pub mod alpha_scan;
pub mod estimate;
mod params;
mod record;
mod stage;

pub use params::AlphaScanParams;
pub use record::{eval_inputs, evaluation_record};
pub use stage::{EvaluateStage, LevelInput};
