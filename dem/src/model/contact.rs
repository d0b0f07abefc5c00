//! [`ContactModel`]: normal + tangential + friction law of a slider–substrate sphere pair.

use super::{
    Friction, FrictionLaw, HertzNormal, Mindlin, MindlinForce, MindlinRescale, NormalModel,
    TangentialModel,
};
use crate::params::Tangential;

/// Result of evaluating one pair (SI).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairOut {
    /// Force on the first body (slider sphere) (N); the second gets its negative.
    pub force: [f64; 3],
    /// Overlap δ (m) when touching; when apart a negative gap measure `(R² − r²)/(2R)` (m),
    /// `R = R1 + R2`, which is below `R − r`.
    pub delta: f64,
    /// Maximum Hertz pressure p0 (Pa) (0 when not touching).
    pub p0: f64,
    /// Whether the contact's coating has failed (p0 above the friction law's threshold).
    pub failed: bool,
}

/// The pair contact model. `radius_sum` = R1 + R2 (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactModel {
    /// Normal sub-model.
    pub normal: HertzNormal,
    /// Tangential sub-model (its stiffness law and damping).
    pub tangential: Mindlin,
    /// Its history: displacement ([`Mindlin`]) or force ([`MindlinForce`]).
    pub history: Tangential,
    /// Friction law μ(p0).
    pub friction: Friction,
    /// Sum of the two radii (m).
    pub radius_sum: f64,
}

/// Effective mass (kg) of a pair of masses `m1`, `m2`: `m1 m2/(m1 + m2)`, and exactly `m1/2`
/// when they are equal (so one sphere size keeps the one-size arithmetic bit for bit).
#[inline]
pub fn reduced_mass(m1: f64, m2: f64) -> f64 {
    if m1 == m2 {
        0.5 * m1
    } else {
        m1 * m2 / (m1 + m2)
    }
}

