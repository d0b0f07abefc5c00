//! [`Columns`]: the tilt Newton's pairs held as columns (one array per field), so that the Hertz
//! law of every pair at a state is one branch-free loop the compiler vectorises, and the sums are
//! then taken pair by pair in list order. The loop does what [`super::law::pair_response`] does,
//! operation for operation, so each pair's response and the sums keep their bits
//! (`docs/validation/path-solve.md`, "Sixth round").

use super::law::{BodyPair, Law};

/// A working set of pairs with one law (the scene's `k`, `d`), as columns: the lever
/// `g = [g₀, g₁]`, touch height `c` (m), lateral distance² `r²` (m²) and touch gap `u_t` (m)
/// of each pair ([`BodyPair`]), and the response of each at the last state evaluated.
#[derive(Debug, Default)]
pub(crate) struct Columns {
    g0: Vec<f64>,
    g1: Vec<f64>,
    c: Vec<f64>,
    r2: Vec<f64>,
    ut: Vec<f64>,
    /// Vertical force F_z (N) of each pair at the last state.
    pub fz: Vec<f64>,
    /// Stiffness s = −dF_z/du (N/m) of each pair at the last state.
    pub s: Vec<f64>,
    /// Energy Φ (J) of each pair at the last state.
    pub phi: Vec<f64>,
}

impl Columns {
    /// Holds `tp`'s pairs (their own laws are not kept: for the scene's one law only). O(P),
    /// no allocation once the columns have grown.
    pub fn fill<L: Law>(&mut self, tp: &[BodyPair<L>]) {
        debug_assert!(!L::SIZED, "columns hold pairs of the scene's one law");
        let n = tp.len();
        for v in [
            &mut self.g0,
            &mut self.g1,
            &mut self.c,
            &mut self.r2,
            &mut self.ut,
        ] {
            v.clear();
        }
        self.g0.extend(tp.iter().map(|p| p.g[0]));
        self.g1.extend(tp.iter().map(|p| p.g[1]));
        self.c.extend(tp.iter().map(|p| p.c));
        self.r2.extend(tp.iter().map(|p| p.r2));
        self.ut.extend(tp.iter().map(|p| p.ut));
        for v in [&mut self.fz, &mut self.s, &mut self.phi] {
            v.resize(n, 0.0);
        }
    }

    /// Number of pairs held.
    pub fn len(&self) -> usize {
        self.c.len()
    }

    /// Lever `[g₀, g₁]` of pair `j`.
    #[inline]
    pub fn g(&self, j: usize) -> [f64; 2] {
        [self.g0[j], self.g1[j]]
    }

    /// Fills `fz`, `s`, `phi` with every pair's response at `q = [ζ, L·t_x, L·t_y]`: offset
    /// `dz = ζ + q₁ g₀ + q₂ g₁ − c`, then [`super::law::pair_response`] with prefactor `k`
    /// (N/m^{3/2}) and contact distance `two_r` (m), zero where `dz ≥ 0` or `u_t + dz ≤ 0`.
    /// O(P), a few flops and two square roots per pair, branch-free: 4 pairs at a time with
    /// AVX2 where the CPU has it (checked once per process; the same IEEE operations, so the
    /// same bits), else 2.
    pub fn respond(&mut self, k: f64, two_r: f64, q: [f64; 3]) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, the one feature `respond_avx2` is compiled for.
            unsafe { self.respond_avx2(k, two_r, q) };
            return;
        }
        self.respond_here(k, two_r, q);
    }

    /// [`Columns::respond`] compiled for AVX2 (no FMA: the same roundings as without).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn respond_avx2(&mut self, k: f64, two_r: f64, q: [f64; 3]) {
        self.respond_here(k, two_r, q);
    }

    /// The loop of [`Columns::respond`], for whichever target features its caller has.
    #[inline(always)]
    fn respond_here(&mut self, k: f64, two_r: f64, q: [f64; 3]) {
        let n = self.c.len();
        let (g0, g1, c, r2, ut) = (
            &self.g0[..n],
            &self.g1[..n],
            &self.c[..n],
            &self.r2[..n],
            &self.ut[..n],
        );
        let (fz, s, phi) = (&mut self.fz[..n], &mut self.s[..n], &mut self.phi[..n]);
        for j in 0..n {
            // the operations of `pair_response`, in its order (same bits); inactive lanes
            // compute NaN or garbage and are replaced by zero. Written out here rather than
            // calling a shared helper: with the call inlined, LLVM no longer vectorises the loop
            // (measured: scalar square roots, 7 % slower per path sample); the property test
            // below keeps the two equal bit for bit.
            let dz = q[0] + q[1] * g0[j] + q[2] * g1[j] - c[j];
            let u = ut[j] + dz;
            let active = !(dz >= 0.0 || u <= 0.0);
            let dd = (r2[j] + u * u).sqrt();
            let delta = -dz * (ut[j] + u) / (two_r + dd);
            let sd = delta.sqrt();
            let fnorm = k * delta * sd;
            let inv = 1.0 / dd;
            let f = fnorm * u * inv;
            let sj = 1.5 * k * sd * u * u * inv * inv - fnorm * r2[j] * inv * inv * inv;
            let p = 0.4 * fnorm * delta;
            fz[j] = if active { f } else { 0.0 };
            s[j] = if active { sj } else { 0.0 };
            phi[j] = if active { p } else { 0.0 };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::law::{pair_response, Shared};
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Every pair's response from the columns (the vectorised pass, AVX2 where the CPU has
        /// it, and the plain loop) is `pair_response`'s bit for bit: touching, grazing and
        /// separated pairs, levers of both signs, tilted states.
        #[test]
        fn columns_respond_as_pair_response(
            pairs in proptest::collection::vec(
                (-1.0f64..1.0, -1.0f64..1.0, -40e-9f64..40e-9, 0.0f64..8.9e-12),
                1..40,
            ),
            q in (-30e-9f64..30e-9, -5e-9f64..5e-9, -5e-9f64..5e-9),
        ) {
            let (k, two_r) = (2.1e10, 3e-6);
            let tp: Vec<BodyPair<Shared>> = pairs
                .iter()
                .map(|&(g0, g1, c, r2)| BodyPair {
                    g: [g0, g1],
                    r2,
                    ut: (two_r * two_r - r2).sqrt(),
                    c,
                    law: Shared,
                })
                .collect();
            let q = [q.0, q.1, q.2];
            let mut cols = Columns::default();
            cols.fill(&tp);
            cols.respond(k, two_r, q);
            let fast = (cols.fz.clone(), cols.s.clone(), cols.phi.clone());
            cols.respond_here(k, two_r, q);
            for (j, p) in tp.iter().enumerate() {
                let dz = q[0] + q[1] * p.g[0] + q[2] * p.g[1] - p.c;
                let r = pair_response(k, two_r, p.r2, p.ut, dz);
                for (got, want) in [
                    (fast.0[j], r.fz),
                    (fast.1[j], r.s),
                    (fast.2[j], r.phi),
                    (cols.fz[j], r.fz),
                    (cols.s[j], r.s),
                    (cols.phi[j], r.phi),
                ] {
                    prop_assert_eq!(got.to_bits(), want.to_bits(), "pair {} at dz {:e}", j, dz);
                }
            }
        }
    }
}
