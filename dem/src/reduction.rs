//! Model choice per scene: which reductions a run uses, and why.
//!
//! - **prune** (leave out the substrate spheres the slider can never reach) and the **active
//!   set** (integrate only the particles in or near contact or still ringing) are exact, so
//!   every model uses them.
//! - **rigid-z** (slider spheres rigid in z on the control layer instead of on k_z springs)
//!   changes the physics by the compliance it removes. Each contact is a Hertz spring of normal
//!   stiffness `S_n = 2E*a = π·p0·R_eff` in series with its k_z spring, so the load shared among
//!   the contacts, and with it P_max and the friction, change to first order in
//!   `κ = S_n(p_ref)/k_z`, evaluated at the surrogate's P_max for the scene and load. Where
//!   contacts may exceed P_crit while sliding, a small shift of P_max switches contacts between
//!   μ1 and μ2 = 50·μ1, so the friction is no longer first order in κ. `auto` takes rigid-z only
//!   where κ ≤ [`RIGID_Z_KAPPA_MAX`], the surrogate's P_max times the sliding overshoot
//!   allowance [`SLIDING_P_MAX_FACTOR`] stays below P_crit, and no stick-slip is expected
//!   (Prandtl–Tomlinson η ≤ [`STICK_SLIP_ETA`], [`stick_slip_eta`]); the full model elsewhere
//!   (the measurements behind the limits are in `docs/validation/dem-engine.md`, "Model choice").

use crate::{DemError, Nominal, SimParams};
use serde::Serialize;
use surrogate::map::{path_profile, MapParams};
use surrogate::solver::Solver;
use surrogate::Scene;

/// Prandtl–Tomlinson parameter of the slide: `η = 2π·F_max/(K0·a)` from the surrogate's
/// quasi-static path along the pulling direction over two substrate periods (`F_max` the
/// largest pulling force, the static-friction barrier; `a` the substrate spacing; `K0` the
/// pulling spring, much softer than the slider's own lateral stiffness). `η > 1`: stick-slip
/// expected (docs/physics.md, "Estimating friction without dynamics"). Returns `(η, F_max)`, or `None` when the run does
/// not slide or the path cannot be solved. Cost: ~40 surrogate solves (tens of ms).
pub fn stick_slip_eta(scene: &Scene, params: &SimParams, solver: &Solver) -> Option<(f64, f64)> {
    if params.protocol.slide_time <= 0.0
        || params.protocol.support_speed <= 0.0
        || params.protocol.k0 <= 0.0
    {
        return None;
    }
    let lat = scene.substrate.lattice;
    let norm = |a: [f64; 2]| (a[0] * a[0] + a[1] * a[1]).sqrt();
    let a = norm(lat.a1).min(norm(lat.a2));
    let mp = MapParams {
        distance: 2.0 * norm(lat.a1).max(norm(lat.a2)),
        step: a / 20.0,
        ..MapParams::default()
    };
    let prof = path_profile(
        solver,
        scene.slider.theta,
        params.protocol.load,
        params.protocol.alpha,
        &mp,
        &|| {},
    )
    .ok()?;
    let f_max = prof.max_pull().max(0.0);
    Some((
        2.0 * std::f64::consts::PI * f_max / (params.protocol.k0 * a),
        f_max,
    ))
}

/// Largest `κ = S_n(P_max)/k_z` for which `auto` uses rigid-z: the square-tri study scene up to
/// 2.45 mN (κ = 0.0063), just above where rigid-z was measured against the full model
/// (κ = 0.0053, docs/validation/dem-engine.md "Model choice").
pub const RIGID_Z_KAPPA_MAX: f64 = 0.0065;

/// Allowance for the rise of P_max while sliding over the surrogate's static P_max at the
/// start pose (measured: ×1.06–1.09 on square-tri 0°/α = 90°, ×1.19–1.21 on tri-tri 30°): `auto`
/// keeps the full model unless `P_max·1.25 < P_crit`, i.e. unless no contact is expected to come
/// near coating failure.
pub const SLIDING_P_MAX_FACTOR: f64 = 1.25;

