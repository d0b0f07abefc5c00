//! [`SystemSpec`]: the static particle layout of a DEM run (SI).

use surrogate::Material;

/// Static layout: sites, heights, radii and material. Built by [`super::from_scene`] or by
/// hand (tests).
#[derive(Debug, Clone, PartialEq)]
pub struct SystemSpec {
    /// Substrate sphere sites `[x, y, h]` (m); z stays at h.
    pub substrate: Vec<[f64; 3]>,
    /// Slider sphere sites in the plane (m), absolute at the start; their offsets from the
    /// control-layer centre of mass are the spring rest positions.
    pub slider_sites: Vec<[f64; 2]>,
    /// Initial z (m) of each slider sphere centre.
    pub slider_z: Vec<f64>,
    /// Initial control-layer reference height Z (m): slider sphere i's z-spring is relaxed at
    /// `z_i = Z`.
    pub control_z: f64,
    /// Radius of slider and substrate spheres (m).
    pub sphere_radius: f64,
    /// Material (density for the masses, elastic constants for the contact model).
    pub material: Material,
}

impl SystemSpec {
    /// Mass of one slider or substrate sphere (kg).
    pub fn sphere_mass(&self) -> f64 {
        self.material.sphere_mass(self.sphere_radius)
    }
    /// Total particle count: substrate + slider + control-layer spheres + 1 support.
    pub fn particle_count(&self) -> usize {
        self.substrate.len() + 2 * self.slider_sites.len() + 1
    }
}
