//! The velocity-Verlet engine ([`Sim`]): its state (`sim.rs`), its construction (`build.rs`),
//! the step pipeline (`step.rs`), the slider body and the control layer's generalized
//! coordinates (`body.rs`), the force passes (`forces.rs`; the slider's in `slider_pass.rs`),
//! the implicit mount step of the full model (`mount.rs`), the active set (`active.rs`, its
//! selection `active_select.rs` and its dense packing and index `active_index.rs`),
//! observables and checks (`observe.rs`), the kernels and index the passes share
//! (`kernel.rs`), the work chunking (`chunks.rs`) and the team of threads that runs the passes
//! (`team.rs`).
//!
//! No two files import each other: `kernel.rs`, `body.rs`, `chunks.rs`, `ring.rs`, `team.rs`,
//! `slider_pass.rs` and `mount.rs` know no [`Sim`]; `sim.rs` defines it from them; the other
//! files add `impl Sim` blocks and import `sim.rs` and the leaves (`step.rs` also `forces.rs`).

pub(crate) mod active;
mod active_index;
mod active_select;
pub(crate) mod body;
mod build;
pub(crate) mod chunks;
mod drift;
pub(crate) mod forces;
pub(crate) mod kernel;
pub(crate) mod mount;
pub mod observe;
pub(crate) mod ring;
pub mod sim;
mod slider_pass;
mod step;
pub(crate) mod team;

pub use sim::{Observables, Sim};
