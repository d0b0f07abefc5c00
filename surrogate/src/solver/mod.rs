//! Quasi-static load sharing of the slider: given the slider's lateral pose (x, y, θ) and
//! the normal load W, find the height (and, where the scene needs them, tilts and compliances)
//! at which the vertical Hertz forces of all sphere contacts carry W.
//!
//! Models (see [`Model`]): rigid-z (1-D safeguarded Newton), rigid-tilt (3 unknowns,
//! damped Newton, 3 × 3 Cholesky), compliant (3 + n unknowns, sparse Newton with faer's
//! sparse Cholesky). The tilt models obey the scene's slider mount ([`crate::Mount`]): the
//! moment balance is `M_c = K_t·t` with the mount's rotational stiffness K_t (zero for `free`);
//! a `locked` mount has no tilt unknowns. [`Model::Auto`] solves rigid-z and escalates to
//! rigid-tilt only where the rigid-z answer leaves a moment (see `auto.rs`).

mod along;
mod assemble;
mod auto;
mod chunk_solver;
mod columns;
mod compliant;
mod ctx;
mod equilibrium;
mod law;
mod model;
mod pair_set;
mod params;
mod path_pairs;
mod rigid_tilt;
mod rigid_z;
mod search;
mod solve;
#[allow(clippy::module_inception)]
mod solver;
mod z_root;

pub use along::StraightPath;
pub use equilibrium::{ContactInfo, Equilibrium};
pub use model::Model;
pub use pair_set::PairSet;
pub use params::SolverParams;
pub(crate) use solve::{check_load, Warm};
pub use solver::{Pose, SearchKind, Solver};
