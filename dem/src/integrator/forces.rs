//! The force passes of a step, each fused with the second half kick of the particles it
//! computes: slider spheres with their pairs (`slider_pass.rs`), then the substrate spheres,
//! then the control layer and the common mode of the inactive slider spheres.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::mat_vec;
use super::kernel::{kick, kick_hm, spring_stretch, Index};
use super::sim::Sim;
use super::slider_pass::SliderPass;
use super::team::{Exec, Shards};
use crate::model::PairOut;
use crate::params::DampingFrame;
use crate::params::SimParams;
use crate::params::Tangential;
use crate::system::SystemSpec;

/// Read-only inputs of the substrate force pass (tether, damping, minus the pair forces).
pub(crate) struct SubstrateForce<'a> {
    sub_start: &'a [u32],
    sub_items: &'a [u32],
    sites: &'a [[f64; 3]],
    kt: f64,
    m: f64,
    inv_tau: f64,
    hm: f64,
    /// Half step h (s).
    h: f64,
    /// Each substrate sphere's own mass (kg) with per-sphere sizes.
    masses: Option<&'a [f64]>,
}

impl<'a> SubstrateForce<'a> {
    /// The pass with second half kick `h` (s) over the index `idx` of the active set.
    pub(crate) fn new(
        idx: &'a Index,
        spec: &'a SystemSpec,
        params: &SimParams,
        m: f64,
        masses: Option<&'a [f64]>,
        inv_tau: f64,
        h: f64,
    ) -> SubstrateForce<'a> {
        SubstrateForce {
            sub_start: &idx.sub_start,
            sub_items: &idx.sub_items,
            sites: &spec.substrate,
            kt: params.mount.k_substrate_xy,
            m,
            inv_tau,
            hm: h / m,
            h,
            masses,
        }
    }

    /// Force and second half kick of the dense substrate spheres `b0..b0 + v.len()` (ids, pair
    /// results: the dense arrays of the active set).
    #[inline]
    pub(crate) fn chunk_with(
        &self,
        b0: usize,
        ids: &[u32],
        out: &[PairOut],
        v: &mut [[f64; 2]],
        f: &mut [[f64; 2]],
        x: &[[f64; 2]],
    ) {
        match self.masses {
            None => self.chunk_sized::<false>(b0, ids, out, v, f, x),
            Some(_) => self.chunk_sized::<true>(b0, ids, out, v, f, x),
        }
    }

    /// [`SubstrateForce::chunk_with`] with each sphere's own mass (`SIZED`) or the body's.
    #[inline]
    fn chunk_sized<const SIZED: bool>(
        &self,
        b0: usize,
        ids: &[u32],
        out: &[PairOut],
        v: &mut [[f64; 2]],
        f: &mut [[f64; 2]],
        x: &[[f64; 2]],
    ) {
        let it = self.inv_tau;
        for (l, ((v, f), x)) in v.iter_mut().zip(f.iter_mut()).zip(x).enumerate() {
            let b = b0 + l;
            let (m, hm) = if SIZED {
                let mj = self.masses.unwrap()[ids[b] as usize];
                (mj, self.h / mj)
            } else {
                (self.m, self.hm)
            };
            let site = self.sites[ids[b] as usize];
            let mut acc = [
                self.kt * (site[0] - x[0]) - m * v[0] * it,
                self.kt * (site[1] - x[1]) - m * v[1] * it,
            ];
            for &pi in &self.sub_items[self.sub_start[b] as usize..self.sub_start[b + 1] as usize] {
                let o = &out[pi as usize];
                acc[0] -= o.force[0];
                acc[1] -= o.force[1];
            }
            kick_hm(&mut v[0], acc[0], hm);
            kick_hm(&mut v[1], acc[1], hm);
            *f = acc;
        }
    }
}

impl Sim {
    /// Every force from the current positions and half-step velocities, each particle's second
    /// half kick by `h` (0: forces only), the control layer's force and second half kick, and
    /// the common mode's. Updates the tangential histories by one step. With
    /// `defer_substrate` the substrate spheres' force and second half kick are left to the next
    /// step's fused first pass ([`Sim::kick_drift`]).
    pub(crate) fn forces(&mut self, exec: Exec, h: f64, defer_substrate: bool) {
        let rel = self.params.numerics.damping_frame == DampingFrame::Relative;
        let inv_tau = self.inv_tau();
        let (q, qd) = (self.q(), self.qdot());
        // 1. slider spheres and their pairs
        let (r, peak) = self.slider_forces(exec, h, rel, inv_tau, q, qd);
        // 2. substrate spheres (deferred when pipelined: see `Sim::run_steps`)
        if !defer_substrate {
            self.substrate_forces(exec, h);
        }
        self.state.p0_peak = self.state.p0_peak.max(peak);
        // 3. common mode of the inactive slider spheres
        self.common_mode_forces(h, rel, inv_tau, qd);
        // 4. control layer: reactions, load, mount, damping, pulling spring; second half kick
        self.control_forces(r, rel, inv_tau, qd);
        if h != 0.0 {
            self.kick_control_second(h);
        }
    }

