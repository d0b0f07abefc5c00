//! The force passes of a step, each fused with the second half kick of the particles it
//! computes: slider spheres with their pairs (one pass over slider chunks, returning each
//! chunk's reaction on the control layer), then the substrate spheres, then the control layer
//! and the common mode of the inactive slider spheres.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, g_of, mat_vec, Sizes};
use super::kernel::{kick, kick_hm, spring_stretch, Index};
use super::sim::Sim;
use super::team::{Exec, Shards};
use crate::model::{BatchPair, ContactBatch, ContactModel, PairOut, BATCH};
use crate::params::DampingFrame;
use crate::params::SimParams;
use crate::params::Tangential;
use crate::system::PairHist;
use crate::system::SystemSpec;

/// Read-only inputs of the slider pass.
struct SliderPass<'a> {
    model: &'a ContactModel,
    ids: &'a [u32],
    x: &'a [[f64; 3]],
    off: &'a [[f64; 2]],
    pstart: &'a [u32],
    pair_b: &'a [u32],
    sub_ids: &'a [u32],
    sub_x: &'a [[f64; 2]],
    sub_v: &'a [[f64; 2]],
    sub_h: &'a [f64],
    cx: [f64; 3],
    q: [f64; 3],
    qd: [f64; 3],
    vref: [f64; 2],
    rel: bool,
    tilting: bool,
    rigid: bool,
    /// z springs and damping in the implicit mount step: z gets the contact force only.
    implicit: bool,
    kxy: f64,
    kz: f64,
    m_s: f64,
    m_eff: f64,
    inv_tau: f64,
    dt: f64,
    hm: f64,
    /// Half step h (s), for each sphere's own `h/m_i` with per-sphere sizes.
    h: f64,
    /// Each sphere's own radius, mass and anchor offset; `None`: one size per body.
    sizes: Option<&'a Sizes>,
    chunk: usize,
}