/// Above this Prandtl–Tomlinson η `auto` keeps the full model: the slider sticks and slips, and
/// rigid-z misses the pressure peaks when it drops into the corrugation (measured on
/// square-tri 0°/α = 0°, 1.4 mN, η = 6.0: max P_max −9.8 % at every step, −12 % at the rows
/// every 0.1 µs; contacts −8 %).
pub const STICK_SLIP_ETA: f64 = 1.0;

/// Which model the user asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ModelRequest {
    /// The cheapest model within its measured error for this scene (default).
    Auto,
    /// The full model (slider spheres on k_z springs), with the exact reductions, its linear
    /// mount network integrated implicitly ([`crate::MountParams::implicit_mount`]): the step is
    /// set by the contacts.
    Full,
    /// The full model integrated by velocity-Verlet throughout (the step set by the stiff k_z
    /// springs, ~28× smaller): the reference for [`ModelRequest::Full`].
    FullExplicit,
    /// The reduced model: rigid-z, with the exact reductions.
    Reduced,
}

impl ModelRequest {
    /// Parses `auto | full | full-explicit | reduced`; errors name the flag `--model`.
    pub fn parse(s: &str) -> Result<ModelRequest, DemError> {
        match s {
            "auto" => Ok(ModelRequest::Auto),
            "full" => Ok(ModelRequest::Full),
            "full-explicit" => Ok(ModelRequest::FullExplicit),
            "reduced" => Ok(ModelRequest::Reduced),
            _ => Err(DemError::invalid(
                "--model",
                s,
                "expected one of auto, full, full-explicit, reduced",
            )),
        }
    }
    /// The kebab-case name.
    pub fn name(&self) -> &'static str {
        match self {
            ModelRequest::Auto => "auto",
            ModelRequest::Full => "full",
            ModelRequest::FullExplicit => "full-explicit",
            ModelRequest::Reduced => "reduced",
        }
    }
}

/// The reductions a run uses, with the reason (for the log and the JSON summary).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelChoice {
    /// What was asked for: `auto`, `full`, `full-explicit` or `reduced`.
    pub requested: &'static str,
    /// What runs: `full`, `full-explicit` or `reduced` (= rigid-z).
    pub model: &'static str,
    /// Slider spheres rigid in z.
    pub rigid_z: bool,
    /// Full model with the implicit mount step (`full`; `false` for `full-explicit`).
    pub implicit_mount: bool,
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
    /// Prandtl–Tomlinson η of the slide ([`stick_slip_eta`]); `None` without sliding.
    pub stick_slip_eta: Option<f64>,
    /// Whether a contact may reach coating failure while sliding: the surrogate's P_max ×
    /// [`SLIDING_P_MAX_FACTOR`] ≥ P_crit (then `auto` keeps the full model).
    pub coating_may_fail: bool,
    /// Human-readable reason for the choice.
    pub reason: String,
}

impl ModelChoice {
    /// Sets the reductions in `p`.
    pub fn apply(&self, p: &mut SimParams) {
        p.mount.rigid_z = self.rigid_z;
        p.mount.implicit_mount = self.implicit_mount && !self.rigid_z;
        p.active.prune_substrate = self.prune;
        p.active.enabled = self.active_set;
    }
}

/// Decides rigid-z, prune and the active set for `scene` at `params.protocol.load` (see the
/// module doc). Cost: one surrogate solve (milliseconds) and, with sliding, the path of
/// [`stick_slip_eta`]; [`choose_model_at`] reuses a run's [`Nominal`] solve.
pub fn choose_model(
    scene: &Scene,
    params: &SimParams,
    request: ModelRequest,
) -> Result<ModelChoice, DemError> {
    let nominal = Nominal::solve(scene, params.protocol.load)?;
    Ok(choose_model_at(scene, params, request, &nominal))
}

