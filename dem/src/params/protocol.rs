//! [`ProtocolParams`]: what the experiment does to the slider — the load, the drive (pulling
//! spring, support, direction) and the phases with their sampling.

use serde::{Deserialize, Serialize};

/// The protocol of a DEM run (SI: s, m, N, N/m, rad): equilibrate under the load W with the
/// control layer held laterally, relax with the pulling spring K0 attached and the support at
/// rest, then slide: the support moves at `support_speed` along α and the friction is the mean
/// spring force `K0·(x_support − x_cl − lead)` over the measuring window. Defaults = the
/// reference study (docs/physics.md, Tier 3).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ProtocolParams {
    /// Pulling spring stiffness K0 between support and control-layer centre of mass (N/m).
    pub k0: f64,
    /// Distance the support starts ahead of the control layer along α (m) = spring rest length.
    pub support_lead: f64,
    /// Support speed (m/s) along α during sliding. Study: 0.1.
    pub support_speed: f64,
    /// Pulling angle α (rad) from the +x axis (the substrate row / contact-line direction).
    pub alpha: f64,
    /// Normal load W (N) applied downward on the control layer.
    pub load: f64,
    /// Equilibration time under load (s), control layer held laterally. Study: 10 µs.
    pub equilibrate_time: f64,
    /// Relaxation time with the pulling spring attached and the support at rest (s). Study: 10 µs.
    pub relax_time: f64,
    /// Sliding time (s). Study: 300 µs.
    pub slide_time: f64,
    /// Friction = mean spring force over sliding times in `[measure_from·slide_time, slide_time]`.
    /// Study: 1/3 (100–300 µs of 300 µs).
    pub measure_from: f64,
    /// Sampling interval of the time series (s).
    pub sample_interval: f64,
    /// Lock-in: over the measuring window, slider advance / support advance below this → locked.
    pub lock_in_ratio: f64,
}

impl Default for ProtocolParams {
    fn default() -> Self {
        ProtocolParams {
            k0: 50.0,
            support_lead: 120e-6,
            support_speed: 0.1,
            alpha: 0.0,
            load: 0.35e-3,
            equilibrate_time: 10e-6,
            relax_time: 10e-6,
            slide_time: 300e-6,
            measure_from: 1.0 / 3.0,
            sample_interval: 0.1e-6,
            lock_in_ratio: 0.5,
        }
    }
}
