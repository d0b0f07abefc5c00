//! The slider force pass of a step: each active slider sphere's pairs (touching ones in
//! [`ContactBatch`]es), fused with its springs, damping and second half kick; one pass over
//! slider chunks, each returning its reaction on the control layer.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, g_of, Sizes};
use super::kernel::kick_hm;
use super::team::{Exec, Shards};
use crate::model::{BatchPair, ContactBatch, ContactModel, PairOut, BATCH};
use crate::system::PairHist;

/// Read-only inputs of the slider pass.
pub(super) struct SliderPass<'a> {
    pub(super) model: &'a ContactModel,
    pub(super) ids: &'a [u32],
    pub(super) x: &'a [[f64; 3]],
    pub(super) off: &'a [[f64; 2]],
    pub(super) pstart: &'a [u32],
    pub(super) pair_b: &'a [u32],
    pub(super) sub_ids: &'a [u32],
    pub(super) sub_x: &'a [[f64; 2]],
    pub(super) sub_v: &'a [[f64; 2]],
    pub(super) sub_h: &'a [f64],
    pub(super) cx: [f64; 3],
    pub(super) q: [f64; 3],
    pub(super) qd: [f64; 3],
    pub(super) vref: [f64; 2],
    pub(super) rel: bool,
    pub(super) tilting: bool,
    pub(super) rigid: bool,
    /// z springs and damping in the implicit mount step: z gets the contact force only.
    pub(super) implicit: bool,
    pub(super) kxy: f64,
    pub(super) kz: f64,
    pub(super) m_s: f64,
    pub(super) m_eff: f64,
    pub(super) inv_tau: f64,
    pub(super) dt: f64,
    pub(super) hm: f64,
    /// Half step h (s), for each sphere's own `h/m_i` with per-sphere sizes.
    pub(super) h: f64,
    /// Each sphere's own radius, mass and anchor offset; `None`: one size per body.
    pub(super) sizes: Option<&'a Sizes>,
    pub(super) chunk: usize,
    /// Evaluate touching pairs in [`ContactBatch`]es (only for the default history, whose
    /// law the batch computes; the same bits as one pair at a time).
    pub(super) batched: bool,
}