/// [`choose_model`] from the run's nominal solve `nominal` (at `params.protocol.load`).
/// Cost: with sliding, the ~40 solves of [`stick_slip_eta`]; none otherwise.
pub fn choose_model_at(
    scene: &Scene,
    params: &SimParams,
    request: ModelRequest,
    nominal: &Nominal,
) -> ModelChoice {
    let (solver, eq) = (&nominal.solver, &nominal.eq);
    let p_ref = eq.p_max;
    let r_eff = scene.hertz().r_eff;
    let s_n = std::f64::consts::PI * p_ref * r_eff;
    let kappa = if params.mount.k_slider_z > 0.0 {
        s_n / params.mount.k_slider_z
    } else {
        f64::INFINITY
    };
    let eta = stick_slip_eta(scene, params, solver);
    let coating_may_fail = p_ref * SLIDING_P_MAX_FACTOR >= scene.coating.p_crit;
    let (rigid_z, reason) = decide(scene, request, kappa, s_n, p_ref, eta, coating_may_fail);
    let implicit_mount = !rigid_z && request != ModelRequest::FullExplicit;
    ModelChoice {
        requested: request.name(),
        model: if rigid_z {
            "reduced"
        } else if implicit_mount {
            "full"
        } else {
            "full-explicit"
        },
        rigid_z,
        implicit_mount,
        prune: true,
        active_set: true,
        stiffness_ratio: kappa,
        p_ref_gpa: p_ref * 1e-9,
        stick_slip_eta: eta.map(|e| e.0),
        coating_may_fail,
        reason,
    }
}

/// Whether `request` runs rigid-z, and why: `auto` keeps the full model where a contact may
/// reach coating failure, where stick-slip is expected (η > [`STICK_SLIP_ETA`]) or beyond
/// [`RIGID_Z_KAPPA_MAX`]; the reason quotes κ, S_n (N/m), the reference P_max `p_ref` (Pa) and
/// η with F_max (N). Cost: O(1).
fn decide(
    scene: &Scene,
    request: ModelRequest,
    kappa: f64,
    s_n: f64,
    p_ref: f64,
    eta: Option<(f64, f64)>,
    coating_may_fail: bool,
) -> (bool, String) {
    let exact = "prune and the active set are exact";
    match request {
        ModelRequest::Full => (
            false,
            format!("full model as requested (mount springs implicit, step set by the contacts); {exact}"),
        ),
        ModelRequest::FullExplicit => (
            false,
            format!("full model, velocity-Verlet throughout, as requested (step set by the k_z springs); {exact}"),
        ),
        ModelRequest::Reduced => (
            true,
            format!(
                "rigid-z as requested (κ = S_n/k_z = {kappa:.4} at P_max {:.3} GPa; its error grows with κ); {exact}",
                p_ref * 1e-9
            ),
        ),
        ModelRequest::Auto => {
            let head = format!(
                "κ = S_n/k_z = {kappa:.4} (S_n = π·P_max·R_eff = {:.0} N/m at the surrogate's P_max {:.3} GPa){}",
                s_n,
                p_ref * 1e-9,
                match eta {
                    Some((e, f)) => format!(
                        ", Prandtl–Tomlinson η = 2π·F_max/(K0·a) = {e:.3} (F_max {:.3} µN along the path)",
                        f * 1e6
                    ),
                    None => String::new(),
                }
            );
            if coating_may_fail {
                (
                    false,
                    format!(
                        "full model: P_max {:.3} GPa × {SLIDING_P_MAX_FACTOR} (sliding overshoot) reaches P_crit {:.3} GPa, where rigid-z's shift of P_max switches contacts between μ1 and μ2; {head}; {exact}",
                        p_ref * 1e-9,
                        scene.coating.p_crit * 1e-9
                    ),
                )
            } else if eta.is_some_and(|(e, _)| e > STICK_SLIP_ETA) {
                (
                    false,
                    format!(
                        "full model: stick-slip expected (η > {STICK_SLIP_ETA}), where rigid-z misses the pressure peaks of the slips; {head}; {exact}"
                    ),
                )
            } else if kappa > RIGID_Z_KAPPA_MAX {
                (
                    false,
                    format!(
                        "full model: κ > {RIGID_Z_KAPPA_MAX}, beyond the range where rigid-z was measured accurate; {head}; {exact}"
                    ),
                )
            } else {
                (
                    true,
                    format!(
                        "rigid-z: κ ≤ {RIGID_Z_KAPPA_MAX}, P_max far below P_crit {:.3} GPa and no stick-slip expected; {head}; {exact}",
                        scene.coating.p_crit * 1e-9
                    ),
                )
            }
        }
    }
}
