//! # surrogate — scene model and quasi-static rigid-slider solver of superlube
//!
//! Data flows one way: [`scene`] (lattices, patterns, materials) → [`contact`] (Hertz law,
//! candidate pairs) → [`solver`] (load sharing: equilibrium height, tilts, compliance) →
//! [`solver::Equilibrium`] (contacts, P_max, z) → [`map`] (landscapes, corrugation paths) and
//! [`friction`] (the surrogate friction estimate).
//!
//! Everything inside this crate is SI (m, N, Pa, s, kg, rad) in `f64`. The only place that converts
//! to the user-facing units (µm, mN, GPa, µs, degrees) is [`units`].
#![warn(missing_docs)]

pub mod atomic_file;
pub mod contact;
pub mod error;
pub mod friction;
pub mod io_error;
pub mod map;
pub mod scene;
pub mod solver;
pub mod units;

pub use error::SceneError;
pub use scene::{
    BodyMaterials, Coating, Lattice, Material, Mount, Scene, SceneFile, SliderSpec, SubstrateSpec,
};
