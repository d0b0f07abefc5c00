//! [`Sim`]: the DEM engine's state (layout, contact model, knobs, dynamic state, work buffers)
//! and its small accessors and protocol switches (attach the spring, start the support).
//!
//! The engine's other files add to it: `build.rs` creates it ([`Sim::new`]), `step.rs` runs the
//! velocity-Verlet step, `forces.rs` the force passes, `mount.rs` the implicit mount, `active.rs`
//! (with `active_select.rs` and `active_index.rs`) the active set and `observe.rs` the
//! observables; the kernels they share are in `kernel.rs`.

use super::body::Body;
use super::chunks::Tuner;
use super::kernel::{spring_stretch, Index};
use super::mount::Mount;
use crate::model::ContactModel;
use crate::params::SimParams;
use crate::system::{State, SystemSpec};
use crate::DemError;

/// Instantaneous observables of a state (SI).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct Observables {
    /// Simulated time (s).
    pub t: f64,
    /// Touching pairs (δ > 0).
    pub contacts: usize,
    /// Touching pairs whose coating has failed now (p0 > P_crit).
    pub failed: usize,
    /// Listed pairs whose coating failed at some time.
    pub ever_failed: usize,
    /// Largest p0 over the contacts (Pa).
    pub p_max: f64,
    /// Largest p0 (Pa) at any force evaluation since the peak was last taken
    /// ([`Sim::observe_sample`]), now included (≥ `p_max`).
    pub p_max_peak: f64,
    /// Largest overlap (m).
    pub max_overlap: f64,
    /// Mean z of the slider sphere centres (m); with per-sphere sizes, of their reference
    /// heights `z_i − (R − r_i)` (the body's reference centre plane).
    pub z: f64,
    /// Σ vertical contact force on the slider (N).
    pub contact_fz: f64,
    /// Pulling-spring force along α (N) (0 when detached).
    pub spring_force: f64,
    /// Support travel along α since the spring was attached (m).
    pub support_travel: f64,
    /// Control-layer travel along α since the spring was attached (m).
    pub slider_travel: f64,
    /// Control-layer tilts `[t_x, t_y]` (rad).
    pub tilt: [f64; 2],
    /// Slider spheres integrated in the last step (all of them without the active set).
    pub active_slider: usize,
    /// Substrate spheres integrated in the last step.
    pub active_substrate: usize,
}

/// The DEM engine: static layout, contact model, knobs, state and work buffers.
///
/// Per step: O(n + p) work over the n *active* particles and their p pairs (all particles
/// without the active set), no allocation except at active-set evaluations and neighbour
/// rebuilds, bit-identical for any thread count.
pub struct Sim {
    /// Static layout.
    pub spec: SystemSpec,
    /// Contact model.
    pub model: ContactModel,
    /// Knobs (the `dt` actually used is [`Sim::dt`]).
    pub params: SimParams,
    /// Time step (s).
    pub dt: f64,
    /// Estimated critical step (s), reported on instability.
    pub dt_crit: f64,
    /// Dynamic state.
    pub state: State,
    pub(crate) sub_h: Vec<f64>,
    pub(crate) body: Body,
    pub(crate) idx: Index,
    pub(crate) h_min: f64,
    pub(crate) overhang0: f64,
    pub(crate) tuner: Tuner,
    /// Per chunk of the kick-drift pass: its largest squared displacement (m²).
    pub(crate) d2: Vec<f64>,
    /// The implicit mount step (`params.implicit_mount`, full model); `None`: velocity-Verlet.
    pub(crate) mount: Option<Mount>,
}

impl Sim {
    /// Control-layer mass (kg): one control sphere per slider sphere.
    pub fn control_mass(&self) -> f64 {
        self.body.m_cl
    }

    /// Mass of a slider sphere (kg).
    pub fn slider_sphere_mass(&self) -> f64 {
        self.body.m_s
    }

