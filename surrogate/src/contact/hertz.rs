//! The Hertz law of two elastic spheres.

use crate::scene::Material;
use serde::{Deserialize, Serialize};

/// Hertz contact of two spheres with effective radius `R_eff` and effective modulus `E*` (SI).
///
/// With overlap δ (m):
/// - normal force `F = (4/3) E* √R_eff δ^{3/2}` (N),
/// - contact radius `a = √(R_eff δ)` (m),
/// - maximum pressure `p0 = 3F / (2π a²) = (2E*/π) √(δ / R_eff)` (Pa),
/// - normal stiffness `dF/dδ = 2 E* √(R_eff δ)` (N/m).
///
/// Every method costs O(1) (one `sqrt`, or one `cbrt` for the inverses).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Hertz {
    /// Effective modulus E* (Pa).
    pub e_star: f64,
    /// Effective radius R_eff (m).
    pub r_eff: f64,
}

impl Hertz {
    /// Two equal spheres of radius `r` (m) and the same material: `R_eff = r/2`,
    /// `E* = E / (2(1 − ν²))`.
    pub fn equal_spheres(r: f64, m: &Material) -> Self {
        Hertz {
            e_star: m.e_star(),
            r_eff: 0.5 * r,
        }
    }

    /// Two spheres of radii `r1`, `r2` (m) and the same material: `1/R_eff = 1/r1 + 1/r2`,
    /// `E* = E / (2(1 − ν²))`.
    pub fn spheres(r1: f64, r2: f64, m: &Material) -> Self {
        Hertz {
            e_star: m.e_star(),
            r_eff: r1 * r2 / (r1 + r2),
        }
    }

    /// `(4/3) E* √R_eff`, the prefactor `k` of `F = k δ^{3/2}` (N/m^{3/2}).
    #[inline]
    pub fn k(&self) -> f64 {
        4.0 / 3.0 * self.e_star * self.r_eff.sqrt()
    }

    /// Normal force (N) at overlap `delta` (m); 0 for `delta ≤ 0`.
    #[inline]
    pub fn force(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            0.0
        } else {
            self.k() * delta * delta.sqrt()
        }
    }

    /// Normal stiffness dF/dδ (N/m) at overlap `delta` (m); 0 for `delta ≤ 0`.
    #[inline]
    pub fn stiffness(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            0.0
        } else {
            2.0 * self.e_star * (self.r_eff * delta).sqrt()
        }
    }

    /// Contact radius `a` (m) at overlap `delta` (m).
    #[inline]
    pub fn contact_radius(&self, delta: f64) -> f64 {
        (self.r_eff * delta.max(0.0)).sqrt()
    }

    /// Maximum contact pressure p0 (Pa) at overlap `delta` (m).
    #[inline]
    pub fn p0(&self, delta: f64) -> f64 {
        2.0 * self.e_star / std::f64::consts::PI * (delta.max(0.0) / self.r_eff).sqrt()
    }

    /// Overlap (m) that carries normal force `f` (N): `δ = (F/k)^{2/3}`.
    #[inline]
    pub fn overlap_for_force(&self, f: f64) -> f64 {
        if f <= 0.0 {
            0.0
        } else {
            (f / self.k()).powf(2.0 / 3.0)
        }
    }

    /// Contact radius `a` (m) at which the maximum pressure is `p0` (Pa): `a = π p0 R_eff / (2E*)`.
    #[inline]
    pub fn contact_radius_for_p0(&self, p0: f64) -> f64 {
        std::f64::consts::PI * p0 * self.r_eff / (2.0 * self.e_star)
    }

    /// Overlap δ (m) at which the maximum pressure is `p0` (Pa): `δ = a² / R_eff` with `a` of
    /// [`Hertz::contact_radius_for_p0`].
    #[inline]
    pub fn overlap_for_p0(&self, p0: f64) -> f64 {
        let a = self.contact_radius_for_p0(p0);
        a * a / self.r_eff
    }

    /// Maximum pressure p0 (Pa) of a contact carrying normal force `f` (N):
    /// `p0 = (6 F E*² / (π³ R_eff²))^{1/3}`.
    #[inline]
    pub fn p0_for_force(&self, f: f64) -> f64 {
        let pi = std::f64::consts::PI;
        (6.0 * f.max(0.0) * self.e_star * self.e_star / (pi * pi * pi * self.r_eff * self.r_eff))
            .cbrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn study() -> Hertz {
        Hertz::equal_spheres(1.5e-6, &Material::default())
    }

    #[test]
    fn closed_forms_agree() {
        let h = study();
        for &d in &[1e-12, 1e-10, 3e-9, 5e-8] {
            let f = h.force(d);
            let a = h.contact_radius(d);
            let p_from_f = 3.0 * f / (2.0 * std::f64::consts::PI * a * a);
            assert!((p_from_f - h.p0(d)).abs() < 1e-12 * h.p0(d));
            assert!((h.p0_for_force(f) - h.p0(d)).abs() < 1e-12 * h.p0(d));
            assert!((h.overlap_for_force(f) - d).abs() < 1e-12 * d);
            assert!((h.overlap_for_p0(h.p0(d)) - d).abs() < 1e-12 * d);
            assert!((h.contact_radius_for_p0(h.p0(d)) - a).abs() < 1e-12 * a);
            let e = 1e-6 * d;
            let num = (h.force(d + e) - h.force(d - e)) / (2.0 * e);
            assert!((num - h.stiffness(d)).abs() < 1e-6 * h.stiffness(d));
        }
        assert_eq!(h.force(-1e-9), 0.0);
        assert_eq!(h.force(0.0), 0.0);
    }

    #[test]
    fn study_reference_pressure() {
        // 3.86 mN shared by 3505 on-top contacts → p0 ≈ 1.05 GPa (docs/physics.md).
        let p = study().p0_for_force(3.86e-3 / 3505.0);
        assert!((p / 1e9 - 1.05).abs() < 0.02 * 1.05, "{p}");
    }
}