impl SliderPass<'_> {
    /// Forces and second half kick of slider chunk `c` (its spheres' `v`, `f` and its pairs'
    /// `hist`, `out`); returns the chunk's reaction on the control layer
    /// `[F_x, F_y, Q_z, Q_tx, Q_ty]` and the largest p0 of its pairs (Pa). With the default
    /// history the touching pairs are evaluated in [`ContactBatch`]es (the same bits as one
    /// at a time), each sphere finished once its pairs are.
    fn chunk<const SIZED: bool>(
        &self,
        c: usize,
        v: &mut [[f64; 3]],
        f: &mut [[f64; 3]],
        hist: &mut [PairHist],
        out: &mut [PairOut],
    ) -> [f64; 6] {
        let a0 = c * self.chunk;
        let pbase = self.pstart[a0] as usize;
        let batched = self.model.history == Tangential::Mindlin;
        let mut batch = ContactBatch::default();
        let mut part = [0.0f64; 6];
        // spheres 0..done are finished
        let mut done = 0;
        for l in 0..v.len() {
            let a = a0 + l;
            let pairs = self.pstart[a] as usize..self.pstart[a + 1] as usize;
            let in_batch = batched && pairs.len() <= BATCH;
            if in_batch && !batch.fits(pairs.len()) {
                self.flush(&mut batch, hist, out);
                for k in done..l {
                    self.finish::<SIZED>(a0 + k, &mut v[k], &mut f[k], hist, out, pbase, &mut part);
                }
                done = l;
            }
            let gi = self.ids[a] as usize;
            let x = self.x[a];
            let hm = self.mass::<SIZED>(gi).1;
            // Implicit mount: v[2] still lacks this step's second contact half kick; the
            // contact law sees it predicted with the last contact force (at rest: 0, as
            // velocity-Verlet's half-step velocity).
            let vz = if self.implicit {
                v[l][2] + hm * f[l][2]
            } else {
                v[l][2]
            };
            for p in pairs {
                let b = self.pair_b[p] as usize;
                let xb = self.sub_x[b];
                let vb = self.sub_v[b];
                let d = [
                    x[0] - xb[0],
                    x[1] - xb[1],
                    x[2] - self.sub_h[self.sub_ids[b] as usize],
                ];
                let vr = [v[l][0] - vb[0], v[l][1] - vb[1], vz];
                // the pair's own contact distance, R_eff and reduced mass with sizes
                let mut model = *self.model;
                let m_eff = if SIZED {
                    let (rs, r_eff, m_eff) = self.sizes.unwrap().pair(gi, self.sub_ids[b] as usize);
                    model.radius_sum = rs;
                    model.normal.hertz.r_eff = r_eff;
                    m_eff
                } else {
                    self.m_eff
                };
                let hp = &mut hist[p - pbase];
                let rs = model.radius_sum;
                let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                if in_batch && r2 < rs * rs {
                    batch.push(BatchPair {
                        slot: (p - pbase) as u32,
                        d,
                        r2,
                        v: vr,
                        xi: hp.xi,
                        rs,
                        r_eff: model.normal.hertz.r_eff,
                        m_eff,
                    });
                } else {
                    out[p - pbase] = model.pair(d, vr, &mut hp.xi, m_eff, self.dt);
                }
            }
        }
        self.flush(&mut batch, hist, out);
        for k in done..v.len() {
            self.finish::<SIZED>(a0 + k, &mut v[k], &mut f[k], hist, out, pbase, &mut part);
        }
        part
    }

    /// Evaluates the pairs held in `batch` and writes their results and histories back into
    /// the chunk's `out` and `hist`; empties it.
    fn flush(&self, batch: &mut ContactBatch, hist: &mut [PairHist], out: &mut [PairOut]) {
        if batch.is_empty() {
            return;
        }
        batch.eval(self.model, self.dt);
        for j in 0..batch.len() {
            let q = batch.slot[j] as usize;
            let (o, xi) = batch.result(j, self.model);
            out[q] = o;
            hist[q].xi = xi;
        }
        batch.clear();
    }

    /// Mass (kg) and `h/m` (s/kg) of slider sphere `gi`: its own with per-sphere sizes.
    #[inline(always)]
    fn mass<const SIZED: bool>(&self, gi: usize) -> (f64, f64) {
        if SIZED {
            let mi = self.sizes.unwrap().sl_m[gi];
            (mi, self.h / mi)
        } else {
            (self.m_s, self.hm)
        }
    }

    /// Sums the evaluated pairs of active slider sphere `a` (in pair order) and adds its
    /// springs and damping; its second half kick into `v`, its force into `f`, its reaction
    /// and largest p0 into `part`.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn finish<const SIZED: bool>(
        &self,
        a: usize,
        v: &mut [f64; 3],
        f: &mut [f64; 3],
        hist: &mut [PairHist],
        out: &[PairOut],
        pbase: usize,
        part: &mut [f64; 6],
    ) {
        let gi = self.ids[a] as usize;
        let o = self.off[gi];
        let x = self.x[a];
        let (m, hm) = self.mass::<SIZED>(gi);
        let mut acc = [0.0; 3];
        for p in self.pstart[a] as usize..self.pstart[a + 1] as usize {
            let r = &out[p - pbase];
            hist[p - pbase].ever_failed |= r.failed;
            part[5] = part[5].max(r.p0);
            acc[0] += r.force[0];
            acc[1] += r.force[1];
            acc[2] += r.force[2];
        }
        let g = g_of(o);
        if self.rigid {
            part[2] += acc[2];
            if self.tilting {
                part[3] += acc[2] * g[1];
                part[4] += acc[2] * g[2];
            }
        }
        let it = self.inv_tau;
        let sx = self.kxy * (self.cx[0] + o[0] - x[0]);
        let sy = self.kxy * (self.cx[1] + o[1] - x[1]);
        acc[0] += sx - m * (v[0] - self.vref[0]) * it;
        acc[1] += sy - m * (v[1] - self.vref[1]) * it;
        part[0] -= sx;
        part[1] -= sy;
        kick_hm(&mut v[0], acc[0], hm);
        kick_hm(&mut v[1], acc[1], hm);
        if self.implicit {
            kick_hm(&mut v[2], acc[2], hm);
        } else if !self.rigid {
            let (az, vaz) = if self.tilting {
                (dot3(g, self.q), dot3(g, self.qd))
            } else {
                (self.q[0], self.qd[0])
            };
            let az = if SIZED {
                az + self.sizes.unwrap().sl_dz[gi]
            } else {
                az
            };
            let vrz = if self.rel { vaz } else { 0.0 };
            let sz = self.kz * (az - x[2]);
            acc[2] += sz - m * (v[2] - vrz) * it;
            part[2] -= sz;
            if self.tilting {
                part[3] -= sz * g[1];
                part[4] -= sz * g[2];
            }
            kick_hm(&mut v[2], acc[2], hm);
        }
        *f = acc;
    }

    /// Runs the `nc` chunks over the slider spheres' `v`, `f` and their pairs' `hist`, `out`
    /// (on the team of `exec` when `par`), writing chunk `c`'s reaction into `parts[c]`.
    #[allow(clippy::too_many_arguments)]
    fn run(
        &self,
        exec: Exec,
        par: bool,
        nc: usize,
        v: &mut [[f64; 3]],
        f: &mut [[f64; 3]],
        hist: &mut [PairHist],
        out: &mut [PairOut],
        parts: &mut [[f64; 6]],
    ) {
        let n = v.len();
        let (v, f) = (Shards::new(v), Shards::new(f));
        let (hist, out, parts) = (Shards::new(hist), Shards::new(out), Shards::new(parts));
        exec.pass(par, [nc, 0], &|c| {
            let (a0, a1) = (c * self.chunk, ((c + 1) * self.chunk).min(n));
            let (p0, p1) = (self.pstart[a0] as usize, self.pstart[a1] as usize);
            // SAFETY: chunk c alone takes slider spheres a0..a1, their pairs p0..p1 (the pair
            // ranges of consecutive spheres are consecutive) and slot c; the pass runs each
            // chunk once.
            let (v, f, hist, out, part) = unsafe {
                (
                    v.range(a0, a1),
                    f.range(a0, a1),
                    hist.range(p0, p1),
                    out.range(p0, p1),
                    parts.range(c, c + 1),
                )
            };
            // one copy of the loop per case: the one-size path stays the one-size code
            part[0] = if self.sizes.is_some() {
                self.chunk::<true>(c, v, f, hist, out)
            } else {
                self.chunk::<false>(c, v, f, hist, out)
            };
        });
    }
}

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
            kt: params.k_substrate_xy,
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
        let p = &self.params;
        let rel = p.damping_frame == DampingFrame::Relative;
        let inv_tau = self.inv_tau();
        let (q, qd) = (self.q(), self.qdot());
        let s = &mut self.state;
        let ch = self.idx.chunks;
        let n_sl = s.act.sl.len();
        // 1. slider spheres and their pairs
        let parts = &mut self.idx.parts;
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
                rigid: p.rigid_z,
                implicit: self.mount.is_some(),
                kxy: p.k_slider_xy,
                kz: p.k_slider_z,
                m_s: self.body.m_s,
                m_eff: self.body.m_eff,
                inv_tau,
                dt: self.dt,
                hm: h / self.body.m_s,
                h,
                sizes: self.body.sizes.as_ref(),
                chunk: ch.sl,
            };
            if n_sl > 0 {
                let nc = ch.n_sl_chunks(n_sl);
                pass.run(exec, ch.par, nc, sl_v, sl_f, hist, out, &mut parts[..nc]);
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
        // 2. substrate spheres (deferred when pipelined: see `Sim::run_steps`)
        if !defer_substrate {
            self.substrate_forces(exec, h);
        }
        let p = &self.params;
        let s = &mut self.state;
        s.p0_peak = s.p0_peak.max(peak);
        // 3. common mode of the inactive slider spheres
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
                c.fu[k] = -p.k_slider_xy * c.u[k] - m * (c.v[k] - vref[k]) * inv_tau;
                kick(&mut c.v[k], c.fu[k], h, m);
                c.fd[k] = -p.k_slider_xy * c.d[k] - m * c.dv[k] * inv_tau;
                kick(&mut c.dv[k], c.fd[k], h, m);
            }
            if implicit {
                // the z mode is advanced by the implicit mount step
                c.fw = [0.0; 3];
                c.fdz = [0.0; 3];
            } else if !p.rigid_z {
                let sref = if rel { qd } else { [0.0; 3] };
                for k in 0..3 {
                    c.fw[k] = -p.k_slider_z * c.w[k] - m * (c.s[k] - sref[k]) * inv_tau;
                    kick(&mut c.s[k], c.fw[k], h, m);
                    c.fdz[k] = -p.k_slider_z * c.dz[k] - m * c.dzv[k] * inv_tau;
                    kick(&mut c.dzv[k], c.fdz[k], h, m);
                }
            }
        }
        // 4. control layer: reactions, load, mount, damping, pulling spring; second half kick
        let n_in = self.idx.n_in as f64;
        let mut f = [r[0], r[1], r[2]];
        let mut qt = [r[3], r[4]];
        if self.idx.n_in > 0 {
            // reaction of the free slider spheres: the common mode (N_in·k·u, k_z·G_in·w)
            // plus the sum of their ringing deviations (k·Σδ, k_z·Σδz g)
            let c = &s.common;
            f[0] += n_in * p.k_slider_xy * c.u[0] + p.k_slider_xy * c.d[0];
            f[1] += n_in * p.k_slider_xy * c.u[1] + p.k_slider_xy * c.d[1];
            if !p.rigid_z && !implicit {
                let gw = mat_vec(&self.idx.g_in, c.w);
                f[2] += p.k_slider_z * (gw[0] + c.dz[0]);
                qt[0] += p.k_slider_z * (gw[1] + c.dz[1]);
                qt[1] += p.k_slider_z * (gw[2] + c.dz[2]);
            }
        }
        f[2] -= p.load;
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
            f[0] += p.k0 * d[0];
            f[1] += p.k0 * d[1];
        }
        s.cl_f = f;
        s.tilt_f = qt;
        if h != 0.0 {
            self.kick_control_second(h);
        }
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
