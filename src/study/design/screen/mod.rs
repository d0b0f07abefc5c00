//! Stage 1 of a design, the screen: the symmetry cut of θ to the pattern's fundamental domain
//! ([`domain`]), then every θ × W screened ([`ScreenStage`]). Its knobs:
//! [`ScreenStageParams`].

pub mod domain;
mod inputs;
mod params;
mod stage;

pub use inputs::{screen_inputs, screen_params};
pub use params::ScreenStageParams;
pub use stage::{ScreenStage, Screened};
