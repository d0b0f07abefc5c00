//! [`ContactBatch`]: touching pairs evaluated together, lane by lane, with the arithmetic of
//! [`ContactModel::pair`] for the default history ([`crate::params::Tangential::Mindlin`]).

use super::mindlin::rotate_history_lanes;
use super::{ContactModel, Friction, PairOut};

/// Pairs one batch holds.
pub const BATCH: usize = 32;

/// Up to [`BATCH`] touching pairs (`r² < (R1 + R2)²`) in structure-of-arrays form, evaluated
/// by [`ContactBatch::eval`]: Hertz normal force with damping, the pressure-switched μ and the
/// Mindlin history spring capped by μF_n, the same IEEE operations in the same order as
/// [`ContactModel::pair`] with [`super::Mindlin`] history, so the same bits. The branches of
/// the scalar law (history rotation, slip) become selects, so the loop runs 4 pairs at a
/// time with AVX2 where the CPU has it (checked once per process; no FMA), else 2. Cost O(n),
/// six square roots and seven divisions a pair, the slip ones computed for every lane.
/// Why: `docs/validation/dem-engine.md`, "The contact law in lanes".
#[derive(Debug, Clone)]
pub struct ContactBatch {
    n: usize,
    /// The caller's index of each pair.
    pub slot: [u32; BATCH],
    d: [[f64; BATCH]; 3],
    v: [[f64; BATCH]; 3],
    xi: [[f64; BATCH]; 3],
    r2: [f64; BATCH],
    rs: [f64; BATCH],
    r_eff: [f64; BATCH],
    m_eff: [f64; BATCH],
    f: [[f64; BATCH]; 3],
    delta: [f64; BATCH],
    p0: [f64; BATCH],
}

impl Default for ContactBatch {
    fn default() -> Self {
        ContactBatch {
            n: 0,
            slot: [0; BATCH],
            d: [[0.0; BATCH]; 3],
            v: [[0.0; BATCH]; 3],
            xi: [[0.0; BATCH]; 3],
            r2: [0.0; BATCH],
            rs: [0.0; BATCH],
            r_eff: [0.0; BATCH],
            m_eff: [0.0; BATCH],
            f: [[0.0; BATCH]; 3],
            delta: [0.0; BATCH],
            p0: [0.0; BATCH],
        }
    }
}

/// One pair's inputs to [`ContactBatch::push`] (SI): centre difference `d = x1 − x2` (m) with
/// `|d|² = r2` below `rs²`, relative velocity `v` (m/s), history `xi` (m), contact distance
/// `rs` = R1 + R2 (m), `r_eff` (m) and reduced mass `m_eff` (kg).
#[derive(Debug, Clone, Copy)]
pub struct BatchPair {
    /// The caller's index of the pair.
    pub slot: u32,
    /// Centre difference (m).
    pub d: [f64; 3],
    /// Its squared length (m²).
    pub r2: f64,
    /// Relative velocity (m/s).
    pub v: [f64; 3],
    /// Tangential history ξ (m).
    pub xi: [f64; 3],
    /// Contact distance R1 + R2 (m).
    pub rs: f64,
    /// Effective radius (m).
    pub r_eff: f64,
    /// Reduced mass (kg).
    pub m_eff: f64,
}

impl ContactBatch {
    /// Pairs held.
    #[inline]
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether it holds no pair.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Whether `k` more pairs fit.
    #[inline]
    pub fn fits(&self, k: usize) -> bool {
        self.n + k <= BATCH
    }

    /// Adds a touching pair (panics when full). O(1).
    #[inline]
    pub fn push(&mut self, p: BatchPair) {
        let j = self.n;
        self.slot[j] = p.slot;
        for k in 0..3 {
            self.d[k][j] = p.d[k];
            self.v[k][j] = p.v[k];
            self.xi[k][j] = p.xi[k];
        }
        self.r2[j] = p.r2;
        self.rs[j] = p.rs;
        self.r_eff[j] = p.r_eff;
        self.m_eff[j] = p.m_eff;
        self.n = j + 1;
    }

