//! The JSON summaries of a DEM run: [`EquilibrateReport`], [`SlideReport`] and their parts.

use super::{EquilibrateSummary, SlideSummary};
use serde::Serialize;

/// Facts of a DEM run reported in every DEM summary (user units).
#[derive(Debug, Clone, Serialize)]
pub struct RunInfo {
    /// Time step used (µs).
    pub dt_us: f64,
    /// Estimated critical step (µs).
    pub dt_crit_us: f64,
    /// Mode that sets the critical step.
    pub dt_crit_mode: &'static str,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Contact-line angle from the substrate x axis (degrees).
    pub line_deg: f64,
    /// Pulling direction from the substrate x axis = line + α (degrees).
    pub direction_deg: f64,
    /// Moving particles (substrate + slider + control body).
    pub particles: usize,
    /// Substrate spheres left out by `--prune`.
    pub pruned_substrate: usize,
    /// Particle-steps per wall second.
    pub particle_steps_per_s: f64,
    /// Slider spheres rigid in z (reduction).
    pub rigid_z: bool,
    /// Substrate pruning in use.
    pub prune: bool,
    /// Model in use: `full` or `reduced` (= rigid-z).
    pub model: &'static str,
    /// `--model` as given: `auto`, `full` or `reduced`.
    pub model_requested: &'static str,
    /// Why this model (κ = S_n/k_z, P_max, Prandtl–Tomlinson η; docs/validation/dem-engine.md "Model choice").
    pub model_reason: String,
    /// ω_t/ω_p of the `springs` mount (`surrogate::friction::TiltResonance`): in 0.6–1.15 the
    /// friction where contacts fail depends strongly on K1; `null` without springs.
    pub tilt_pair_ratio: Option<f64>,
    /// Active set in use.
    pub active_set: bool,
    /// Mean number of particles integrated per step (the active set; all particles without it).
    pub mean_active_particles: f64,
}

/// What a DEM summary says about its configuration (user units): enough to tell two summaries
/// apart without the sidecar.
#[derive(Debug, Clone, Serialize)]
pub struct DemCase {
    /// Pattern pair name.
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Normal load W (mN).
    #[serde(rename = "load_mN")]
    pub load_mn: f64,
}

/// JSON summary of `superlube equilibrate`: the case, the DEM state at the end, the surrogate's
/// answer, their differences and the run facts.
#[derive(Debug, Clone, Serialize)]
pub struct EquilibrateReport {
    /// Pattern, θ, W.
    #[serde(flatten)]
    pub case: DemCase,
    /// DEM state at the end and the surrogate's answer.
    #[serde(flatten)]
    pub result: EquilibrateSummary,
    /// DEM contacts − surrogate contacts.
    pub contacts_diff: i64,
    /// DEM P_max / surrogate P_max − 1.
    pub p_max_rel_diff: f64,
    /// DEM z − surrogate z (nm); negative: the compliant DEM slider sits lower.
    pub z_diff_nm: f64,
    /// Run facts.
    #[serde(flatten)]
    pub run: RunInfo,
}

/// JSON summary of `superlube slide`: the case, friction and lock-in, and the run facts.
#[derive(Debug, Clone, Serialize)]
pub struct SlideReport {
    /// Pattern, θ, W.
    #[serde(flatten)]
    pub case: DemCase,
    /// Friction, contacts, lock-in over the measuring window.
    #[serde(flatten)]
    pub result: SlideSummary,
    /// Run facts.
    #[serde(flatten)]
    pub run: RunInfo,
}
