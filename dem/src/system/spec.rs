//! [`SystemSpec`]: the static particle layout of a DEM run (SI).

use surrogate::{Material, Scene};

/// Static layout: sites, heights, radii, material, the slider mount and the substrate outline.
/// Built by [`super::from_scene`] or by hand (tests).
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
    /// `z_i = Z + t_x·y_i − t_y·x_i` (tilts t start at 0).
    pub control_z: f64,
    /// Radius of every slider sphere (m).
    pub slider_sphere_radius: f64,
    /// Radius of every substrate sphere (m); may differ from the slider's (the contact law
    /// then takes `R_eff = R_sl R_sb/(R_sl + R_sb)` and the contact distance `R_sl + R_sb`).
    pub substrate_sphere_radius: f64,
    /// Material (density for the masses, elastic constants for the contact model).
    pub material: Material,
    /// Rotational stiffness `K_t` (N·m/rad, lab frame, on `[t_x, t_y]`) of the slider mount when
    /// the control layer may tilt (`free`: zeros; `springs`: the anti-tilt springs); `None`: the
    /// mount is locked (no tilt degrees of freedom).
    pub tilt_stiffness: Option<[[f64; 2]; 2]>,
    /// Slider disc radius (m) and its centre at the start (m), for the substrate-edge check.
    pub disc: Option<([f64; 2], f64)>,
    /// Substrate rectangle `[Lx, Ly]` (m), centred on the origin, for the substrate-edge check.
    pub substrate_size: Option<[f64; 2]>,
    /// The scene this layout was built from (recorded in checkpoints).
    pub scene: Option<Scene>,
}

impl SystemSpec {
    /// Mass of one slider sphere (kg).
    pub fn slider_sphere_mass(&self) -> f64 {
        self.material.sphere_mass(self.slider_sphere_radius)
    }
    /// Mass of one substrate sphere (kg).
    pub fn substrate_sphere_mass(&self) -> f64 {
        self.material.sphere_mass(self.substrate_sphere_radius)
    }
    /// Centre distance (m) at which a slider and a substrate sphere touch, `R_sl + R_sb`
    /// (`2R`, bit for bit, for one size).
    pub fn contact_distance(&self) -> f64 {
        self.slider_sphere_radius + self.substrate_sphere_radius
    }
    /// Total particle count: substrate + slider + control-layer spheres + 1 support.
    pub fn particle_count(&self) -> usize {
        self.substrate.len() + 2 * self.slider_sites.len() + 1
    }
    /// How far (m) the slider disc, plus one slider sphere radius, reaches beyond the substrate
    /// rectangle when its centre is at `centre` (m); ≤ 0 when it lies wholly over it. `None`
    /// when the layout does not record the outline.
    pub fn overhang_at(&self, centre: [f64; 2]) -> Option<f64> {
        let (_, r) = self.disc?;
        let [lx, ly] = self.substrate_size?;
        let reach = r + self.slider_sphere_radius;
        Some((centre[0].abs() + reach - 0.5 * lx).max(centre[1].abs() + reach - 0.5 * ly))
    }
}
