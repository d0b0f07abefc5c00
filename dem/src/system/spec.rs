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
    /// Per-sphere radii (m) of the slider spheres (in `slider_sites` order) when a site file
    /// gives them differing sizes; `None`: every one has `slider_sphere_radius` (the one-size
    /// arithmetic, untouched). Slider sphere i's spring anchor then sits `R − r_i` above the
    /// body's reference anchor (its top on the slider plate; R = `slider_sphere_radius`).
    pub slider_radii: Option<Vec<f64>>,
    /// Per-sphere radii (m) of the substrate spheres (in `substrate` order) when they differ;
    /// `None`: every one has `substrate_sphere_radius`. Their heights in `substrate` already
    /// include the offset `r_j − R` (bottom on the substrate plane).
    pub substrate_radii: Option<Vec<f64>>,
    /// Material of the slider spheres and the control layer (density for their masses; the
    /// contact model's elastic constants come from both bodies' materials).
    pub slider_material: Material,
    /// Material of the substrate spheres (density for their masses).
    pub substrate_material: Material,
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
        self.slider_material.sphere_mass(self.slider_sphere_radius)
    }
    /// Mass of one substrate sphere (kg).
    pub fn substrate_sphere_mass(&self) -> f64 {
        self.substrate_material
            .sphere_mass(self.substrate_sphere_radius)
    }
    /// Centre distance (m) at which a slider and a substrate sphere touch, `R_sl + R_sb`
    /// (`2R`, bit for bit, for one size).
    pub fn contact_distance(&self) -> f64 {
        self.slider_sphere_radius + self.substrate_sphere_radius
    }
    /// Whether either body has per-sphere sizes (`slider_radii` or `substrate_radii`).
    pub fn has_sizes(&self) -> bool {
        self.slider_radii.is_some() || self.substrate_radii.is_some()
    }
    /// Radius (m) of slider sphere `i`. O(1).
    pub fn slider_radius(&self, i: usize) -> f64 {
        self.slider_radii
            .as_ref()
            .map_or(self.slider_sphere_radius, |r| r[i])
    }
    /// Radius (m) of substrate sphere `j`. O(1).
    pub fn substrate_radius(&self, j: usize) -> f64 {
        self.substrate_radii
            .as_ref()
            .map_or(self.substrate_sphere_radius, |r| r[j])
    }
    /// Largest slider sphere radius (m) (`slider_sphere_radius` for one size). O(N).
    pub fn max_slider_radius(&self) -> f64 {
        self.slider_radii
            .as_ref()
            .map_or(self.slider_sphere_radius, |r| {
                r.iter().copied().fold(0.0, f64::max)
            })
    }
    /// Largest substrate sphere radius (m). O(N).
    pub fn max_substrate_radius(&self) -> f64 {
        self.substrate_radii
            .as_ref()
            .map_or(self.substrate_sphere_radius, |r| {
                r.iter().copied().fold(0.0, f64::max)
            })
    }
    /// Smallest sphere radius (m) of either body. O(N).
    pub fn min_radius(&self) -> f64 {
        let mut m = self.slider_sphere_radius.min(self.substrate_sphere_radius);
        for r in [&self.slider_radii, &self.substrate_radii]
            .into_iter()
            .flatten()
        {
            m = r.iter().copied().fold(m, f64::min);
        }
        m
    }
    /// Largest centre distance (m) at which any slider–substrate pair touches,
    /// `max r_i + max r_j` ([`SystemSpec::contact_distance`], bit for bit, for one size per
    /// body): the candidate-list cutoff. O(N).
    pub fn max_contact_distance(&self) -> f64 {
        if !self.has_sizes() {
            return self.contact_distance();
        }
        self.max_slider_radius() + self.max_substrate_radius()
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
        let reach = r + self.max_slider_radius();
        Some((centre[0].abs() + reach - 0.5 * lx).max(centre[1].abs() + reach - 0.5 * ly))
    }
}
