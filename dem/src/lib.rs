//! # dem — dynamic DEM tier of superlube (Tier 3 confirm; model in docs/physics.md)
//!
//! A slider of spheres tied to a rigid control layer slides over a tethered substrate of
//! spheres; Hertz + Mindlin contacts with a pressure-switched friction coefficient.
//!
//! Layout (one folder per concern): [`model`] (contact sub-models), [`system`] (particles and
//! state), [`neighbor`] (cell list + Verlet list with skin), [`integrator`] (velocity-Verlet
//! with damping: [`Sim`]), [`protocol`] (equilibrate / slide / lock-in), [`params`] (every knob:
//! [`SimParams`], composed of protocol, contact, mount, numerics and active-set parts), [`checkpoint`] (atomic save/resume), [`stability`] (stable-step estimate).
//!
//! Quick use:
//! ```no_run
//! # use dem::*;
//! let scene = surrogate::Scene::preset("square-tri").unwrap();
//! let mut params = SimParams::default();
//! params.protocol.load = 1.4e-3;
//! let prep = prepare(&scene, params, Start::Surrogate, None).unwrap();
//! let mut sim = prep.sim;
//! let mut samples = Vec::new();
//! protocol::run(&mut sim, protocol::RunKind::Slide, &Default::default(), &mut samples, &mut |_| {}).unwrap();
//! ```
#![warn(missing_docs)]

pub mod checkpoint;
pub mod error;
pub mod export;
pub mod integrator;
pub mod model;
pub mod neighbor;
pub mod nominal;
pub mod params;
pub mod path;
pub mod protocol;
pub mod reduction;
pub mod stability;
pub mod system;

pub use error::DemError;
pub use integrator::observe::Snapshot;
pub use integrator::{Observables, Sim};
pub use nominal::Nominal;
pub use params::{
    ActiveSetParams, ContactParams, DampingFrame, MountParams, NumericsParams, ProtocolParams,
    SimParams, Tangential,
};
pub use path::check_path;
pub use reduction::{choose_model, choose_model_at, ModelChoice, ModelRequest};
pub use stability::{stable_step, StabilityInput, StableStep};
pub use system::{from_scene, from_scene_at, Start, StartInfo, SystemSpec};

use model::{ContactModel, Friction, HertzNormal, Mindlin, PressureSwitched};
use surrogate::Scene;

/// A ready-to-run simulation with its provenance.
pub struct Prepared {
    /// The engine at its start state.
    pub sim: Sim,
    /// The surrogate's equilibrium for the same scene and load, and the pruning count.
    pub start: StartInfo,
    /// Stable-step estimate of this model.
    pub stable: StableStep,
}

/// The contact model of `scene` with damping from `params`; `friction` overrides the scene's
/// pressure-switched coating law (e.g. a [`model::Constant`] μ for reference runs). Hertz of
/// the slider–substrate pair (`R_eff` from both sphere radii), radius sum `R_sl + R_sb`.
pub fn contact_model(
    scene: &Scene,
    params: &SimParams,
    friction: Option<Friction>,
) -> ContactModel {
    ContactModel {
        normal: HertzNormal {
            hertz: scene.hertz(),
            gamma_n: params.contact.gamma_n,
        },
        tangential: Mindlin::between(
            &scene.slider_material(),
            &scene.substrate_material(),
            params.contact.gamma_t,
        ),
        history: params.contact.tangential,
        friction: friction.unwrap_or(Friction::PressureSwitched(PressureSwitched::from(
            &scene.coating,
        ))),
        radius_sum: scene.contact_distance(),
    }
}

/// Stable-step inputs for `scene` at reference pressure `p_ref` (Pa) with `n_contacts` contacts.
pub fn stability_input(
    scene: &Scene,
    params: &SimParams,
    n_slider: usize,
    n_contacts: usize,
    p_ref: f64,
) -> StabilityInput {
    let m = contact_model(scene, params, None);
    // with per-site sizes the lightest spheres and the stiffest pair (largest R_eff) bound
    // the step
    let (m_slider, m_substrate, r_eff) = if scene.has_site_sizes() {
        let min =
            |r: Option<&[f64]>, r0: f64| r.map_or(r0, |r| r.iter().copied().fold(r0, f64::min));
        let (r_sl, r_sb) = (
            scene.max_slider_sphere_radius(),
            scene.max_contact_distance() - scene.max_slider_sphere_radius(),
        );
        (
            scene
                .slider_material()
                .sphere_mass(min(scene.slider_radii(), f64::INFINITY)),
            scene
                .substrate_material()
                .sphere_mass(min(scene.substrate_radii(), scene.sphere_radius)),
            r_sl * r_sb / (r_sl + r_sb),
        )
    } else {
        (
            scene
                .slider_material()
                .sphere_mass(scene.slider_sphere_radius()),
            scene.substrate_material().sphere_mass(scene.sphere_radius),
            m.normal.hertz.r_eff,
        )
    };
    let m_control = scene
        .slider_material()
        .sphere_mass(params.mount.control_sphere_radius);
    StabilityInput {
        m_slider,
        m_substrate,
        m_control,
        n_slider,
        n_contacts,
        e_star: m.normal.hertz.e_star,
        g_star: m.tangential.g_star,
        r_eff,
        p_ref,
        tilt_omega2: tilt_omega2(scene, params, m_slider, m_control),
    }
}

