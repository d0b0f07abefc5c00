//! The knobs of a yield ([`YieldParams`]), their one check ([`YieldParams::bad_knob`]) and what
//! a yield returns ([`YieldOutcome`]).

use super::dem_decide::YieldDem;
use super::fabrication::FabricationModel;
use super::interval;
use super::row::{YieldRow, YieldSummary};
use crate::study::tolerance::LimitParams;

/// Every knob of a yield (SI inside; angles in degrees as given).
#[derive(Debug, Clone)]
pub struct YieldParams {
    /// Nominal θ (degrees).
    pub theta_deg: f64,
    /// Nominal pull direction from the substrate's x axis (degrees).
    pub direction_deg: f64,
    /// What varies between devices.
    pub fabrication: FabricationModel,
    /// Devices drawn (≥ 1).
    pub samples: usize,
    /// q in (0, 1): the fraction of devices the quoted load must hold.
    pub quantile: f64,
    /// γ in (0, 1): confidence of the intervals and of the bound.
    pub confidence: f64,
    /// Bisection resolution: a fraction of the load (> 0).
    pub resolution: f64,
    /// The ladder (N), μ_sl, contact line and the estimate's knobs.
    pub limit: LimitParams,
    /// The DEM's settings (`None`: no DEM).
    pub dem: Option<YieldDem>,
}

/// What a yield found.
#[derive(Debug, Clone)]
pub struct YieldOutcome {
    /// One row per device, the check's included (`yield.csv`).
    pub rows: Vec<YieldRow>,
    /// The answer (`summary.json`).
    pub summary: YieldSummary,
    /// Single-load estimates made (cost).
    pub estimates: usize,
}

/// The fewest devices for a one-sided 95 %/95 % bound of the load at 95 % yield (Wilks: 59),
/// the devices of a yield unless asked otherwise.
pub fn bound_samples() -> usize {
    interval::min_samples(0.95, 0.95)
}

/// A knob of a yield that is out of its range (the caller names its flag or field).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BadKnob {
    /// `samples` is 0.
    Samples,
    /// `quantile` outside (0, 1).
    Quantile,
    /// `confidence` outside (0, 1).
    Confidence,
    /// `resolution` outside (0, 0.5].
    Resolution,
}

impl YieldParams {
    /// Which knob is out of range (`None`: all are in range): samples ≥ 1, q and γ in (0, 1),
    /// the resolution in (0, 0.5]. The one check of `superlube yield` and of the design's
    /// yield stage; each words it with its own flags.
    pub fn bad_knob(
        samples: usize,
        quantile: f64,
        confidence: f64,
        resolution: f64,
    ) -> Option<BadKnob> {
        let frac = |v: f64| v.is_finite() && v > 0.0 && v < 1.0;
        if samples == 0 {
            Some(BadKnob::Samples)
        } else if !frac(quantile) {
            Some(BadKnob::Quantile)
        } else if !frac(confidence) {
            Some(BadKnob::Confidence)
        } else if !(resolution.is_finite() && resolution > 0.0 && resolution <= 0.5) {
            Some(BadKnob::Resolution)
        } else {
            None
        }
    }
}
