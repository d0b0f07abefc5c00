//! Model choice per scene: which reductions a run uses, and why.
//!
//! - **prune** (leave out the substrate spheres the slider can never reach) and the **active
//!   set** (integrate only the particles in or near contact or still ringing) are exact, so
//!   every model uses them.
//! - **rigid-z** (slider spheres rigid in z on the control layer instead of on k_z springs)
//!   changes the physics by the compliance it removes. Each contact is a Hertz spring of normal
//!   stiffness `S_n = 2E*a = π·p0·R_eff` in series with its k_z spring, so the load shared among
//!   the contacts, and with it P_max and the friction, change to first order in
//!   `κ = S_n(p_ref)/k_z`, evaluated at the surrogate's P_max for the scene and load. `auto`
//!   takes rigid-z where κ is within the range where its error was measured small (see
//!   [`RIGID_Z_KAPPA_MAX`] and `dem/README.md`), and the full model elsewhere.

use crate::{DemError, SimParams};
use serde::Serialize;
use surrogate::solver::{Model, Pose, Solver};
use surrogate::Scene;

/// Largest `κ = S_n(P_max)/k_z` for which `auto` uses rigid-z. Measured (dem/README.md,
/// "Model choice"): κ = 0.0053 (square-tri 0°, 1.4 mN, α = 90°): friction +0.9 %, P_max +0.2 %.
pub const RIGID_Z_KAPPA_MAX: f64 = 0.0060;

/// Which model the user asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ModelRequest {
    /// The cheapest model within its measured error for this scene (default).
    Auto,
    /// The full model (slider spheres on k_z springs), with the exact reductions.
    Full,
    /// The reduced model: rigid-z, with the exact reductions.
    Reduced,
}

impl ModelRequest {
    /// Parses `auto | full | reduced`; errors name the flag `--model`.
    pub fn parse(s: &str) -> Result<ModelRequest, DemError> {
        match s {
            "auto" => Ok(ModelRequest::Auto),
            "full" => Ok(ModelRequest::Full),
            "reduced" => Ok(ModelRequest::Reduced),
            _ => Err(DemError::invalid(
                "--model",
                s,
                "expected one of auto, full, reduced",
            )),
        }
    }
    /// The kebab-case name.
    pub fn name(&self) -> &'static str {
        match self {
            ModelRequest::Auto => "auto",
            ModelRequest::Full => "full",
            ModelRequest::Reduced => "reduced",
        }
    }
}

/// The reductions a run uses, with the reason (for the log and the JSON summary).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelChoice {
    /// What was asked for: `auto`, `full` or `reduced`.
    pub requested: &'static str,
    /// What runs: `full` or `reduced` (= rigid-z).
    pub model: &'static str,
    /// Slider spheres rigid in z.
    pub rigid_z: bool,
    /// Unreachable substrate spheres left out (exact).
    pub prune: bool,
    /// Active set (exact to its tolerance).
    pub active_set: bool,
    /// `κ = S_n(p_ref)/k_z` (–): contact normal stiffness at the reference pressure over the
    /// slider z-spring stiffness; rigid-z's error scales with it.
    pub stiffness_ratio: f64,
    /// Reference pressure: the surrogate's P_max for this scene and load (GPa).
    #[serde(rename = "p_ref_GPa")]
    pub p_ref_gpa: f64,
    /// Human-readable reason for the choice.
    pub reason: String,
}

impl ModelChoice {
    /// Sets the reductions in `p`.
    pub fn apply(&self, p: &mut SimParams) {
        p.rigid_z = self.rigid_z;
        p.prune_substrate = self.prune;
        p.active_set = self.active_set;
    }
}

/// Decides rigid-z, prune and the active set for `scene` at `params.load` (see the module
/// doc). Cost: one surrogate solve (milliseconds).
pub fn choose_model(
    scene: &Scene,
    params: &SimParams,
    request: ModelRequest,
) -> Result<ModelChoice, DemError> {
    let eq = Solver::new(scene)?.solve(
        Pose {
            theta: scene.slider.theta,
            shift: [0.0, 0.0],
        },
        params.load,
        Model::Auto,
    )?;
    let p_ref = eq.p_max;
    let r_eff = scene.hertz().r_eff;
    let s_n = std::f64::consts::PI * p_ref * r_eff;
    let kappa = if params.k_slider_z > 0.0 {
        s_n / params.k_slider_z
    } else {
        f64::INFINITY
    };
    let exact = "prune and the active set are exact";
    let (rigid_z, reason) = match request {
        ModelRequest::Full => (false, format!("full model as requested; {exact}")),
        ModelRequest::Reduced => (
            true,
            format!(
                "rigid-z as requested (κ = S_n/k_z = {kappa:.4} at P_max {:.3} GPa; its error grows with κ); {exact}",
                p_ref * 1e-9
            ),
        ),
        ModelRequest::Auto => {
            if kappa <= RIGID_Z_KAPPA_MAX {
                (
                    true,
                    format!(
                        "rigid-z: contact stiffness S_n = π·P_max·R_eff = {:.0} N/m at the surrogate's P_max {:.3} GPa is κ = {kappa:.4} of k_z ≤ {RIGID_Z_KAPPA_MAX} (measured error there: friction ≤ 1 %, P_max ≤ 0.2 %); {exact}",
                        s_n,
                        p_ref * 1e-9
                    ),
                )
            } else {
                (
                    false,
                    format!(
                        "full model: contact stiffness S_n = {:.0} N/m at the surrogate's P_max {:.3} GPa is κ = {kappa:.4} of k_z > {RIGID_Z_KAPPA_MAX}, beyond the range where rigid-z was measured accurate; {exact}",
                        s_n,
                        p_ref * 1e-9
                    ),
                )
            }
        }
    };
    Ok(ModelChoice {
        requested: request.name(),
        model: if rigid_z { "reduced" } else { "full" },
        rigid_z,
        prune: true,
        active_set: true,
        stiffness_ratio: kappa,
        p_ref_gpa: p_ref * 1e-9,
        reason,
    })
}
