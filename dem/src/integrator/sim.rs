//! [`Sim`]: the DEM engine — the velocity-Verlet pipeline of one step and the engine's state.
//!
//! One step, in order (each stage a function below or in the sibling files):
//! 1. control layer (translation + tilts) and the common mode of the free slider spheres:
//!    first half kick and drift (O(1));
//! 2. the active particles: first half kick and drift, with their displacement since the last
//!    active-set evaluation (one parallel pass, `Sim::kick_drift`);
//! 3. if some particle may have moved `margin/2`: re-evaluate the active set (and rebuild the
//!    candidate pair list when needed) (`integrator::active`);
//! 4. forces: pair forces fused with the slider-sphere forces and their second half kick (one
//!    parallel pass over slider chunks, which also returns each chunk's reaction on the control
//!    layer), then the substrate spheres (one parallel pass), then the control layer and the
//!    common mode (O(1)) (`integrator::forces`).
//!
//! Work is split into chunks whose size depends only on the work, and partial sums are added
//! in chunk order, so results are bit-identical for any thread count. [`Sim::run_steps`] runs
//! the passes of its steps on a team of threads that stays hot between passes
//! (`integrator::team`).

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, Body};
use super::chunks::Chunking;
use super::team::{with_team, Exec, Shards};
use crate::model::ContactModel;
use crate::params::SimParams;
use crate::system::{Active, State, SystemSpec};
use crate::DemError;

/// Calls of [`Sim::run_steps`] shorter than this run on the calling thread (starting a team
/// costs ~20 µs per thread), unless the parallel passes are forced.
const MIN_TEAM_STEPS: u64 = 16;

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
    /// Mean z of the slider sphere centres (m).
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

/// Derived index data of the active set (rebuilt at each evaluation and after a checkpoint
/// load; never checkpointed).
#[derive(Debug, Clone, Default)]
pub(crate) struct Index {
    /// Per active slider sphere: its active pairs are `sl_pair_start[a]..sl_pair_start[a+1]`.
    pub sl_pair_start: Vec<u32>,
    /// Per active pair: the dense index of its substrate sphere.
    pub pair_b: Vec<u32>,
    /// Per active substrate sphere: its pairs are `sub_items[sub_start[b]..sub_start[b+1]]`.
    pub sub_start: Vec<u32>,
    /// Active-pair indices, grouped by substrate sphere, ascending within a group.
    pub sub_items: Vec<u32>,
    /// Inactive slider spheres.
    pub n_in: usize,
    /// Σ g gᵀ over the inactive slider spheres.
    pub g_in: [[f64; 3]; 3],
    /// Σ g over the inactive slider spheres.
    pub s_in: [f64; 3],
    /// Inactive candidate pairs whose coating failed at some time.
    pub ever_failed_inactive: usize,
    /// Chunking of the slider and substrate passes.
    pub chunks: Chunking,
    /// Per slider chunk: its reaction on the control layer (lateral x, y; generalized z, t_x,
    /// t_y) and the largest p0 (Pa) of its pairs.
    pub parts: Vec<[f64; 6]>,
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
    pub(crate) tuner: super::chunks::Tuner,
    /// Per chunk of the kick-drift pass: its largest squared displacement (m²).
    pub(crate) d2: Vec<f64>,
    /// The implicit mount step (`params.implicit_mount`, full model); `None`: velocity-Verlet.
    pub(crate) mount: Option<super::mount::Mount>,
}

#[inline]
pub(crate) fn kick(v: &mut f64, f: f64, h: f64, m: f64) {
    *v += h * f / m;
}

