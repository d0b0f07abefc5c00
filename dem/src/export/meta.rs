//! [`ExportMeta`]: what `export.json` records about an export (user units in the key names);
//! `superlube lammps-check` reads it to interpret the dump.

use super::layout::Ids;
use serde::{Deserialize, Serialize};

/// Format tag written to and required in `export.json`.
pub const FORMAT: &str = "superlube-lammps-export 1";

/// Step counts of the exported protocol.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Steps {
    /// Equilibration steps (under load, control layer held laterally).
    pub equilibrate: u64,
    /// Relaxation steps (pulling spring attached, support at rest).
    pub relax: u64,
    /// Sliding steps (support moving).
    pub slide: u64,
    /// Steps between time-series rows.
    pub sample_every: u64,
    /// Steps between contact-dump frames (0 = no dump).
    pub dump_every: u64,
}

impl Steps {
    /// Total steps of the protocol (the deck's default `nsteps`).
    pub fn total(&self) -> u64 {
        self.equilibrate + self.relax + self.slide
    }
    /// Name of the phase that step `step` (the state after `step` steps) belongs to:
    /// `equilibrate` up to and including the last equilibration step, and so on.
    pub fn phase(&self, step: u64) -> &'static str {
        if step <= self.equilibrate {
            "equilibrate"
        } else if step <= self.equilibrate + self.relax {
            "relax"
        } else {
            "slide"
        }
    }
}

/// The surrogate's quasi-static answer for the same scene and load (the start state).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SurrogateStart {
    /// Contacts.
    pub contacts: usize,
    /// P_max (GPa).
    #[serde(rename = "p_max_GPa")]
    pub p_max_gpa: f64,
    /// Height (µm).
    pub z_um: f64,
}

/// Contents of `export.json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ExportMeta {
    /// [`FORMAT`].
    pub format: String,
    /// Command that made the export.
    pub command: String,
    /// Pattern pair name.
    pub pattern: String,
    /// Slider rotation θ (degrees).
    pub theta_deg: f64,
    /// Slider centre offset (µm).
    pub offset_um: [f64; 2],
    /// Substrate height amplitude σ_h (µm).
    pub sigma_h_um: f64,
    /// Seed of the substrate heights.
    pub seed: u64,
    /// Slider mount: `locked`, `free` or `springs`.
    pub mount: String,
    /// K1 of the `springs` mount (N/m), null otherwise.
    #[serde(rename = "tilt_k1_N_m")]
    pub tilt_k1_n_m: Option<f64>,
    /// Normal load W (mN).
    #[serde(rename = "load_mN")]
    pub load_mn: f64,
    /// Pulling direction from the substrate x axis (degrees).
    pub direction_deg: f64,
    /// Pulling angle α from the contact line (degrees), if given.
    pub alpha_deg: Option<f64>,
    /// Contact-line angle from the substrate x axis (degrees), if given.
    pub line_deg: Option<f64>,
    /// The exported constant friction coefficient.
    pub mu: f64,
    /// The coating's μ1 (intact) and μ2 (failed).
    pub mu1: f64,
    /// See `mu1`.
    pub mu2: f64,
    /// Coating strength P_crit (GPa).
    #[serde(rename = "p_crit_GPa")]
    pub p_crit_gpa: f64,
    /// Radius of the substrate spheres, and of the slider's unless `slider_sphere_radius_um`
    /// is given (µm).
    pub sphere_radius_um: f64,
    /// Radius of the slider spheres when it differs from the substrate's (µm); absent for one
    /// sphere size.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub slider_sphere_radius_um: Option<f64>,
    /// Per-site sizes: each slider atom's radius (µm), in atom-ID order; absent without them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub slider_radii_um: Option<Vec<f64>>,
    /// Per-site sizes: each substrate atom's radius (µm), in atom-ID order.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub substrate_radii_um: Option<Vec<f64>>,
    /// Effective modulus E* of a sphere pair (GPa).
    #[serde(rename = "e_star_GPa")]
    pub e_star_gpa: f64,
    /// Effective radius R_eff of a sphere pair (µm).
    pub r_eff_um: f64,
    /// Time step (µs).
    pub dt_us: f64,
    /// Step counts.
    pub steps: Steps,
    /// Atom-ID ranges.
    pub ids: Ids,
    /// The surrogate's start state.
    pub surrogate: SurrogateStart,
    /// LAMMPS atoms in the data file.
    pub atoms: u64,
}

impl ExportMeta {
    /// Centre distance (µm) at which a slider and a substrate sphere touch: the sum of their
    /// radii (`2R`, bit for bit, for one sphere size).
    pub fn contact_distance_um(&self) -> f64 {
        self.slider_sphere_radius_um
            .unwrap_or(self.sphere_radius_um)
            + self.sphere_radius_um
    }

    /// Contact distance (µm) and R_eff (µm) of slider atom index `i` and substrate atom index
    /// `j` (0-based within their ranges): their own radii with per-site sizes, else
    /// [`ExportMeta::contact_distance_um`] and `r_eff_um`. O(1).
    pub fn pair_um(&self, i: usize, j: usize) -> (f64, f64) {
        if self.slider_radii_um.is_none() && self.substrate_radii_um.is_none() {
            return (self.contact_distance_um(), self.r_eff_um);
        }
        let a = self.slider_radii_um.as_ref().map_or(
            self.slider_sphere_radius_um
                .unwrap_or(self.sphere_radius_um),
            |r| r[i],
        );
        let b = self
            .substrate_radii_um
            .as_ref()
            .map_or(self.sphere_radius_um, |r| r[j]);
        (a + b, a * b / (a + b))
    }
}
