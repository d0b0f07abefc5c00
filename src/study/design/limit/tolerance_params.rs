//! [`ToleranceParams`]: the fabrication tolerance of a design, which the robust search, the
//! ranking, the tolerance maps, the DEM's corners and the yield share ([`super::LimitKnobs`]).

/// The tolerance box the robust limit holds over, its sampling and the substrate seeds.
#[derive(Debug, Clone, PartialEq)]
pub struct ToleranceParams {
    /// Fabrication tolerance of θ (degrees, ≥ 0): the robust limit holds for every θ within
    /// ± this of the nominal ([`crate::study::tolerance`]).
    pub theta_tol_deg: f64,
    /// Tolerance of the pulling direction in the substrate frame (degrees, ≥ 0).
    pub direction_tol_deg: f64,
    /// Largest sampling step of the θ tolerance (degrees): a window narrower than it cannot
    /// pass (the first sample off the nominal is at most one step away).
    pub theta_tol_step_deg: f64,
    /// Largest sampling step of the direction tolerance (degrees).
    pub direction_tol_step_deg: f64,
    /// Substrate seeds evaluated for the robust limit besides the scene's own (σ_h > 0 only).
    pub seeds: Vec<u64>,
}
