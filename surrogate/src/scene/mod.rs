//! The scene: slider pattern over substrate pattern, material and coating. Shared by the
//! screening tier ([`crate::solver`]) and the dynamic tier (crate `dem`).

mod file;
mod lattice;
mod material;
mod mount;
#[allow(clippy::module_inception)]
mod scene;

pub use file::{CoatingFile, LatticeFile, MaterialFile, SceneFile, SliderFile, SubstrateFile};
pub use lattice::Lattice;
pub use material::{Coating, Material};
pub use mount::{rotate_tilt_stiffness, Mount, STUDY_K1};
pub use scene::{Scene, SliderSpec, SubstrateSpec, PATTERNS};
