//! [`NormalModel`]: the normal force law of a contact.

/// Normal force of a contact as a function of overlap δ (m) and overlap rate δ̇ (m/s).
pub trait NormalModel: Sync + Send {
    /// The normal force magnitude (N, ≥ 0, repulsive), the elastic normal stiffness dF/dδ
    /// (N/m), the maximum contact pressure (Pa) and the contact radius (m), for an overlap
    /// `delta > 0`, overlap rate `delta_dot` and pair effective mass `m_eff` (kg). O(1).
    fn force(&self, delta: f64, delta_dot: f64, m_eff: f64) -> NormalOut;
    /// Contact radius a (m) at overlap `delta` (m).
    fn contact_radius(&self, delta: f64) -> f64;
    /// Elastic energy (J) stored at overlap `delta` (m).
    fn energy(&self, delta: f64) -> f64;
}

/// Result of a [`NormalModel`] at one overlap (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalOut {
    /// Normal force magnitude (N), ≥ 0.
    pub force: f64,
    /// Elastic normal stiffness dF/dδ (N/m).
    pub stiffness: f64,
    /// Maximum contact pressure p0 (Pa).
    pub p0: f64,
    /// Contact radius a (m).
    pub radius: f64,
}
