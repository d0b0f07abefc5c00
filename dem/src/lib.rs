//! # dem — dynamic DEM tier of superlube (SPEC.md "Tier 2")
//!
//! A slider of spheres tied to a rigid control layer slides over a tethered substrate of
//! spheres; Hertz + Mindlin contacts with a pressure-switched friction coefficient.
//!
//! Layout (one folder per concern): [`model`] (contact sub-models), [`system`] (particles and
//! state), [`neighbor`] (cell list + Verlet list with skin), [`integrator`] (velocity-Verlet
//! with damping: [`Sim`]), [`protocol`] (equilibrate / slide / lock-in), [`params`] (every knob:
//! [`SimParams`]), [`checkpoint`] (atomic save/resume), [`stability`] (stable-step estimate).
//!
//! Quick use:
//! ```no_run
//! # use dem::*;
//! let scene = surrogate::Scene::preset("square-tri").unwrap();
//! let params = SimParams { load: 1.4e-3, ..SimParams::default() };
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
pub mod params;
pub mod protocol;
pub mod stability;
pub mod system;

pub use error::DemError;
pub use integrator::{Observables, Sim};
pub use params::{DampingFrame, SimParams};
pub use stability::{stable_step, StabilityInput, StableStep};
pub use system::{from_scene, Start, StartInfo, SystemSpec};

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
/// pressure-switched coating law (e.g. a [`model::Constant`] μ for reference runs).
pub fn contact_model(
    scene: &Scene,
    params: &SimParams,
    friction: Option<Friction>,
) -> ContactModel {
    ContactModel {
        normal: HertzNormal {
            hertz: scene.hertz(),
            gamma_n: params.gamma_n,
        },
        tangential: Mindlin::equal_spheres(
            scene.material.youngs,
            scene.material.poisson,
            params.gamma_t,
        ),
        friction: friction.unwrap_or(Friction::PressureSwitched(PressureSwitched::from(
            &scene.coating,
        ))),
        radius_sum: 2.0 * scene.sphere_radius,
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
    StabilityInput {
        m_sphere: scene.material.sphere_mass(scene.sphere_radius),
        m_control: scene.material.sphere_mass(params.control_sphere_radius),
        n_slider,
        n_contacts,
        e_star: m.normal.hertz.e_star,
        g_star: m.tangential.g_star,
        r_eff: m.normal.hertz.r_eff,
        p_ref,
    }
}

/// Lays out `scene` (its θ, offset), starts it per `start`, estimates the stable step
/// (contact stiffness at `max(1.5·P_max(surrogate), P_crit)`), and builds the [`Sim`] with
/// `params.dt` or `dt_safety × dt_crit`.
pub fn prepare(
    scene: &Scene,
    params: SimParams,
    start: Start,
    friction: Option<Friction>,
) -> Result<Prepared, DemError> {
    if !(params.load.is_finite() && params.load > 0.0) {
        return Err(DemError::invalid(
            "load_mN",
            params.load * 1e3,
            "must be positive",
        ));
    }
    let (spec, info) = from_scene(scene, &params, start)?;
    let p_ref = (1.5 * info.p_max).max(scene.coating.p_crit);
    let inp = stability_input(
        scene,
        &params,
        spec.slider_sites.len(),
        info.contacts.max(1),
        p_ref,
    );
    let stable = stable_step(&inp, &params);
    let dt = params.dt.unwrap_or(params.dt_safety * stable.dt_crit);
    let model = contact_model(scene, &params, friction);
    let sim = Sim::new(spec, model, params, dt, stable.dt_crit)?;
    Ok(Prepared {
        sim,
        start: info,
        stable,
    })
}
