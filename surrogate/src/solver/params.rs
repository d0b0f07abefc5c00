//! [`SolverParams`]: every numerical knob of the quasi-static solver in one place.

use serde::{Deserialize, Serialize};

/// Numerical knobs of the quasi-static solver.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SolverParams {
    /// Relative force-balance tolerance: stop when |ΣF_z − W| ≤ `force_rtol`·W.
    pub force_rtol: f64,
    /// Relative moment-balance tolerance of the tilt models: stop when
    /// |ΣF_z·arm| ≤ `moment_rtol`·W·L (L = slider radius).
    pub moment_rtol: f64,
    /// Maximum Newton/bisection iterations of a root find before giving up with an error.
    pub max_iter: usize,
    /// Slider-sphere vertical spring stiffness (N/m) used by the compliant model (study: 1e6).
    pub k_slider_z: f64,
    /// Substrate tether stiffness (N/m) (study: 1e3, lateral). Not used by the quasi-static
    /// models (they are vertical-only); kept for the dynamic tier.
    pub k_substrate_xy: f64,
}

impl Default for SolverParams {
    fn default() -> Self {
        SolverParams {
            force_rtol: 1e-12,
            moment_rtol: 1e-10,
            max_iter: 200,
            k_slider_z: 1e6,
            k_substrate_xy: 1e3,
        }
    }
}