impl SliderPass<'_> {
    /// Forces and second half kick of slider chunk `c` (its spheres' `v`, `f` and its pairs'
    /// `hist`, `out`); returns the chunk's reaction on the control layer
    /// `[F_x, F_y, Q_z, Q_tx, Q_ty]` and the largest p0 of its pairs (Pa). When `batched`
    /// the touching pairs are evaluated in [`ContactBatch`]es (the same bits as one at a
    /// time), each sphere finished once its pairs are.
    fn chunk<const SIZED: bool>(
        &self,
        c: usize,
        v: &mut [[f64; 3]],
        f: &mut [[f64; 3]],
        hist: &mut [PairHist],
        out: &mut [PairOut],
        batch: &mut ContactBatch,
    ) -> [f64; 6] {
        let a0 = c * self.chunk;
        let pbase = self.pstart[a0] as usize;
        let mut part = [0.0f64; 6];
        // spheres 0..done are finished
        let mut done = 0;
        for l in 0..v.len() {
            let a = a0 + l;
            let pairs = self.pstart[a] as usize..self.pstart[a + 1] as usize;
            let in_batch = self.batched && pairs.len() <= BATCH;
            if in_batch && !batch.fits(pairs.len()) {
                self.flush(batch, hist, out);
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
                // the pair's own contact distance, R_eff and reduced mass with sizes (a copy of
                // the model only then)
                let sized;
                let (model, m_eff) = if SIZED {
                    let (rs, r_eff, m_eff) = self.sizes.unwrap().pair(gi, self.sub_ids[b] as usize);
                    let mut own = *self.model;
                    own.radius_sum = rs;
                    own.normal.hertz.r_eff = r_eff;
                    sized = own;
                    (&sized, m_eff)
                } else {
                    (self.model, self.m_eff)
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
        self.flush(batch, hist, out);
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
    pub(super) fn run(
        &self,
        exec: Exec,
        par: bool,
        nc: usize,
        v: &mut [[f64; 3]],
        f: &mut [[f64; 3]],
        hist: &mut [PairHist],
        out: &mut [PairOut],
        parts: &mut [[f64; 6]],
        batches: &mut [ContactBatch],
    ) {
        let n = v.len();
        let (v, f) = (Shards::new(v), Shards::new(f));
        let (hist, out, parts) = (Shards::new(hist), Shards::new(out), Shards::new(parts));
        let batches = Shards::new(batches);
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
            // SAFETY: slot c likewise
            let batch = unsafe { &mut batches.range(c, c + 1)[0] };
            // one copy of the loop per case: the one-size path stays the one-size code
            part[0] = if self.sizes.is_some() {
                self.chunk::<true>(c, v, f, hist, out, batch)
            } else {
                self.chunk::<false>(c, v, f, hist, out, batch)
            };
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::contact_batch::test_support::{study_model, Rng};

    /// The batched pass gives the one-pair pass's bits: velocities, forces, histories, pair
    /// results and the chunk's reaction, for 70 spheres with 1–3 pairs each (more touching
    /// pairs than one batch holds, some spheres with more pairs than fit in what is left),
    /// one size and per-sphere sizes, a rigid and a free z.
    #[test]
    fn batched_pairs_give_the_one_pair_bits() {
        let r = 1.5e-6;
        let model = study_model(r);
        let mut rng = Rng(0x2545f4914f6cdd1d);
        let mut unit = move || rng.unit();
        let n = 70;
        let (mut x, mut off, mut pstart) = (Vec::new(), Vec::new(), vec![0u32]);
        let (mut sub_x, mut sub_v, mut sub_h) = (Vec::new(), Vec::new(), Vec::new());
        let (mut v, mut f, mut hist) = (Vec::new(), Vec::new(), Vec::new());
        for i in 0..n {
            let xi = [1e-5 * i as f64, 2e-7 * unit(), 3.0e-6];
            x.push(xi);
            off.push([xi[0] - 3e-4, xi[1]]);
            v.push([
                1e-2 * (unit() - 0.5),
                1e-2 * (unit() - 0.5),
                1e-4 * (unit() - 0.5),
            ]);
            f.push([1e-6 * (unit() - 0.5), 1e-6 * (unit() - 0.5), 1e-5 * unit()]);
            let k = 1 + (unit() * 3.0) as usize;
            for _ in 0..k {
                // lateral offset up to 0.3 µm; gap from −30 nm (overlap) to +20 nm
                let lat = [3e-7 * (unit() - 0.5), 3e-7 * (unit() - 0.5)];
                let gap = -3e-8 + 5e-8 * unit();
                let h = xi[2] - ((2.0 * r + gap).powi(2) - lat[0].powi(2) - lat[1].powi(2)).sqrt();
                sub_x.push([xi[0] - lat[0], xi[1] - lat[1]]);
                sub_v.push([1e-3 * (unit() - 0.5), 1e-3 * (unit() - 0.5)]);
                sub_h.push(h);
                let xi0 = if unit() < 0.5 {
                    [0.0; 3]
                } else {
                    [1e-9 * (unit() - 0.5), 1e-9 * (unit() - 0.5), 0.0]
                };
                hist.push(PairHist {
                    xi: xi0,
                    ever_failed: false,
                });
            }
            pstart.push(sub_x.len() as u32);
        }
        let np = sub_x.len();
        let ids: Vec<u32> = (0..n as u32).collect();
        let pair_b: Vec<u32> = (0..np as u32).collect();
        let sub_ids = pair_b.clone();
        let sizes = Sizes {
            sl_r: (0..n).map(|i| r * (1.0 + 0.01 * (i % 3) as f64)).collect(),
            sl_m: (0..n)
                .map(|i| 1e-14 * (1.0 + 0.03 * (i % 3) as f64))
                .collect(),
            sl_dz: (0..n).map(|i| -0.01 * r * (i % 3) as f64).collect(),
            sub_r: (0..np).map(|j| r * (1.0 - 0.01 * (j % 2) as f64)).collect(),
            sub_m: (0..np)
                .map(|j| 1e-14 * (1.0 - 0.02 * (j % 2) as f64))
                .collect(),
        };
        let mut touching = 0;
        for case in 0..4 {
            let (sized, rigid) = (case % 2 == 1, case >= 2);
            let pass = |batched: bool| SliderPass {
                model: &model,
                ids: &ids,
                x: &x,
                off: &off,
                pstart: &pstart,
                pair_b: &pair_b,
                sub_ids: &sub_ids,
                sub_x: &sub_x,
                sub_v: &sub_v,
                sub_h: &sub_h,
                cx: [1e-7, -2e-7, 3.0e-6],
                q: [3.0e-6, 1e-4, -2e-4],
                qd: [1e-5, 1e-3, 2e-3],
                vref: [0.1, 0.0],
                rel: true,
                tilting: true,
                rigid,
                implicit: false,
                kxy: 50.0,
                kz: 5e3,
                m_s: 1e-14,
                m_eff: 0.5e-14,
                inv_tau: 1e5,
                dt: 4e-10,
                hm: 2e-10 / 1e-14,
                h: 2e-10,
                sizes: sized.then_some(&sizes),
                chunk: n,
                batched,
            };
            let run = |batched: bool| {
                let (mut v, mut f, mut hist) = (v.clone(), f.clone(), hist.clone());
                let mut out = vec![PairOut::default(); np];
                let mut batch = ContactBatch::default();
                let p = pass(batched);
                let part = if sized {
                    p.chunk::<true>(0, &mut v, &mut f, &mut hist, &mut out, &mut batch)
                } else {
                    p.chunk::<false>(0, &mut v, &mut f, &mut hist, &mut out, &mut batch)
                };
                let bits = |a: &[[f64; 3]]| -> Vec<u64> {
                    a.iter().flatten().map(|x| x.to_bits()).collect()
                };
                let hb: Vec<u64> = hist.iter().flat_map(|h| h.xi.map(f64::to_bits)).collect();
                let fl: Vec<bool> = hist.iter().map(|h| h.ever_failed).collect();
                (bits(&v), bits(&f), hb, fl, out, part.map(f64::to_bits))
            };
            let (a, b) = (run(true), run(false));
            touching = a.4.iter().filter(|o| o.p0 > 0.0).count();
            assert_eq!(a.0, b.0, "v, case {case}");
            assert_eq!(a.1, b.1, "f, case {case}");
            assert_eq!(a.2, b.2, "histories, case {case}");
            assert_eq!(a.3, b.3, "failed flags, case {case}");
            assert_eq!(a.4, b.4, "pair results, case {case}");
            assert_eq!(a.5, b.5, "reaction, case {case}");
        }
        // more touching pairs than one batch: the pass flushed mid-chunk
        assert!(touching > BATCH + 8, "{touching} touching pairs");
    }
}