    /// Mass of a substrate sphere (kg).
    pub fn substrate_sphere_mass(&self) -> f64 {
        self.body.m_b
    }

    /// Number of slider spheres.
    pub fn n_slider(&self) -> usize {
        self.state.sl_x.len()
    }

    /// Number of substrate spheres.
    pub fn n_substrate(&self) -> usize {
        self.state.sub_x.len()
    }

    /// Moving particles of the model (substrate + slider + 1 control body), whether or not the
    /// active set integrates them all.
    pub fn particles(&self) -> usize {
        self.n_substrate() + self.n_slider() + 1
    }

    /// Particles integrated in the current step (active slider + substrate spheres + 1).
    pub fn active_particles(&self) -> usize {
        self.state.act.sl.len() + self.state.act.sub.len() + 1
    }

    /// Rest offset (m) of slider sphere `i` from the control-layer centre of mass.
    pub fn site_offset(&self, i: usize) -> [f64; 2] {
        self.body.off[i]
    }

    /// Whether the control layer has tilt degrees of freedom (mount `free` or `springs`).
    pub fn tilting(&self) -> bool {
        self.body.tilt.is_some()
    }

    /// Generalized velocity `q̇ = (Ż, ṫ_x, ṫ_y)` of the control layer.
    #[inline]
    pub(crate) fn qdot(&self) -> [f64; 3] {
        let s = &self.state;
        [s.cl_v[2], s.tilt_v[0], s.tilt_v[1]]
    }

    /// Generalized position `q = (Z, t_x, t_y)`.
    #[inline]
    pub(crate) fn q(&self) -> [f64; 3] {
        let s = &self.state;
        [s.cl_x[2], s.tilt[0], s.tilt[1]]
    }

    /// 1 / damping time (1/s), 0 when damping is off.
    #[inline]
    pub(crate) fn inv_tau(&self) -> f64 {
        let t = self.params.numerics.damping_time;
        if t.is_finite() && t > 0.0 {
            1.0 / t
        } else {
            0.0
        }
    }

    /// The instability error for the current time.
    pub fn unstable(&self, what: String) -> DemError {
        DemError::Unstable {
            t_us: self.state.t * 1e6,
            what,
            dt_us: self.dt * 1e6,
            dt_crit_us: self.dt_crit * 1e6,
        }
    }

    /// Releases the lateral hold of the control layer and attaches the pulling spring with the
    /// support `support_lead` ahead along α (zero initial spring force).
    pub fn attach_spring(&mut self) {
        let (sa, ca) = self.params.protocol.alpha.sin_cos();
        let p = &self.params;
        let s = &mut self.state;
        s.held_xy = false;
        s.spring_on = true;
        s.support = [
            s.cl_x[0] + p.protocol.support_lead * ca,
            s.cl_x[1] + p.protocol.support_lead * sa,
        ];
        s.support0 = s.support;
        // Only the control-layer force changes: the spring is at rest length (adds 0 up to
        // rounding); the pair histories are not touched.
        let d = spring_stretch(p, s.support, s.cl_x);
        s.cl_f[0] += p.protocol.k0 * d[0];
        s.cl_f[1] += p.protocol.k0 * d[1];
    }

    /// Sets the support moving at `support_speed` along α.
    pub fn start_support(&mut self) {
        let (sa, ca) = self.params.protocol.alpha.sin_cos();
        let v = self.params.protocol.support_speed;
        self.state.support_v = [v * ca, v * sa];
    }

    /// Per-pair results of the last force evaluation, parallel to `state.act.pairs` (the
    /// active pairs; every listed pair without the active set).
    pub fn pair_results(&self) -> &[crate::model::PairOut] {
        &self.state.act.out
    }

    /// Friction coefficient μ(p0) of the model's friction law.
    pub fn mu_at(&self, p0: f64) -> f64 {
        use crate::model::FrictionLaw;
        self.model.friction.mu(p0)
    }
}
