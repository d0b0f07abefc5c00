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
        // Rotate the history into the current tangent plane, keeping its magnitude.
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
