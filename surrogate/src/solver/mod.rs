//! Quasi-static load sharing of the rigid slider: given the slider's lateral pose (x, y, θ) and
//! the normal load W, find the height (and, where the scene needs them, tilts and compliances)
//! at which the vertical Hertz forces of all sphere contacts carry W.

mod equilibrium;
mod model;
mod params;
mod rigid_z;
mod solver;

pub use equilibrium::{ContactInfo, Equilibrium};
pub use model::Model;
pub use params::SolverParams;
pub use rigid_z::solve_rigid_z;
pub use solver::{Pose, Solver};