    /// Empties the batch. O(1).
    #[inline]
    pub fn clear(&mut self) {
        self.n = 0;
    }

    /// Pair `j`'s result and updated history, valid after [`ContactBatch::eval`].
    #[inline]
    pub fn result(&self, j: usize, model: &ContactModel) -> (PairOut, [f64; 3]) {
        use super::FrictionLaw;
        let p0 = self.p0[j];
        (
            PairOut {
                force: [self.f[0][j], self.f[1][j], self.f[2][j]],
                delta: self.delta[j],
                p0,
                failed: model.friction.failed(p0),
            },
            [self.xi[0][j], self.xi[1][j], self.xi[2][j]],
        )
    }

    /// Evaluates every pair held with `model` (its Hertz constants E*, γ_n, its Mindlin G*,
    /// γ_t, its friction law; each pair's own `rs`, `r_eff`, `m_eff`) and step `dt` (s),
    /// updating the histories. The history sub-model is Mindlin whatever `model.history` says:
    /// the caller batches only that one.
    pub fn eval(&mut self, model: &ContactModel, dt: f64) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, the one feature `eval_avx2` is compiled for.
            unsafe { self.eval_avx2(model, dt) };
            return;
        }
        self.eval_here(model, dt);
    }

    /// [`ContactBatch::eval`] compiled for AVX2 (no FMA: the same roundings as without).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn eval_avx2(&mut self, model: &ContactModel, dt: f64) {
        self.eval_here(model, dt);
    }

    /// The loop of [`ContactBatch::eval`], for whichever target features its caller has.
    #[inline(always)]
    fn eval_here(&mut self, model: &ContactModel, dt: f64) {
        let (e_star, gamma_n) = (model.normal.hertz.e_star, model.normal.gamma_n);
        let (g_star, gamma_t) = (model.tangential.g_star, model.tangential.gamma_t);
        // the friction law as a switch (a constant μ: a threshold nothing exceeds)
        let (p_crit, mu1, mu2) = match model.friction {
            Friction::PressureSwitched(s) => (s.p_crit, s.mu1, s.mu2),
            Friction::Constant(c) => (f64::INFINITY, c.mu, c.mu),
        };
        let n = self.n;
        let [d0, d1, d2] = &self.d;
        let [v0, v1, v2] = &self.v;
        let (d0, d1, d2) = (&d0[..n], &d1[..n], &d2[..n]);
        let (v0, v1, v2) = (&v0[..n], &v1[..n], &v2[..n]);
        let (r2s, rss) = (&self.r2[..n], &self.rs[..n]);
        let (r_effs, m_effs) = (&self.r_eff[..n], &self.m_eff[..n]);
        let [x0, x1, x2] = &mut self.xi;
        let (x0, x1, x2) = (&mut x0[..n], &mut x1[..n], &mut x2[..n]);
        let [f0, f1, f2] = &mut self.f;
        let (f0, f1, f2) = (&mut f0[..n], &mut f1[..n], &mut f2[..n]);
        let (deltas, p0s) = (&mut self.delta[..n], &mut self.p0[..n]);
        for j in 0..n {
            // ContactModel::pair, touching branch, in its order (same bits)
            let (r_eff, m_eff) = (r_effs[j], m_effs[j]);
            let dist = r2s[j].sqrt();
            let delta = rss[j] - dist;
            let inv = 1.0 / dist;
            let nv = [d0[j] * inv, d1[j] * inv, d2[j] * inv];
            let v = [v0[j], v1[j], v2[j]];
            let vn = v[0] * nv[0] + v[1] * nv[1] + v[2] * nv[2];
            // HertzNormal::force(delta, −vn, m_eff)
            let a = (r_eff * delta).sqrt();
            let fe = 4.0 / 3.0 * e_star * a * delta;
            let s_n = 2.0 * e_star * a;
            let fd = gamma_n * (m_eff * s_n).sqrt() * -vn;
            let p0 = 2.0 * e_star / std::f64::consts::PI * a / r_eff;
            let fnorm = (fe + fd).max(0.0);
            let mu = if p0 > p_crit { mu2 } else { mu1 };
            let vt = [v[0] - vn * nv[0], v[1] - vn * nv[1], v[2] - vn * nv[2]];
            // Mindlin::force(xi, n, vt, a, μ F_n, m_eff, dt): rotate the history into the
            // tangent plane keeping its magnitude (when it has one)
            let mut xi = rotate_history_lanes([x0[j], x1[j], x2[j]], nv);
            for k in 0..3 {
                xi[k] += vt[k] * dt;
            }
            let kt = 8.0 * g_star * a;
            let eta = gamma_t * (m_eff * kt).sqrt();
            let mut f = [0.0; 3];
            for k in 0..3 {
                f[k] = -kt * xi[k] - eta * vt[k];
            }
            let cap = mu * fnorm;
            let ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
            // slip: scale the force to the cap, reset the history to match
            let fm = ff.sqrt();
            let sc = if fm > 0.0 { cap / fm } else { 0.0 };
            let slip = ff > cap * cap;
            for k in 0..3 {
                let fs = f[k] * sc;
                let xs = if kt > 0.0 {
                    -(fs + eta * vt[k]) / kt
                } else {
                    0.0
                };
                if slip {
                    f[k] = fs;
                    xi[k] = xs;
                }
            }
            x0[j] = xi[0];
            x1[j] = xi[1];
            x2[j] = xi[2];
            f0[j] = fnorm * nv[0] + f[0];
            f1[j] = fnorm * nv[1] + f[1];
            f2[j] = fnorm * nv[2] + f[2];
            deltas[j] = delta;
            p0s[j] = p0;
        }
    }
}