/// Max that propagates NaN (a non-finite displacement must reach the caller).
#[inline]
fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Kick with the precomputed `h/m` (no division in the particle loops).
#[inline]
pub(crate) fn kick_hm(v: &mut f64, f: f64, hm: f64) {
    *v += f * hm;
}

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
        if params.active_set {
            let m = params.active_margin;
            if !(m.is_finite() && m > 0.0 && m <= params.skin) {
                return Err(DemError::invalid(
                    "active_margin_nm",
                    m * 1e9,
                    &format!(
                        "must be positive and at most the neighbour skin ({} nm)",
                        params.skin * 1e9
                    ),
                ));
            }
            let ks = [
                params.k_slider_xy,
                params.k_substrate_xy,
                if params.rigid_z {
                    1.0
                } else {
                    params.k_slider_z
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
        let body = Body::new(&spec, &params);
        let mount = (params.implicit_mount && !params.rigid_z)
            .then(|| super::mount::Mount::new(&body, &params, dt));
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
        let state = State {
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
        };
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

    /// Control-layer mass (kg): one control sphere per slider sphere.
    pub fn control_mass(&self) -> f64 {
        self.body.m_cl
    }

    /// Mass of a slider / substrate sphere (kg).
    pub fn sphere_mass(&self) -> f64 {
        self.body.m_s
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
        let t = self.params.damping_time;
        if t.is_finite() && t > 0.0 {
            1.0 / t
        } else {
            0.0
        }
    }

    /// Half-displacement limit (m) that triggers an active-set evaluation.
    #[inline]
    fn trigger(&self) -> f64 {
        if self.params.active_set {
            0.5 * self.params.active_margin
        } else {
            0.5 * self.params.skin
        }
    }

    /// One velocity-Verlet step (see the module doc), on the calling thread. Errors with
    /// [`DemError::Unstable`] when a position or the control layer's state is no longer
    /// finite.
    pub fn step(&mut self) -> Result<(), DemError> {
        self.step_inner(Exec::Alone, false, false)
    }

    /// One step. `fused`: the substrate spheres' force and second half kick of the previous step
    /// were deferred and are done in this step's first pass, fused with their first half kick
    /// and drift. `defer`: leave this step's substrate force and second half kick to the next
    /// step. Each particle sees the same arithmetic either way (bit-identical results).
    fn step_inner(&mut self, exec: Exec, fused: bool, defer: bool) -> Result<(), DemError> {
        let h = 0.5 * self.dt;
        self.kick_control(h);
        self.kick_common(h);
        self.drift_frame();
        self.mount_step();
        let d2 = self.kick_drift(exec, h, fused);
        if !d2.is_finite() {
            return Err(self.unstable("non-finite particle position".into()));
        }
        let lim = self.trigger();
        let inactive_moves = self.idx.n_in > 0 || !self.state.ringing.sub.is_empty();
        if d2 > lim * lim || (inactive_moves && self.frame_disp() > lim) {
            self.evaluate(false);
        }
        self.forces(exec, h, defer);
        let s = &mut self.state;
        s.step += 1;
        s.t = s.step as f64 * self.dt;
        s.stats.particle_steps += (s.act.sl.len() + s.act.sub.len()) as u64;
        let fin = s.cl_x.iter().chain(&s.cl_v).chain(&s.tilt).chain(&s.tilt_v);
        if !fin.into_iter().all(|v| v.is_finite()) {
            return Err(self.unstable("non-finite control-layer state".into()));
        }
        Ok(())
    }

    /// Steps `k0..k1` of a call of `n` steps (the first fuses nothing, the last defers
    /// nothing).
    fn steps(&mut self, exec: Exec, k0: u64, k1: u64, n: u64) -> Result<(), DemError> {
        for k in k0..k1 {
            self.step_inner(exec, k > 0, k + 1 < n)?;
        }
        Ok(())
    }

    /// Runs `n` steps, bit-identical to `n` calls of [`Sim::step`] but with two passes per
    /// step instead of three: between two steps the substrate spheres' force and second half
    /// kick are fused with their next first half kick and drift (the substrate force needs
    /// only the pair forces of the slider pass and the substrate's own state).
    ///
    /// When the work is large enough (`parallel_min_work`) and the call long enough, the
    /// passes run on a team of `rayon::current_num_threads()` threads (the caller and scoped
    /// workers, `integrator::team`) kept for the whole call. Whether they actually do is decided
    /// by timing both modes now and then (`integrator::chunks::Tuner`): never slower with more
    /// threads, and the results do not depend on it.
    pub fn run_steps(&mut self, n: u64) -> Result<(), DemError> {
        let threads = rayon::current_num_threads();
        // parallel_min_work = 0 forces the parallel passes (no timing probes)
        let forced = self.params.parallel_min_work == 0;
        let team = threads > 1
            && self.idx.chunks.par
            && (forced || (n >= MIN_TEAM_STEPS && self.tuner.wants_par()));
        if !team {
            let t0 = std::time::Instant::now();
            let r = self.steps(Exec::Alone, 0, n, n);
            // (a call too short for a team is too short to time a mode)
            if self.idx.chunks.par && !forced && n >= MIN_TEAM_STEPS {
                self.tuner.record(false, n, t0.elapsed().as_secs_f64());
            }
            return r;
        }
        with_team(threads, |crew| {
            let mut k = 0;
            while k < n {
                let (par, len) = if forced {
                    (true, n - k)
                } else {
                    self.tuner.plan(n - k)
                };
                crew.set_idle(!par);
                let exec = if par { Exec::Team(crew) } else { Exec::Alone };
                let t0 = std::time::Instant::now();
                self.steps(exec, k, k + len, n)?;
                if !forced {
                    self.tuner.record(par, len, t0.elapsed().as_secs_f64());
                }
                k += len;
            }
            Ok(())
        })
    }

    /// First half kick of the control layer (lateral unless held; Z and the tilts through the
    /// mass matrix).
    fn kick_control(&mut self, h: f64) {
        let s = &mut self.state;
        if s.held_xy {
            s.cl_v[0] = 0.0;
            s.cl_v[1] = 0.0;
        } else {
            kick(&mut s.cl_v[0], s.cl_f[0], h, self.body.m_cl);
            kick(&mut s.cl_v[1], s.cl_f[1], h, self.body.m_cl);
        }
        match &self.body.tilt {
            None => kick(&mut s.cl_v[2], s.cl_f[2], h, self.body.mz),
            Some(t) => {
                let a = super::body::mat_vec(&t.m_inv, [s.cl_f[2], s.tilt_f[0], s.tilt_f[1]]);
                s.cl_v[2] += h * a[0];
                s.tilt_v[0] += h * a[1];
                s.tilt_v[1] += h * a[2];
            }
        }
    }

    /// Half kick of the common mode and of the aggregate of the ringing deviations, with their
    /// forces from the last force evaluation.
    fn kick_common(&mut self, h: f64) {
        let m = self.body.m_s;
        let c = &mut self.state.common;
        for k in 0..2 {
            kick(&mut c.v[k], c.fu[k], h, m);
            kick(&mut c.dv[k], c.fd[k], h, m);
        }
        if !self.params.rigid_z {
            for k in 0..3 {
                kick(&mut c.s[k], c.fw[k], h, m);
                kick(&mut c.dzv[k], c.fdz[k], h, m);
            }
        }
    }

    /// Drift of the control layer, the support and the common mode (relative to the layer).
    /// With the implicit mount the z parts (Z, tilts, common z mode) are left to
    /// [`Sim::mount_step`].
    fn drift_frame(&mut self) {
        let dt = self.dt;
        let implicit = self.mount.is_some();
        let rigid = self.params.rigid_z || implicit;
        let s = &mut self.state;
        for k in 0..if implicit { 2 } else { 3 } {
            s.cl_x[k] += dt * s.cl_v[k];
        }
        if self.body.tilt.is_some() && !implicit {
            s.tilt[0] += dt * s.tilt_v[0];
            s.tilt[1] += dt * s.tilt_v[1];
        }
        s.support[0] += dt * s.support_v[0];
        s.support[1] += dt * s.support_v[1];
        let c = &mut s.common;
        for k in 0..2 {
            c.u[k] += dt * (c.v[k] - s.cl_v[k]);
            c.d[k] += dt * c.dv[k];
        }
        if !rigid {
            let qd = [s.cl_v[2], s.tilt_v[0], s.tilt_v[1]];
            for k in 0..3 {
                c.w[k] += dt * (c.s[k] - qd[k]);
                c.dz[k] += dt * c.dzv[k];
            }
        }
    }

    /// First half kick and drift of the active particles; returns the largest squared
    /// displacement since the last active-set evaluation (m²). One pass over the slider
    /// chunks, then the substrate chunks. With `fused` the substrate spheres first get their
    /// deferred force and second half kick of the previous step
    /// ([`super::forces::SubstrateForce`]).
    fn kick_drift(&mut self, exec: Exec, h: f64, fused: bool) -> f64 {
        let inv_tau = self.inv_tau();
        let sf = super::forces::SubstrateForce::new(
            &self.idx,
            &self.spec,
            &self.params,
            self.body.m_s,
            inv_tau,
            h,
        );
        let dt = self.dt;
        let hm = h / self.body.m_s;
        let rigid = self.params.rigid_z;
        // z already advanced by the implicit mount step
        let implicit = self.mount.is_some();
        let q = self.q();
        let qd = self.qdot();
        let tilting = self.body.tilt.is_some();
        let off = &self.body.off;
        let Chunking { sl, sub, par } = self.idx.chunks;
        let crate::system::Active {
            sl: sl_ids,
            sl_x,
            sl_v,
            sl_f,
            sl_x0,
            sub: sub_ids,
            sub_x,
            sub_v,
            sub_f,
            sub_x0,
            out,
            ..
        } = &mut self.state.act;
        let (sl_ids, sl_f, sl_x0) = (&*sl_ids, &*sl_f, &*sl_x0);
        let (sub_ids, sub_x0, out) = (&*sub_ids, &*sub_x0, &*out);
        let n_sl = sl_x.len().div_ceil(sl);
        let n_sub = sub_x.len().div_ceil(sub);
        if self.d2.len() < n_sl + n_sub {
            self.d2.resize(n_sl + n_sub, 0.0);
        }
        let d2s = Shards::new(&mut self.d2[..n_sl + n_sub]);
        let (slx, slv) = (Shards::new(sl_x), Shards::new(sl_v));
        let (sbx, sbv, sbf) = (Shards::new(sub_x), Shards::new(sub_v), Shards::new(sub_f));
        let slider = |c: usize| {
            let (a, b) = (c * sl, (c + 1) * sl);
            // SAFETY: chunk c alone takes elements c·sl..(c+1)·sl and slot c (disjoint from
            // every other chunk), and the pass runs each chunk once.
            let (x, v, slot) = unsafe { (slx.range(a, b), slv.range(a, b), d2s.range(c, c + 1)) };
            let (f, x0, ids) = (&sl_f[a..a + x.len()], &sl_x0[a..], &sl_ids[a..]);
            // largest squared displacement; the plain sum only flags a non-finite value (two
            // independent accumulators, no NaN-aware max in the loop's dependency chain)
            let (mut d2, mut sum) = (0.0f64, 0.0f64);
            for ((((x, v), f), x0), &i) in x.iter_mut().zip(v.iter_mut()).zip(f).zip(x0).zip(ids) {
                kick_hm(&mut v[0], f[0], hm);
                kick_hm(&mut v[1], f[1], hm);
                x[0] += dt * v[0];
                x[1] += dt * v[1];
                if rigid {
                    if tilting {
                        let g = super::body::g_of(off[i as usize]);
                        x[2] = dot3(g, q);
                        v[2] = dot3(g, qd);
                    } else {
                        x[2] = q[0];
                        v[2] = qd[0];
                    }
                } else if !implicit {
                    kick_hm(&mut v[2], f[2], hm);
                    x[2] += dt * v[2];
                }
                let d = [x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]];
                let m = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                sum += m;
                if m > d2 {
                    d2 = m;
                }
            }
            slot[0] = if sum.is_finite() { d2 } else { f64::NAN };
        };
        let substrate = |k: usize| {
            let (a, b) = (k * sub, (k + 1) * sub);
            // SAFETY: substrate chunk k alone takes elements k·sub..(k+1)·sub and slot
            // n_sl + k, and the pass runs each chunk once.
            let (x, v, f, slot) = unsafe {
                (
                    sbx.range(a, b),
                    sbv.range(a, b),
                    sbf.range(a, b),
                    d2s.range(n_sl + k, n_sl + k + 1),
                )
            };
            if fused {
                sf.chunk_with(a, sub_ids, out, v, f, x);
            }
            let (mut d2, mut sum) = (0.0f64, 0.0f64);
            for (((x, v), f), x0) in x
                .iter_mut()
                .zip(v.iter_mut())
                .zip(f.iter())
                .zip(&sub_x0[a..])
            {
                kick_hm(&mut v[0], f[0], hm);
                kick_hm(&mut v[1], f[1], hm);
                x[0] += dt * v[0];
                x[1] += dt * v[1];
                let d = [x[0] - x0[0], x[1] - x0[1]];
                let m = d[0] * d[0] + d[1] * d[1];
                sum += m;
                if m > d2 {
                    d2 = m;
                }
            }
            slot[0] = if sum.is_finite() { d2 } else { f64::NAN };
        };
        exec.pass(par, [n_sl, n_sub], &|c| {
            if c < n_sl {
                slider(c)
            } else {
                substrate(c - n_sl)
            }
        });
        // NaN must win the max
        self.d2[..n_sl + n_sub]
            .iter()
            .fold(0.0, |a, &b| nan_max(a, b))
    }

    /// Upper bound of the displacement (m) of every inactive particle since the last
    /// evaluation: slider spheres move with the control layer and the common mode, plus their
    /// ringing deviation; substrate spheres by their ringing deviation only.
    fn frame_disp(&self) -> f64 {
        let s = &self.state;
        let mk = &s.mark;
        let lat = [
            s.cl_x[0] - mk.cl[0] + s.common.u[0] - mk.u[0],
            s.cl_x[1] - mk.cl[1] + s.common.u[1] - mk.u[1],
        ];
        let mut dq = [
            s.cl_x[2] - mk.cl[2],
            s.tilt[0] - mk.tilt[0],
            s.tilt[1] - mk.tilt[1],
        ];
        if !self.params.rigid_z {
            for k in 0..3 {
                dq[k] += s.common.w[k] - mk.w[k];
            }
        }
        let [ax, ay] = self.body.arm;
        let z = dq[0].abs() + dq[1].abs() * ay + dq[2].abs() * ax;
        let d = (lat[0] * lat[0] + lat[1] * lat[1] + z * z).sqrt() + mk.ring[0];
        let d = d.max(mk.ring[1]);
        if d.is_nan() {
            f64::INFINITY
        } else {
            d
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
        let (sa, ca) = self.params.alpha.sin_cos();
        let p = &self.params;
        let s = &mut self.state;
        s.held_xy = false;
        s.spring_on = true;
        s.support = [
            s.cl_x[0] + p.support_lead * ca,
            s.cl_x[1] + p.support_lead * sa,
        ];
        s.support0 = s.support;
        // Only the control-layer force changes: the spring is at rest length (adds 0 up to
        // rounding); the pair histories are not touched.
        let d = spring_stretch(p, s.support, s.cl_x);
        s.cl_f[0] += p.k0 * d[0];
        s.cl_f[1] += p.k0 * d[1];
    }

    /// Sets the support moving at `support_speed` along α.
    pub fn start_support(&mut self) {
        let (sa, ca) = self.params.alpha.sin_cos();
        let v = self.params.support_speed;
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

/// Pulling-spring stretch (m): the spring's rest anchor (the support moved back by the lead along
/// α) minus the control layer's centre `cl`, in x and y. The spring force is K0 times this.
#[inline]
pub(crate) fn spring_stretch(p: &SimParams, support: [f64; 2], cl: [f64; 3]) -> [f64; 2] {
    let (sa, ca) = p.alpha.sin_cos();
    [
        support[0] - p.support_lead * ca - cl[0],
        support[1] - p.support_lead * sa - cl[1],
    ]
}