    /// The slider spheres' forces with their pairs' and their second half kick by `h` (one
    /// pass over the slider chunks); the chunks' reactions on the control layer summed in chunk
    /// order (force x, y, z, tilt moments) and the peak pressure p0 (Pa).
    fn slider_forces(
        &mut self,
        exec: Exec,
        h: f64,
        rel: bool,
        inv_tau: f64,
        q: [f64; 3],
        qd: [f64; 3],
    ) -> ([f64; 5], f64) {
        let p = &self.params;
        let s = &mut self.state;
        let ch = self.idx.chunks;
        let n_sl = s.act.sl.len();
        // 1. slider spheres and their pairs
        let (parts, batches) = (&mut self.idx.parts, &mut self.idx.batches);
        {
            let crate::system::Active {
                sl,
                sl_x,
                sl_v,
                sl_f,
                sub,
                sub_x,
                sub_v,
                hist,
                out,
                ..
            } = &mut s.act;
            let pass = SliderPass {
                model: &self.model,
                ids: sl,
                x: sl_x,
                off: &self.body.off,
                pstart: &self.idx.sl_pair_start,
                pair_b: &self.idx.pair_b,
                sub_ids: sub,
                sub_x,
                sub_v,
                sub_h: &self.sub_h,
                cx: s.cl_x,
                q,
                qd,
                vref: if rel {
                    [s.cl_v[0], s.cl_v[1]]
                } else {
                    [0.0; 2]
                },
                rel,
                tilting: self.body.tilt.is_some(),
                rigid: p.mount.rigid_z,
                implicit: self.mount.is_some(),
                kxy: p.mount.k_slider_xy,
                kz: p.mount.k_slider_z,
                m_s: self.body.m_s,
                m_eff: self.body.m_eff,
                inv_tau,
                dt: self.dt,
                hm: h / self.body.m_s,
                h,
                sizes: self.body.sizes.as_ref(),
                chunk: ch.sl,
                batched: self.model.history == Tangential::Mindlin,
            };
            if n_sl > 0 {
                let nc = ch.n_sl_chunks(n_sl);
                let (parts, batches) = (&mut parts[..nc], &mut batches[..nc]);
                pass.run(exec, ch.par, nc, sl_v, sl_f, hist, out, parts, batches);
            }
        }
        let mut r = [0.0; 5];
        let mut peak = 0.0f64;
        for part in parts.iter().take(ch.n_sl_chunks(n_sl)) {
            for k in 0..5 {
                r[k] += part[k];
            }
            peak = peak.max(part[5]);
        }
        (r, peak)
    }

    /// The common mode of the inactive slider spheres: its forces and second half kick by `h`.
    fn common_mode_forces(&mut self, h: f64, rel: bool, inv_tau: f64, qd: [f64; 3]) {
        let p = &self.params;
        let s = &mut self.state;
        let m = self.body.m_s;
        let implicit = self.mount.is_some();
        {
            let c = &mut s.common;
            let vref = if rel {
                [s.cl_v[0], s.cl_v[1]]
            } else {
                [0.0; 2]
            };
            for k in 0..2 {
                c.fu[k] = -p.mount.k_slider_xy * c.u[k] - m * (c.v[k] - vref[k]) * inv_tau;
                kick(&mut c.v[k], c.fu[k], h, m);
                c.fd[k] = -p.mount.k_slider_xy * c.d[k] - m * c.dv[k] * inv_tau;
                kick(&mut c.dv[k], c.fd[k], h, m);
            }
            if implicit {
                // the z mode is advanced by the implicit mount step
                c.fw = [0.0; 3];
                c.fdz = [0.0; 3];
            } else if !p.mount.rigid_z {
                let sref = if rel { qd } else { [0.0; 3] };
                for k in 0..3 {
                    c.fw[k] = -p.mount.k_slider_z * c.w[k] - m * (c.s[k] - sref[k]) * inv_tau;
                    kick(&mut c.s[k], c.fw[k], h, m);
                    c.fdz[k] = -p.mount.k_slider_z * c.dz[k] - m * c.dzv[k] * inv_tau;
                    kick(&mut c.dzv[k], c.fdz[k], h, m);
                }
            }
        }
    }