impl ContactModel {
    /// Evaluates the pair with centre difference `d = x1 − x2` (m), relative velocity
    /// `v = v1 − v2` (m/s), tangential history `xi` (updated in place; reset when apart),
    /// pair effective mass `m_eff` (kg) and step `dt` (s). Cost O(1), ~3 sqrt. Always inlined:
    /// the force pass calls it from its one-size and its per-sphere-size loops.
    #[inline(always)]
    pub fn pair(
        &self,
        d: [f64; 3],
        v: [f64; 3],
        xi: &mut [f64; 3],
        m_eff: f64,
        dt: f64,
    ) -> PairOut {
        let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        let rs = self.radius_sum;
        if r2 >= rs * rs {
            // apart: no square root needed; a negative gap measure suffices
            *xi = [0.0; 3];
            return PairOut {
                delta: (rs * rs - r2) * (0.5 / rs),
                ..Default::default()
            };
        }
        let dist = r2.sqrt();
        let delta = rs - dist;
        let inv = 1.0 / dist;
        let n = [d[0] * inv, d[1] * inv, d[2] * inv];
        let vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
        let nf = self.normal.force(delta, -vn, m_eff);
        let (fnorm, p0) = (nf.force, nf.p0);
        let mu = self.friction.mu(p0);
        let vt = [v[0] - vn * n[0], v[1] - vn * n[1], v[2] - vn * n[2]];
        let ft = match self.history {
            Tangential::Mindlin => {
                self.tangential
                    .force(xi, n, vt, nf.radius, mu * fnorm, m_eff, dt)
            }
            Tangential::MindlinForce => MindlinForce {
                spring: self.tangential,
            }
            .force(xi, n, vt, nf.radius, mu * fnorm, m_eff, dt),
            Tangential::MindlinRescale => {
                // the previous step's separation d − v·dt gives the previous contact radius
                let dp = [d[0] - v[0] * dt, d[1] - v[1] * dt, d[2] - v[2] * dt];
                let delta_prev = rs - (dp[0] * dp[0] + dp[1] * dp[1] + dp[2] * dp[2]).sqrt();
                let a_prev = if delta_prev > 0.0 {
                    self.normal.contact_radius(delta_prev)
                } else {
                    0.0
                };
                MindlinRescale {
                    spring: self.tangential,
                }
                .force(xi, n, vt, nf.radius, a_prev, mu * fnorm, m_eff, dt)
            }
        };
        PairOut {
            force: [
                fnorm * n[0] + ft[0],
                fnorm * n[1] + ft[1],
                fnorm * n[2] + ft[2],
            ],
            delta,
            p0,
            failed: self.friction.failed(p0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Constant, Mindlin};
    use surrogate::contact::Hertz;
    use surrogate::Material;

    /// The `history` switch reaches the pair: a contact sheared while stuck, then unloaded
    /// (overlap halved) without sliding, keeps its tangential force with `MindlinForce` and
    /// loses part of it with `Mindlin` (whose force follows the contact radius) and more with
    /// `MindlinRescale` (whose displacement follows it too).
    #[test]
    fn the_history_switch_selects_the_tangential_sub_model() {
        let r = 1.5e-6;
        let mat = Material::default();
        let model = |history| ContactModel {
            normal: HertzNormal {
                hertz: Hertz::equal_spheres(r, &mat),
                gamma_n: 0.0,
            },
            tangential: Mindlin::equal_spheres(mat.youngs, mat.poisson, 0.0),
            history,
            friction: Friction::Constant(Constant { mu: 10.0 }),
            radius_sum: 2.0 * r,
        };
        // `moving`: the unloading step comes with the normal velocity that makes it (the
        // rescale reads the previous radius from d − v·dt)
        let shear_with = |history, moving: bool| {
            let m = model(history);
            let mut xi = [0.0; 3];
            let (dt, m_eff) = (1e-10, 1e-14);
            let d0 = 2.0 * r - 20e-9;
            let mut f = [0.0; 3];
            for _ in 0..100 {
                f = m
                    .pair([0.0, 0.0, d0], [1e-2, 0.0, 0.0], &mut xi, m_eff, dt)
                    .force;
            }
            let loaded = f[0];
            let d1 = 2.0 * r - 10e-9;
            let v = [0.0, 0.0, if moving { (d1 - d0) / dt } else { 0.0 }];
            let unloaded = m.pair([0.0, 0.0, d1], v, &mut xi, m_eff, dt).force[0];
            (loaded, unloaded)
        };
        let shear = |history| shear_with(history, false);
        let (a0, a1) = shear(Tangential::Mindlin);
        let (b0, b1) = shear(Tangential::MindlinForce);
        assert!(a0 < 0.0 && (a0 / b0 - 1.0).abs() < 1e-9, "{a0} vs {b0}");
        assert!(
            (b1 / b0 - 1.0).abs() < 1e-9,
            "mindlin-force kept {b1} of {b0}"
        );
        // a ∝ √δ: the displacement form keeps 1/√2 of its force
        assert!(
            (a1 / a0 - 0.5f64.sqrt()).abs() < 1e-6,
            "mindlin kept {a1} of {a0}"
        );
        // the rescale also scales ξ by a/a_prev = 1/√2 on unloading: half the force is left
        let (c0, c1) = shear_with(Tangential::MindlinRescale, true);
        let (d0, d1) = shear_with(Tangential::Mindlin, true);
        assert!((c0 / a0 - 1.0).abs() < 1e-9, "{c0} vs {a0}");
        assert!(
            (c1 / c0 - 0.5).abs() < 1e-6,
            "mindlin-rescale kept {c1} of {c0}"
        );
        assert!((d1 / d0 - 0.5f64.sqrt()).abs() < 1e-6, "{d1} of {d0}");
    }

    /// The pair's effective mass: exactly m/2 for equal masses (the one-size arithmetic), and
    /// m1 m2/(m1 + m2), symmetric, between min/2 and min, otherwise.
    #[test]
    fn reduced_mass_of_equal_and_unequal_spheres() {
        let m = Material::default().sphere_mass(1.5e-6);
        assert_eq!(super::reduced_mass(m, m).to_bits(), (0.5 * m).to_bits());
        let mb = Material::default().sphere_mass(1e-6);
        let r = super::reduced_mass(m, mb);
        assert_eq!(r, super::reduced_mass(mb, m));
        assert!((1.0 / r - (1.0 / m + 1.0 / mb)).abs() < 1e-12 / r);
        assert!(r > 0.5 * mb && r < mb);
    }
}
