//! [`HertzNormal`]: Hertz normal force with Tsuji-type viscoelastic damping.

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
    fn force(&self, delta: f64, delta_dot: f64, m_eff: f64) -> (f64, f64, f64) {
        let h = &self.hertz;
        let sq = delta.sqrt();
        let fe = h.k() * delta * sq;
        let s_n = 2.0 * h.e_star * (h.r_eff * delta).sqrt();
        let fd = self.gamma_n * (m_eff * s_n).sqrt() * delta_dot;
        let p0 = 2.0 * h.e_star / std::f64::consts::PI * (delta / h.r_eff).sqrt();
        ((fe + fd).max(0.0), s_n, p0)
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