    /// The control layer's force and tilt moments: the slider spheres' reactions `r`, the free
    /// ones', the load, the mount, the damping and the pulling spring.
    fn control_forces(&mut self, r: [f64; 5], rel: bool, inv_tau: f64, qd: [f64; 3]) {
        let p = &self.params;
        let s = &mut self.state;
        let implicit = self.mount.is_some();
        let n_in = self.idx.n_in as f64;
        let mut f = [r[0], r[1], r[2]];
        let mut qt = [r[3], r[4]];
        if self.idx.n_in > 0 {
            // reaction of the free slider spheres: the common mode (N_in·k·u, k_z·G_in·w)
            // plus the sum of their ringing deviations (k·Σδ, k_z·Σδz g)
            let c = &s.common;
            f[0] += n_in * p.mount.k_slider_xy * c.u[0] + p.mount.k_slider_xy * c.d[0];
            f[1] += n_in * p.mount.k_slider_xy * c.u[1] + p.mount.k_slider_xy * c.d[1];
            if !p.mount.rigid_z && !implicit {
                let gw = mat_vec(&self.idx.g_in, c.w);
                f[2] += p.mount.k_slider_z * (gw[0] + c.dz[0]);
                qt[0] += p.mount.k_slider_z * (gw[1] + c.dz[1]);
                qt[1] += p.mount.k_slider_z * (gw[2] + c.dz[2]);
            }
        }
        f[2] -= p.protocol.load;
        match &self.body.tilt {
            _ if implicit => {
                // Z and the tilts are advanced by the implicit mount step
                f[2] = 0.0;
                qt = [0.0; 2];
            }
            None => f[2] -= self.body.mz * s.cl_v[2] * inv_tau,
            Some(t) => {
                let mq = mat_vec(&t.m, qd);
                f[2] -= mq[0] * inv_tau;
                qt[0] -= mq[1] * inv_tau + t.k[0][0] * s.tilt[0] + t.k[0][1] * s.tilt[1];
                qt[1] -= mq[2] * inv_tau + t.k[1][0] * s.tilt[0] + t.k[1][1] * s.tilt[1];
            }
        }
        let vr = if rel { s.support_v } else { [0.0; 2] };
        f[0] -= self.body.m_cl * (s.cl_v[0] - vr[0]) * inv_tau;
        f[1] -= self.body.m_cl * (s.cl_v[1] - vr[1]) * inv_tau;
        if s.spring_on {
            let d = spring_stretch(p, s.support, s.cl_x);
            f[0] += p.protocol.k0 * d[0];
            f[1] += p.protocol.k0 * d[1];
        }
        s.cl_f = f;
        s.tilt_f = qt;
    }

    /// Force and second half kick (`h`) of the active substrate spheres (one pass).
    pub(crate) fn substrate_forces(&mut self, exec: Exec, h: f64) {
        let inv_tau = self.inv_tau();
        let ctx = SubstrateForce::new(
            &self.idx,
            &self.spec,
            &self.params,
            self.body.m_b,
            self.body.sizes.as_ref().map(|z| &z.sub_m[..]),
            inv_tau,
            h,
        );
        let ch = self.idx.chunks;
        let c = ch.sub;
        let crate::system::Active {
            sub,
            sub_x,
            sub_v,
            sub_f,
            out,
            ..
        } = &mut self.state.act;
        let (ids, out, x) = (&*sub, &*out, &*sub_x);
        let nc = x.len().div_ceil(c);
        let (v, f) = (Shards::new(sub_v), Shards::new(sub_f));
        exec.pass(ch.par, [0, nc], &|k| {
            let (a, b) = (k * c, ((k + 1) * c).min(x.len()));
            // SAFETY: chunk k alone takes substrate spheres a..b; the pass runs each chunk
            // once.
            let (v, f) = unsafe { (v.range(a, b), f.range(a, b)) };
            ctx.chunk_with(a, ids, out, v, f, &x[a..b]);
        });
    }

    /// Second half kick of the control layer (the same map as the first half kick).
    fn kick_control_second(&mut self, h: f64) {
        self.kick_control(h);
    }
}
