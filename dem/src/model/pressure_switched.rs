//! [`PressureSwitched`]: μ1 while p0 ≤ P_crit, μ2 once the coating has failed (p0 > P_crit).

use super::friction_law::FrictionLaw;
use surrogate::contact::{coating_failed, coating_mu};
use surrogate::Coating;

/// The study's coating law ([`surrogate::contact::coating_mu`]): `μ = μ1` for `p0 ≤ P_crit`,
/// `μ = μ2` for `p0 > P_crit` (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureSwitched {
    /// Critical pressure (Pa).
    pub p_crit: f64,
    /// μ of an intact contact.
    pub mu1: f64,
    /// μ of a failed contact.
    pub mu2: f64,
}

impl From<&Coating> for PressureSwitched {
    fn from(c: &Coating) -> Self {
        PressureSwitched {
            p_crit: c.p_crit,
            mu1: c.mu1,
            mu2: c.mu2,
        }
    }
}

impl FrictionLaw for PressureSwitched {
    #[inline]
    fn mu(&self, p0: f64) -> f64 {
        coating_mu(p0, self.p_crit, self.mu1, self.mu2)
    }
    #[inline]
    fn failed(&self, p0: f64) -> bool {
        coating_failed(p0, self.p_crit)
    }
}
