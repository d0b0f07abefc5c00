//! [`Mindlin`]: Mindlin no-slip tangential spring with history, Coulomb cap and viscous damping.

use super::TangentialModel;

/// Tangential stiffness `k_t = 8 G* a` (Mindlin, no-slip), `G* = E / (4(2−ν)(1+ν))` for two
/// equal spheres; force `F_t = −k_t ξ − γ_t √(m_eff k_t) v_t`, capped at `μ F_n`; on slip the
/// history is reset to `ξ = −(F_t + η_t v_t)/k_t` (LAMMPS `tangential mindlin` convention).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mindlin {
    /// Effective shear modulus G* (Pa).
    pub g_star: f64,
    /// Dimensionless tangential damping γ_t.
    pub gamma_t: f64,
}

impl Mindlin {
    /// Two equal spheres of Young's modulus `e` (Pa) and Poisson ratio `nu`.
    pub fn equal_spheres(e: f64, nu: f64, gamma_t: f64) -> Self {
        Mindlin {
            g_star: e / (4.0 * (2.0 - nu) * (1.0 + nu)),
            gamma_t,
        }
    }

    /// A sphere of material `a` against one of `b`: `G*` of
    /// [`surrogate::Material::g_star_with`] (`1/G* = (2 − ν1)/G1 + (2 − ν2)/G2`), equal to
    /// [`Mindlin::equal_spheres`] bit for bit for one material.
    pub fn between(a: &surrogate::Material, b: &surrogate::Material, gamma_t: f64) -> Self {
        Mindlin {
            g_star: a.g_star_with(b),
            gamma_t,
        }
    }
}

#[inline]
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The tangential history `xi` rotated into the tangent plane of the unit normal `n`, keeping
/// its magnitude: `r = ξ − (ξ·n) n`, then `r·|ξ|/|r|` (unchanged for `ξ = 0`; `r` itself where
/// `ξ ∥ n`). The one rotation of the Mindlin springs ([`Mindlin`], [`super::MindlinForce`]);
/// [`rotate_history_lanes`] is its branch-free twin (same bits). O(1).
#[inline]
pub(crate) fn rotate_history(xi: &mut [f64; 3], n: [f64; 3]) {
    let m0 = dot(*xi, *xi);
    if m0 > 0.0 {
        let xn = dot(*xi, n);
        for k in 0..3 {
            xi[k] -= xn * n[k];
        }
        let m1 = dot(*xi, *xi);
        if m1 > 0.0 {
            let s = (m0 / m1).sqrt();
            for v in xi.iter_mut() {
                *v *= s;
            }
        }
    }
}

/// [`rotate_history`] with its branches as selects (every quantity computed, then chosen), for
/// the contact law in lanes ([`super::ContactBatch`]): the same IEEE operations in the same
/// order, so the same bits (`rotate_history_lanes_gives_the_scalar_bits`). O(1).
#[inline(always)]
pub(crate) fn rotate_history_lanes(xi: [f64; 3], n: [f64; 3]) -> [f64; 3] {
    let m0 = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
    let xn = xi[0] * n[0] + xi[1] * n[1] + xi[2] * n[2];
    let r = [xi[0] - xn * n[0], xi[1] - xn * n[1], xi[2] - xn * n[2]];
    let m1 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    let s = (m0 / m1).sqrt();
    if m0 > 0.0 {
        if m1 > 0.0 {
            [r[0] * s, r[1] * s, r[2] * s]
        } else {
            r
        }
    } else {
        xi
    }
}

impl TangentialModel for Mindlin {
    #[inline]
    fn force(
        &self,
        xi: &mut [f64; 3],
        n: [f64; 3],
        v_t: [f64; 3],
        a: f64,
        cap: f64,
        m_eff: f64,
        dt: f64,
    ) -> [f64; 3] {
        rotate_history(xi, n);
        for k in 0..3 {
            xi[k] += v_t[k] * dt;
        }
        let kt = self.stiffness(a);
        let eta = self.gamma_t * (m_eff * kt).sqrt();
        let mut f = [0.0; 3];
        for k in 0..3 {
            f[k] = -kt * xi[k] - eta * v_t[k];
        }
        let f2 = dot(f, f);
        if f2 > cap * cap {
            let fm = f2.sqrt();
            let s = if fm > 0.0 { cap / fm } else { 0.0 };
            for k in 0..3 {
                f[k] *= s;
                xi[k] = if kt > 0.0 {
                    -(f[k] + eta * v_t[k]) / kt
                } else {
                    0.0
                };
            }
        }
        f
    }
    #[inline]
    fn stiffness(&self, a: f64) -> f64 {
        8.0 * self.g_star * a
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::contact_batch::test_support::Rng;

    fn bits(v: [f64; 3]) -> [u64; 3] {
        v.map(f64::to_bits)
    }

    /// The lanes rotation gives the scalar one's bits for any history and unit normal, also a
    /// zero history, one along the normal (nothing left in the plane), subnormal ones, and one
    /// whose in-plane part underflows.
    #[test]
    fn rotate_history_lanes_gives_the_scalar_bits() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for case in 0..200_000 {
            let n = [rng.sym(), rng.sym(), rng.sym()];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            if len < 1e-3 {
                continue;
            }
            let n = n.map(|v| v / len);
            let x = [rng.sym(), rng.sym(), rng.sym()].map(|v| v * 1e-6);
            let xi = match case % 5 {
                0 => [0.0; 3],
                1 => n.map(|v| v * x[0]),
                2 => x.map(|v| v * 1e-300),
                3 => [n[0] * x[0] + 1e-30, n[1] * x[0], n[2] * x[0]],
                _ => x,
            };
            let mut scalar = xi;
            rotate_history(&mut scalar, n);
            assert_eq!(
                bits(rotate_history_lanes(xi, n)),
                bits(scalar),
                "ξ {xi:?}, n {n:?}"
            );
        }
    }
}
