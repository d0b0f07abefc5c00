//! [`FrictionLaw`]: the friction coefficient of a contact as a function of its pressure.

/// Friction coefficient μ(p0) of a contact with maximum Hertz pressure p0 (Pa).
pub trait FrictionLaw: Sync + Send {
    /// μ (–) at p0 (Pa).
    fn mu(&self, p0: f64) -> f64;
    /// Whether the coating of a contact at p0 (Pa) has failed.
    fn failed(&self, p0: f64) -> bool;
}
