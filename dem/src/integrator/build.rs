//! [`Sim::new`]: the engine at rest from a layout, a contact model and the knobs — the checks
//! of the knobs, the initial state (every particle in the dense set), the mount's step data,
//! then the first active-set evaluation and force pass.

use super::body::Body;
use super::kernel::Index;
use super::mount::Mount;
use super::sim::Sim;
use super::team::Exec;
use crate::model::ContactModel;
use crate::params::SimParams;
use crate::system::{Active, State, SystemSpec};
use crate::DemError;

impl Sim {
    /// Creates the engine at rest in the layout `spec`, with step `dt` (s) and the critical-step
    /// estimate `dt_crit` (s, for messages). Builds the pair list, the active set and the
    /// initial forces.
    pub fn new(
        spec: SystemSpec,
        model: ContactModel,
        params: SimParams,
        dt: f64,
        dt_crit: f64,
    ) -> Result<Sim, DemError> {
        check_knobs(&spec, &params, dt)?;
        let body = Body::new(&spec, &params);
        let mount = (params.mount.implicit_mount && !params.mount.rigid_z)
            .then(|| Mount::new(&body, &params, dt));
        // The implicit mount cannot blow up, so a step beyond the contacts' limit would not end
        // in a non-finite state but in contacts that gain energy (the slider is thrown off):
        // refuse it up front, with the message of an unstable run.
        if mount.is_some() && dt > dt_crit {
            return Err(DemError::Unstable {
                t_us: 0.0,
                what: "the step is beyond the stable step of the contacts (with the implicit \
                       mount nothing else limits it, and a contact integrated past its limit \
                       gains energy instead of going non-finite)"
                    .into(),
                dt_us: dt * 1e6,
                dt_crit_us: dt_crit * 1e6,
            });
        }
        let state = initial_state(&spec, &body);
        let h_min = spec
            .substrate
            .iter()
            .map(|p| p[2])
            .fold(f64::INFINITY, f64::min);
        let overhang0 = spec
            .disc
            .and_then(|(c, _)| spec.overhang_at(c))
            .unwrap_or(f64::NEG_INFINITY);
        let mut sim = Sim {
            sub_h: spec.substrate.iter().map(|p| p[2]).collect(),
            spec,
            model,
            params,
            dt,
            dt_crit,
            state,
            body,
            idx: Index::default(),
            h_min,
            overhang0,
            tuner: Default::default(),
            d2: Vec::new(),
            mount,
        };
        sim.evaluate(true);
        sim.forces(Exec::Alone, 0.0, false);
        Ok(sim)
    }
}

/// The knobs' checks before anything is built: a positive step `dt` (s), a slider with
/// spheres, and with the active set a margin within the skin and springs that bring every
/// particle to rest.
fn check_knobs(spec: &SystemSpec, params: &SimParams, dt: f64) -> Result<(), DemError> {
    if !(dt.is_finite() && dt > 0.0) {
        return Err(DemError::invalid("dt_us", dt * 1e6, "must be positive"));
    }
    if spec.slider_sites.is_empty() {
        return Err(DemError::invalid(
            "slider.radius_um",
            0,
            "the slider has no spheres",
        ));
    }
    if params.active.enabled {
        let m = params.active.margin;
        if !(m.is_finite() && m > 0.0 && m <= params.numerics.skin) {
            return Err(DemError::invalid(
                "active_margin_nm",
                m * 1e9,
                &format!(
                    "must be positive and at most the neighbour skin ({} nm)",
                    params.numerics.skin * 1e9
                ),
            ));
        }
        let ks = [
            params.mount.k_slider_xy,
            params.mount.k_substrate_xy,
            if params.mount.rigid_z {
                1.0
            } else {
                params.mount.k_slider_z
            },
        ];
        if ks.iter().any(|k| !(k.is_finite() && *k > 0.0)) {
            return Err(DemError::invalid(
                "active_set",
                "on",
                "needs positive slider and tether springs (a free particle is never at rest)",
            ));
        }
    }
    Ok(())
}

/// The state at rest in the layout `spec`, every particle in the dense set (the first
/// evaluation keeps those that touch or deviate from their rest state).
fn initial_state(spec: &SystemSpec, body: &Body) -> State {
    let n = spec.slider_sites.len();
    let nb = spec.substrate.len();
    let sl_x: Vec<[f64; 3]> = spec
        .slider_sites
        .iter()
        .zip(&spec.slider_z)
        .map(|(s, z)| [s[0], s[1], *z])
        .collect();
    let sub_x: Vec<[f64; 2]> = spec.substrate.iter().map(|p| [p[0], p[1]]).collect();
    // Every particle starts in the dense set; the first evaluation keeps those that touch
    // or deviate from their rest state.
    let act = Active {
        sl: (0..n as u32).collect(),
        sl_x: sl_x.clone(),
        sl_v: vec![[0.0; 3]; n],
        sl_f: vec![[0.0; 3]; n],
        sl_x0: sl_x.clone(),
        sub: (0..nb as u32).collect(),
        sub_x: sub_x.clone(),
        sub_v: vec![[0.0; 2]; nb],
        sub_f: vec![[0.0; 2]; nb],
        sub_x0: sub_x.clone(),
        ..Default::default()
    };
    State {
        sub_v: vec![[0.0; 2]; nb],
        sl_v: vec![[0.0; 3]; n],
        ref_sub: sub_x.clone(),
        ref_sl: sl_x.clone(),
        sub_x,
        sl_x,
        act,
        cl_x: [body.centre0[0], body.centre0[1], spec.control_z],
        held_xy: true,
        ..Default::default()
    }
}
