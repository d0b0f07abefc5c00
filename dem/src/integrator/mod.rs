//! Time integration: [`Sim`] holds a system, its contact model and state, and advances it by
//! velocity-Verlet steps with 0 K Langevin-equivalent viscous damping ([`Sim::step`]).

pub mod sim;

pub use sim::{Observables, Sim};
