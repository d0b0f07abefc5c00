//! Lock-in detection: the support moves but the slider does not follow.

use super::Sample;
use serde::Serialize;

/// Verdict over a measuring window.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LockIn {
    /// Slider advance / support advance over the window (≈ 1 when sliding, ≈ 0 when locked).
    pub advance_ratio: f64,
    /// Slope of the spring force over the window divided by `K0·v` (≈ 1 when locked: the force
    /// rises linearly; ≈ 0 in steady sliding).
    pub force_slope_ratio: f64,
    /// `advance_ratio < threshold`.
    pub locked_in: bool,
}

/// Judges the window `w` (samples in time order) with spring stiffness `k0` (N/m), support
/// speed `v` (m/s) and threshold on the advance ratio. O(n).
pub fn lock_in(w: &[Sample], k0: f64, v: f64, threshold: f64) -> LockIn {
    if w.len() < 2 {
        return LockIn {
            advance_ratio: f64::NAN,
            force_slope_ratio: f64::NAN,
            locked_in: false,
        };
    }
    let (a, b) = (w[0], w[w.len() - 1]);
    let ds = b.support_x_um - a.support_x_um;
    let dx = b.slider_x_um - a.slider_x_um;
    let ratio = if ds.abs() > 0.0 { dx / ds } else { f64::NAN };
    // least-squares slope of spring force (mN) vs time (µs)
    let n = w.len() as f64;
    let mt = w.iter().map(|s| s.t_us).sum::<f64>() / n;
    let mf = w.iter().map(|s| s.spring_force_mn).sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for s in w {
        sxy += (s.t_us - mt) * (s.spring_force_mn - mf);
        sxx += (s.t_us - mt).powi(2);
    }
    let slope_mn_per_us = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let kv_mn_per_us = k0 * v * 1e3 * 1e-6;
    LockIn {
        advance_ratio: ratio,
        force_slope_ratio: if kv_mn_per_us > 0.0 {
            slope_mn_per_us / kv_mn_per_us
        } else {
            f64::NAN
        },
        locked_in: ratio < threshold,
    }
}
