//! [`FrictionLaw`]: the friction coefficient of a contact as a function of its pressure.

use super::{Constant, PressureSwitched};

/// Friction coefficient μ(p0) of a contact with maximum Hertz pressure p0 (Pa).
pub trait FrictionLaw: Sync + Send {
    /// μ (–) at p0 (Pa).
    fn mu(&self, p0: f64) -> f64;
    /// Whether the coating of a contact at p0 (Pa) has failed.
    fn failed(&self, p0: f64) -> bool;
}

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
