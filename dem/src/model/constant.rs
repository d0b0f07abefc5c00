//! [`Constant`]: one friction coefficient for every contact (tests and reference runs).

use super::friction_law::FrictionLaw;

/// Constant μ; no coating failure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Constant {
    /// Friction coefficient (–).
    pub mu: f64,
}

impl FrictionLaw for Constant {
    #[inline]
    fn mu(&self, _p0: f64) -> f64 {
        self.mu
    }
    #[inline]
    fn failed(&self, _p0: f64) -> bool {
        false
    }
}
