//! The velocity-Verlet pipeline of one [`Sim`] step, and runs of steps on a team of threads.
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

use super::body::mat_vec;
use super::chunks::Chunking;
use super::drift::{slider_chunk, substrate_chunk, SliderDrift};
use super::forces::SubstrateForce;
use super::kernel::{kick, nan_max};
use super::sim::Sim;
use super::team::{with_team, Exec, Shards};
use crate::DemError;

/// Calls of [`Sim::run_steps`] shorter than this run on the calling thread (starting a team
/// costs ~20 µs per thread), unless the parallel passes are forced.
const MIN_TEAM_STEPS: u64 = 16;

impl Sim {
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
        let forced = self.params.numerics.parallel_min_work == 0;
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
    pub(super) fn kick_control(&mut self, h: f64) {
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
                let a = mat_vec(&t.m_inv, [s.cl_f[2], s.tilt_f[0], s.tilt_f[1]]);
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
        if !self.params.mount.rigid_z {
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
        let rigid = self.params.mount.rigid_z || implicit;
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
    /// ([`SubstrateForce`]).
    fn kick_drift(&mut self, exec: Exec, h: f64, fused: bool) -> f64 {
        let inv_tau = self.inv_tau();
        let sf = SubstrateForce::new(
            &self.idx,
            &self.spec,
            &self.params,
            self.body.m_b,
            self.body.sizes.as_ref().map(|z| &z.sub_m[..]),
            inv_tau,
            h,
        );
        let dt = self.dt;
        let sizes = self.body.sizes.as_ref();
        let hm = h / self.body.m_s;
        let hm_b = h / self.body.m_b;
        let rigid = self.params.mount.rigid_z;
        // z already advanced by the implicit mount step
        let implicit = self.mount.is_some();
        let k = SliderDrift {
            dt,
            h,
            hm,
            rigid,
            implicit,
            tilting: self.body.tilt.is_some(),
            q: self.q(),
            qd: self.qdot(),
            off: &self.body.off,
            sizes,
        };
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
            slot[0] = slider_chunk(&k, x, v, f, x0, ids);
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
            slot[0] = substrate_chunk(dt, h, hm_b, sizes, x, v, f, &sub_x0[a..], &sub_ids[a..]);
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

    /// The implicit mount's step ([`super::mount::Mount::step`]) of the z network; no-op
    /// without the implicit mount.
    pub(crate) fn mount_step(&mut self) {
        if let Some(mt) = self.mount.as_ref() {
            mt.step(
                self.dt,
                &self.body,
                &self.params,
                &self.idx,
                &mut self.state,
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{DampingFrame, SimParams};
    use crate::system::SystemSpec;

    /// The implicit mount step (`mount.rs`) in the engine's sequence. One slider sphere on its
    /// k_z spring under the light control layer (locked mount): the sphere carries a constant
    /// upward contact-like force F, the layer the load W = F. The
    /// relative coordinate x = z − Z is then a damped oscillator around F/k_z,
    /// `ẍ = −ω²(x − F/k_z) − ẋ/τ`, ω² = k_z(1/m_c + 1/m_s) (absolute damping frame). Steps `n`
    /// of the engine's sequence (contact half kick, mount step, contact half kick) at `dt`
    /// and returns `(t, x, ẋ)` after each, with ω and F/k_z.
    fn one_sphere(dt: f64, tau: f64, n: usize, implicit: bool) -> (Vec<(f64, f64, f64)>, f64, f64) {
        let scene = surrogate::Scene::preset("square-tri").unwrap();
        let spec = SystemSpec {
            substrate: Vec::new(),
            slider_sites: vec![[0.0, 0.0]],
            slider_z: vec![1e-6],
            control_z: 1e-6,
            slider_sphere_radius: scene.sphere_radius,
            substrate_sphere_radius: scene.sphere_radius,
            slider_radii: None,
            substrate_radii: None,
            slider_material: scene.material,
            substrate_material: scene.material,
            tilt_stiffness: None,
            disc: None,
            substrate_size: None,
            scene: None,
        };
        let force = 1e-6;
        let params = SimParams {
            protocol: crate::ProtocolParams {
                load: force,
                ..Default::default()
            },
            mount: crate::MountParams {
                implicit_mount: implicit,
                ..Default::default()
            },
            numerics: crate::NumericsParams {
                damping_time: tau,
                damping_frame: DampingFrame::Absolute,
                dt: Some(dt),
                ..Default::default()
            },
            ..SimParams::default()
        };
        let model = crate::contact_model(&scene, &params, None);
        let mut sim = Sim::new(spec, model, params, dt, dt).unwrap();
        let m_s = sim.body.m_s;
        let (kz, mc) = (sim.params.mount.k_slider_z, sim.body.mz);
        let omega = (kz * (1.0 / mc + 1.0 / m_s)).sqrt();
        let h = 0.5 * dt;
        let mut out = Vec::new();
        for k in 0..n {
            sim.state.act.sl_f[0][2] = force;
            if implicit {
                sim.mount_step();
                sim.state.act.sl_v[0][2] += h * force / m_s;
            } else {
                // velocity-Verlet on the same two bodies, for contrast
                let s = &mut sim.state;
                let fz = |s: &crate::system::State| {
                    let sp = kz * (s.cl_x[2] - s.act.sl_x[0][2]);
                    (
                        sp + force - m_s * s.act.sl_v[0][2] / tau,
                        -sp - force - mc * s.cl_v[2] / tau,
                    )
                };
                let (f1, f2) = fz(s);
                s.act.sl_v[0][2] += h * f1 / m_s;
                s.cl_v[2] += h * f2 / mc;
                s.act.sl_x[0][2] += dt * s.act.sl_v[0][2];
                s.cl_x[2] += dt * s.cl_v[2];
                let (f1, f2) = fz(s);
                s.act.sl_v[0][2] += h * f1 / m_s;
                s.cl_v[2] += h * f2 / mc;
            }
            let s = &sim.state;
            let x = s.act.sl_x[0][2] - s.cl_x[2];
            let v = s.act.sl_v[0][2] - s.cl_v[2];
            out.push(((k + 1) as f64 * dt, x, v));
        }
        (out, omega, force / kz)
    }

    /// At 10× the explicit limit (ω·dt = 20): the static deflection is F/k_z (after the ringing
    /// has decayed) to `(dt/2τ)²`, and the ringing's amplitude `√((x − x*)² + ẋ²/ω²)` decays as
    /// the analytic `x*·e^{−t/2τ}` (down to 0.22 x*) within 5 % (the trapezoidal map mistimes a mode it cannot
    /// resolve, but keeps its energy, and the damping is exact); velocity-Verlet blows up.
    #[test]
    fn one_sphere_at_ten_times_the_explicit_limit_matches_the_analytic_response() {
        let probe = one_sphere(1e-12, 1.0, 1, true);
        let omega = probe.1;
        let dt = 10.0 * 2.0 / omega;
        // decay: τ = 100 ns, 300 ns (450 steps)
        let tau = 100e-9;
        let (run, _, xs) = one_sphere(dt, tau, 450, true);
        let mut worst: f64 = 0.0;
        for &(t, x, v) in run.iter().skip(50) {
            let amp = ((x - xs).powi(2) + (v / omega).powi(2)).sqrt();
            let want = xs * (-t / (2.0 * tau)).exp();
            worst = worst.max((amp / want - 1.0).abs());
        }
        eprintln!("ringing amplitude vs the analytic decay: worst {worst:.4}");
        assert!(
            worst < 0.05,
            "ringing amplitude off the analytic decay by {worst}"
        );
        let t_end = run.last().unwrap().0;
        assert!(
            (-t_end / (2.0 * tau)).exp() < 0.3,
            "too short to see the decay"
        );
        // statics: 40 τ; the split of the damping shifts the rest point by ~(dt/2τ)²/2
        // (3·10⁻⁸ at the study's τ = 1 µs and contact-limited step)
        let (run, _, xs) = one_sphere(dt, tau, 6000, true);
        let (_, x, _) = *run.last().unwrap();
        let bound = (0.5 * dt / tau).powi(2);
        eprintln!(
            "static deflection / (F/k_z) − 1 = {:e} (bound {bound:e})",
            x / xs - 1.0
        );
        assert!(
            (x / xs - 1.0).abs() < bound,
            "static deflection {x} vs F/k_z {xs}"
        );
        let x_prev = run[run.len() - 2].1;
        assert!(
            (x - x_prev).abs() < bound * xs,
            "not at rest: {x_prev} → {x}"
        );
        // the explicit scheme at this step
        let (run, _, xs) = one_sphere(dt, tau, 50, false);
        let x = run.last().unwrap().1;
        assert!(
            x.is_nan() || x.abs() >= 1e3 * xs,
            "velocity-Verlet stayed bounded at ω·dt = 20: {x}"
        );
    }
}
