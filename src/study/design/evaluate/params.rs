//! [`AlphaScanParams`]: the knobs of the design's α scan ([`super::alpha_scan`]).

/// The α scan's knobs, the contact line α is measured from included (the estimate, the DEM
/// and the limits measure α from the same line).
#[derive(Debug, Clone, PartialEq)]
pub struct AlphaScanParams {
    /// Coarse α grid step (degrees) of the scan over [0, P_α).
    pub alpha_step_deg: f64,
    /// Successive finer α steps (degrees), each scanned over ± half the previous step around
    /// the best α so far.
    pub alpha_refine_deg: Vec<f64>,
    /// Contact-line angle (rad from x) for every θ; `None`: the moiré estimate.
    pub line: Option<f64>,
    /// Length (m) of the α-scan paths.
    pub scan_length: f64,
    /// Sample spacing (m) of the α-scan paths.
    pub scan_step: f64,
    /// Pulling angles per orientation whose friction is estimated (the lowest-corrugation
    /// local minima of the scan, ≥ one refine window apart).
    pub alphas_per_theta: usize,
}