/// ω² (1/s²) of the control layer tilting on the mount springs: the largest eigenvalue of K_t
/// over the smallest principal tilt inertia (layer, plus slider spheres with rigid-z). 0 when
/// the mount has no springs.
fn tilt_omega2(scene: &Scene, params: &SimParams, m_sphere: f64, m_control: f64) -> f64 {
    let k = scene.tilt_stiffness_at(scene.slider.theta);
    let eig = |a: f64, b: f64, d: f64| {
        let m = 0.5 * (a + d);
        let r = (0.25 * (a - d) * (a - d) + b * b).sqrt();
        (m - r, m + r)
    };
    let (_, k_max) = eig(k[0][0], k[0][1], k[1][1]);
    if k_max.is_nan() || k_max <= 0.0 {
        return 0.0;
    }
    let sites = scene.slider_sites();
    let n = sites.len() as f64;
    let c = sites
        .iter()
        .fold([0.0, 0.0], |a, s| [a[0] + s[0] / n, a[1] + s[1] / n]);
    let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
    for s in &sites {
        let (x, y) = (s[0] - c[0], s[1] - c[1]);
        sxx += x * x;
        syy += y * y;
        sxy += x * y;
    }
    let unit = if params.mount.rigid_z {
        m_control + m_sphere
    } else {
        m_control
    };
    let (i_min, _) = eig(syy, -sxy, sxx);
    if i_min > 0.0 {
        k_max / (unit * i_min)
    } else {
        0.0
    }
}

/// Checks the slide path against the substrate ([`check_path`]), lays out `scene` (its θ,
/// offset, mount), starts it per `start`, estimates the stable step (contact stiffness at
/// `max(1.5·P_max(surrogate), P_crit)`), and builds the [`Sim`] with `params.numerics.dt` or
/// `dt_safety × dt_crit`. Cost: one surrogate solve ([`Nominal`]) and O(N log N);
/// [`prepare_at`] reuses a run's nominal solve.
pub fn prepare(
    scene: &Scene,
    params: SimParams,
    start: Start,
    friction: Option<Friction>,
) -> Result<Prepared, DemError> {
    check_run(scene, &params)?;
    let nominal = Nominal::solve(scene, params.protocol.load)?;
    build(scene, params, start, friction, &nominal)
}

/// [`prepare`] from the run's nominal solve `nominal` (of `scene` at `params.protocol.load`,
/// as [`choose_model_at`] took it). Cost: O(N log N).
pub fn prepare_at(
    scene: &Scene,
    params: SimParams,
    start: Start,
    friction: Option<Friction>,
    nominal: &Nominal,
) -> Result<Prepared, DemError> {
    check_run(scene, &params)?;
    build(scene, params, start, friction, nominal)
}

/// Refuses a load that is not positive and a slide path off the substrate.
fn check_run(scene: &Scene, params: &SimParams) -> Result<(), DemError> {
    if !(params.protocol.load.is_finite() && params.protocol.load > 0.0) {
        return Err(DemError::invalid(
            "load_mN",
            params.protocol.load * 1e3,
            "must be positive",
        ));
    }
    check_path(scene, params)
}

/// The checked run's layout, stable step and engine.
fn build(
    scene: &Scene,
    params: SimParams,
    start: Start,
    friction: Option<Friction>,
    nominal: &Nominal,
) -> Result<Prepared, DemError> {
    let (spec, info) = from_scene_at(scene, &params, start, &nominal.eq);
    let p_ref = (1.5 * info.p_max).max(scene.coating.p_crit);
    let inp = stability_input(
        scene,
        &params,
        spec.slider_sites.len(),
        info.contacts.max(1),
        p_ref,
    );
    let stable = stable_step(&inp, &params);
    let dt = params
        .numerics
        .dt
        .unwrap_or(params.numerics.dt_safety * stable.dt_crit);
    let model = contact_model(scene, &params, friction);
    let sim = Sim::new(spec, model, params, dt, stable.dt_crit)?;
    Ok(Prepared {
        sim,
        start: info,
        stable,
    })
}
