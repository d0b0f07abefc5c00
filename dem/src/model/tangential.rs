//! [`TangentialModel`]: the history-dependent tangential force of a contact.

/// Tangential force with a per-contact history (elastic tangential displacement ξ).
pub trait TangentialModel: Sync + Send {
    /// Updates the history `xi` (m) with the relative tangential velocity `v_t` (m/s) over `dt`
    /// (after rotating it into the plane normal to `n`) and returns the tangential force on the
    /// first body (N), capped at `cap = μ·F_n` (N). `a` is the contact radius (m), `m_eff` the
    /// pair effective mass (kg). O(1).
    #[allow(clippy::too_many_arguments)]
    fn force(
        &self,
        xi: &mut [f64; 3],
        n: [f64; 3],
        v_t: [f64; 3],
        a: f64,
        cap: f64,
        m_eff: f64,
        dt: f64,
    ) -> [f64; 3];
    /// Tangential stiffness k_t (N/m) at contact radius `a` (m).
    fn stiffness(&self, a: f64) -> f64;
}
