//! [`SliderFile`] and [`SubstrateFile`]: the `[slider]` and `[substrate]` tables of a scene
//! file, in user units.

use super::{LatticeFile, MaterialFile, OutlineFile};
use serde::{Deserialize, Serialize};

/// Slider overrides (user units).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SliderFile {
    /// Slider lattice.
    pub lattice: Option<LatticeFile>,
    /// Disc radius (µm).
    pub radius_um: Option<f64>,
    /// Rotation θ (degrees).
    pub theta_deg: Option<f64>,
    /// Disc centre relative to the central substrate sphere (µm).
    pub offset_um: Option<[f64; 2]>,
    /// Slider mount: `locked` (no tilt), `free` (tilts freely) or `springs` (the study's
    /// anti-tilt springs between opposing halves of the control layer; default).
    pub tilt: Option<String>,
    /// Anti-tilt spring stiffness K1 (N/m) of `tilt = "springs"` (study: 1e6).
    #[serde(rename = "tilt_k1_N_m")]
    pub tilt_k1_n_m: Option<f64>,
    /// Slider outline (default: the disc of `radius_um`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outline: Option<OutlineFile>,
    /// A site file `x_um,y_um[,diameter_um]` (relative to the slider centre) instead of a lattice.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sites: Option<String>,
    /// Diameter of the slider spheres (µm); default the scene's `sphere_diameter_um`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sphere_diameter_um: Option<f64>,
    /// The slider spheres' own material (`[slider.material]`): each field given overrides the
    /// shared `[material]` for the slider only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<MaterialFile>,
}

/// Substrate overrides (user units).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubstrateFile {
    /// Substrate lattice.
    pub lattice: Option<LatticeFile>,
    /// Rectangle size `[Lx, Ly]` (µm).
    pub size_um: Option<[f64; 2]>,
    /// Height perturbation amplitude σ_h (µm).
    pub sigma_h_um: Option<f64>,
    /// Seed of the height perturbation.
    pub seed: Option<u64>,
    /// A site file `x_um,y_um[,diameter_um]` (relative to the substrate centre) instead of a
    /// lattice.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sites: Option<String>,
    /// Diameter of the substrate spheres (µm); default the scene's `sphere_diameter_um`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sphere_diameter_um: Option<f64>,
    /// The substrate spheres' own material (`[substrate.material]`): each field given
    /// overrides the shared `[material]` for the substrate only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material: Option<MaterialFile>,
}
