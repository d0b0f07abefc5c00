//! Contact mechanics between slider and substrate spheres: the Hertz normal law and the search
//! for candidate sphere pairs.

mod candidates;
mod hertz;

pub use candidates::{CandidatePair, CandidateSearch, GridSearch};
pub use hertz::Hertz;
