//! Stage 2 of a design, the shortlist: which orientations of the screen go on to the α scan
//! and the friction estimate ([`ShortlistStage`], its knobs [`ShortlistParams`]), and the walk
//! over its levels ([`walk::LevelWalk`]).

mod params;
mod stage;
pub mod walk;

pub use params::ShortlistParams;
pub use stage::{levels, orientations, ShortlistStage, Shortlisted};

#[cfg(test)]
mod tests;
