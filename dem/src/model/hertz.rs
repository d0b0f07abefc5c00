//! [`HertzNormal`]: Hertz normal force with Tsuji-type viscoelastic damping.

use super::normal::NormalOut;
use super::NormalModel;
use surrogate::contact::Hertz;

/// Hertz law `F_e = (4/3)E*√R_eff δ^{3/2}` plus viscoelastic damping
/// `F_d = γ_n √(m_eff S_n) δ̇` with `S_n = 2E*√(R_eff δ)` (∝ δ^{1/4}: the restitution
/// coefficient is velocity independent, `e = 1 − 1.7207 γ_n + O(γ_n²)`; the constant is
/// `2√(15/8)·π/5`, from integrating the dissipated power along the undamped Hertz orbit).
/// The total force is clamped at 0 (no adhesion).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzNormal {
    /// Hertz law of the pair (E*, R_eff).
    pub hertz: Hertz,
    /// Dimensionless damping γ_n.
    pub gamma_n: f64,
}

impl HertzNormal {
    /// Restitution coefficient of a head-on collision to first order in γ_n:
    /// `e ≈ 1 − 2√(15/8)·(π/5)·γ_n·√(m_eff/m_dyn)`, where `m_dyn` is the mass that actually
    /// moves in the normal direction (= m_eff for two free spheres).
    pub fn restitution_first_order(gamma_n: f64, m_eff_over_m_dyn: f64) -> f64 {
        1.0 - 2.0 * (15.0f64 / 8.0).sqrt() * std::f64::consts::PI / 5.0
            * gamma_n
            * m_eff_over_m_dyn.sqrt()
    }
}

impl NormalModel for HertzNormal {
    #[inline]
    fn force(&self, delta: f64, delta_dot: f64, m_eff: f64) -> NormalOut {
        // one square root for a = √(R_eff δ): F_e = (4/3)E*·a·δ, S_n = 2E*·a,
        // p0 = (2E*/π)·a/R_eff
        let h = &self.hertz;
        let a = (h.r_eff * delta).sqrt();
        let fe = 4.0 / 3.0 * h.e_star * a * delta;
        let s_n = 2.0 * h.e_star * a;
        let fd = self.gamma_n * (m_eff * s_n).sqrt() * delta_dot;
        let p0 = 2.0 * h.e_star / std::f64::consts::PI * a / h.r_eff;
        NormalOut {
            force: (fe + fd).max(0.0),
            stiffness: s_n,
            p0,
            radius: a,
        }
    }
    #[inline]
    fn contact_radius(&self, delta: f64) -> f64 {
        (self.hertz.r_eff * delta.max(0.0)).sqrt()
    }
    fn energy(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            0.0
        } else {
            0.4 * self.hertz.k() * delta * delta * delta.sqrt()
        }
    }
}
