//! The velocity-Verlet engine ([`Sim`]): the step pipeline (`sim.rs`), the slider body and the
//! control layer's generalized coordinates (`body.rs`), the force passes (`forces.rs`), the
//! implicit mount step of the full model (`mount.rs`), the active set (`active.rs`), observables and checks (`observe.rs`), the work chunking
//! (`chunks.rs`) and the team of threads that runs the passes (`team.rs`).

pub(crate) mod active;
pub(crate) mod body;
pub(crate) mod chunks;
pub(crate) mod forces;
pub(crate) mod mount;
pub mod observe;
pub(crate) mod ring;
pub mod sim;
pub(crate) mod team;

pub use sim::{Observables, Sim};
