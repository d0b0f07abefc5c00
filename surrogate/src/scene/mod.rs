//! The scene: slider pattern over substrate pattern, material and coating. Shared by the
//! screening tier ([`crate::solver`]) and the dynamic tier (crate `dem`).

mod body_file;
mod coating_file;
mod file;
mod lattice;
mod lattice_file;
mod material;
mod material_file;
mod mount;
mod outline_file;
mod pattern;
pub mod plausible;
#[allow(clippy::module_inception)]
mod scene;
mod sites;
mod sizes;
pub mod symmetry;
mod to_file;
mod touch;
mod validate;

pub use body_file::{SliderFile, SubstrateFile};
pub use coating_file::CoatingFile;
pub use file::{MaterialFile, SceneFile};
pub use lattice::Lattice;
pub use lattice_file::LatticeFile;
pub use material::{BodyMaterials, Coating, Material};
pub use mount::{rotate_tilt_stiffness, Mount, STUDY_K1};
pub use outline_file::OutlineFile;
pub use pattern::{
    check_basis, closest_sites, min_site_distance, rebased, sites_in_outline, ClosestSites,
    Geometry, Outline,
};
pub use scene::{lattice_name, place, Scene, SliderSpec, SubstrateSpec, PATTERNS};
pub use sites::SiteList;
pub use to_file::{scene_file, scene_file_with_lattices};
pub use touch::{overlaps, TOUCH_TOL};
pub use validate::FEW_SLIDER_SPHERES;
