//! [`Friction`]: the friction laws available at run time, one enum over the [`FrictionLaw`]s.

use super::friction_law::FrictionLaw;
use super::{Constant, PressureSwitched};

/// The friction laws available at run time (enum dispatch keeps the inner loop monomorphic).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Friction {
    /// μ1 below P_crit, μ2 above (the study's coating).
    PressureSwitched(PressureSwitched),
    /// One μ everywhere (tests, reference runs).
    Constant(Constant),
}

impl FrictionLaw for Friction {
    #[inline]
    fn mu(&self, p0: f64) -> f64 {
        match self {
            Friction::PressureSwitched(f) => f.mu(p0),
            Friction::Constant(f) => f.mu(p0),
        }
    }
    #[inline]
    fn failed(&self, p0: f64) -> bool {
        match self {
            Friction::PressureSwitched(f) => f.failed(p0),
            Friction::Constant(f) => f.failed(p0),
        }
    }
}