/// Shared by the tests of the batch and of the slider pass.
#[cfg(test)]
pub(crate) mod test_support {
    use crate::model::{ContactModel, Friction, HertzNormal, Mindlin, PressureSwitched};
    use crate::params::Tangential;
    use surrogate::contact::Hertz;
    use surrogate::Material;

    /// The study's pair law (100 GPa, ν 0.3, μ 0.01 → 0.5 above 4 GPa) for two spheres of
    /// radius `r` (m), with damping γ_n 0.3, γ_t 0.2.
    pub(crate) fn study_model(r: f64) -> ContactModel {
        let mat = Material::default();
        ContactModel {
            normal: HertzNormal {
                hertz: Hertz::equal_spheres(r, &mat),
                gamma_n: 0.3,
            },
            tangential: Mindlin::equal_spheres(mat.youngs, mat.poisson, 0.2),
            history: Tangential::Mindlin,
            friction: Friction::PressureSwitched(PressureSwitched {
                p_crit: 4.0e9,
                mu1: 0.01,
                mu2: 0.5,
            }),
            radius_sum: 2.0 * r,
        }
    }

    /// A small deterministic generator (xorshift64).
    pub(crate) struct Rng(pub u64);

    impl Rng {
        /// Uniform in [0, 1).
        pub(crate) fn unit(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }

        /// Uniform in [−1, 1).
        pub(crate) fn sym(&mut self) -> f64 {
            2.0 * self.unit() - 1.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::test_support::{study_model, Rng};
    use super::*;
    use crate::model::Constant;

    /// The batch gives the scalar law's bits, output and history, for touching pairs that
    /// stick and slip, with and without history, per-pair sizes, both friction laws, in
    /// batches of every length up to [`BATCH`].
    #[test]
    fn the_batch_gives_the_scalar_laws_bits() {
        let r = 1.5e-6;
        let m = 1.0e-14;
        let base = study_model(r);
        let constant = ContactModel {
            friction: Friction::Constant(Constant { mu: 0.1 }),
            ..base
        };
        let dt = 4.0e-10;
        let mut rng = Rng(0x9e3779b97f4a7c15);
        let (mut slips, mut sticks, mut fresh, mut failed) = (0, 0, 0, 0);
        for model in [base, constant] {
            for len in 1..=BATCH {
                let mut batch = ContactBatch::default();
                let mut want = Vec::new();
                for j in 0..len {
                    // per-pair sizes on odd pairs
                    let (rs, r_eff, m_eff) = if j % 2 == 1 {
                        let (a, b) = (r * (1.0 + 0.05 * rng.sym()), r);
                        (a + b, a * b / (a + b), 0.4 * m)
                    } else {
                        (model.radius_sum, model.normal.hertz.r_eff, 0.5 * m)
                    };
                    // overlaps 0.1–40 nm; lateral offsets up to 0.3 µm
                    let delta = 1e-10 + 4e-8 * rng.unit();
                    let lat = [3e-7 * rng.sym(), 3e-7 * rng.sym()];
                    let z = ((rs - delta).powi(2) - lat[0] * lat[0] - lat[1] * lat[1]).sqrt();
                    let d = [lat[0], lat[1], z];
                    let v = [1e-2 * rng.sym(), 1e-2 * rng.sym(), 1e-4 * rng.sym()];
                    let xi = match j % 3 {
                        0 => [0.0; 3],
                        1 => [1e-10 * rng.sym(), 1e-10 * rng.sym(), 1e-11 * rng.sym()],
                        _ => [1e-8 * rng.sym(), 1e-8 * rng.sym(), 0.0],
                    };
                    let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    assert!(r2 < rs * rs);
                    batch.push(BatchPair {
                        slot: j as u32,
                        d,
                        r2,
                        v,
                        xi,
                        rs,
                        r_eff,
                        m_eff,
                    });
                    let mut one = model;
                    one.radius_sum = rs;
                    one.normal.hertz.r_eff = r_eff;
                    let mut h = xi;
                    let out = one.pair(d, v, &mut h, m_eff, dt);
                    want.push((out, h, xi));
                }
                // the portable loop (CPUs without AVX2) gives the same bits
                let mut portable = batch.clone();
                portable.eval_here(&model, dt);
                batch.eval(&model, dt);
                for (j, (out, h, xi0)) in want.into_iter().enumerate() {
                    let (got, gh) = batch.result(j, &model);
                    let (pg, ph) = portable.result(j, &model);
                    assert_eq!((pg, ph.map(f64::to_bits)), (got, gh.map(f64::to_bits)));
                    assert_eq!(batch.slot[j], j as u32);
                    for k in 0..3 {
                        assert_eq!(got.force[k].to_bits(), out.force[k].to_bits(), "{j}");
                        assert_eq!(gh[k].to_bits(), h[k].to_bits(), "{j}");
                    }
                    assert_eq!(got.delta.to_bits(), out.delta.to_bits());
                    assert_eq!(got.p0.to_bits(), out.p0.to_bits());
                    assert_eq!(got.failed, out.failed);
                    // a sticking pair's history keeps its length up to |v_t|·dt (< 1e-11 m
                    // here); a slipping one is reset to μF_n/k_t's length
                    let len = |x: [f64; 3]| (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
                    if (len(h) - len(xi0)).abs() > 1e-11 {
                        slips += 1;
                    } else {
                        sticks += 1;
                    }
                    fresh += usize::from(xi0 == [0.0; 3]);
                    failed += usize::from(out.failed);
                    assert!(out.force.iter().all(|x| x.is_finite()));
                }
            }
        }
        // the cases above were all met
        assert!(slips > 20 && sticks > 20, "{slips} slips, {sticks} sticks");
        assert!(fresh > 20 && failed > 5, "{fresh} fresh, {failed} failed");
    }
}
