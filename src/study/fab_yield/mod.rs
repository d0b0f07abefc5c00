//! The yield of one design: the fraction of fabricated devices that stay superlubric at a
//! load, and the load that a fraction q of them hold, with its confidence bound
//! ([`fab_yield`]).
//!
//! 1. **Devices** — `samples` devices are drawn from the fabrication model
//!    ([`fabrication`]: θ and pull-direction offsets, a fresh substrate at the scene's σ_h,
//!    optionally sphere-diameter and P_crit scatter).
//! 2. **Critical loads** — each device's critical load W_c by the estimate, on the design's
//!    load ladder then bisected to the resolution, with its band bracket [W_low, W_high] and
//!    every single-load estimate made ([`critical`]); the devices are estimated in parallel,
//!    each on its own solver.
//! 3. **DEM rounds** — only the lowest K critical loads set the quote and its bound; the DEM
//!    locates those devices' own critical loads to the resolution and shows the others above
//!    them, its runs placed by the DEM's margin transferred through each device's estimate
//!    ([`margin`]), with a band calibrated on the design's own DEM runs ([`calibration`],
//!    [`rounds`]).
//! 4. **Check** — `check` fresh devices are estimated and run with the DEM at the quoted load;
//!    they are pooled into the yield (DEM-decided devices of the same model), and the rounds go
//!    on over the pool ([`dem_part`]).
//! 5. **Curve and summary** — yield(W) = fraction of devices with W_c ≥ W with its exact
//!    (Clopper–Pearson) interval; the quote W_q = the load a fraction q hold, and its one-sided
//!    lower bound at confidence γ from the order statistics (Wilks; [`interval`]); the check
//!    must agree with the final quote (else the quote is lowered until it does) ([`summary`]).
//!
//! Same inputs and seed give the same result whatever the number of threads: each device's
//! draw comes from its own stream, its estimates depend on it alone, and the DEM's do not
//! depend on the thread count. Cost: the estimate's part ≈ (samples + check) × (one ladder
//! path and 8–15 single-load estimates) / threads; the DEM's at most `max_runs` runs (about 3
//! per located device and 1 per device shown above the quote, plus the check).

pub mod calibration;
pub mod critical;
pub mod dem_decide;
pub mod dem_part;
pub mod device;
pub mod fabrication;
pub mod interval;
pub mod margin;
pub mod monte_carlo;
pub mod rounds;
pub mod row;
pub mod summary;
#[cfg(test)]
mod synthetic_tests;

pub use calibration::{Band, BandSource, Pair};
pub use critical::{critical_load, CriticalLoad, Limit, Probe, DEFAULT_RESOLUTION};
pub use dem_decide::{YieldDem, DEFAULT_MAX_RUNS};
pub use device::{DemRun, Device};
pub use fabrication::{FabricationModel, FabricationRecord, OffsetLaw, Sample};
pub use row::{CurvePoint, DecidedBy, DemCheckRun, DemFailure, YieldRow, YieldSummary};

use crate::runs::progress::Progress;
use crate::study::rows::label;
use crate::study::tolerance::LimitParams;
use anyhow::Result;
use rayon::prelude::*;
use std::ops::Range;
use surrogate::solver::Solver;
use surrogate::Scene;

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

/// The yield of the design (θ, direction) of `scene` (see the module docs). Progress: the
/// stage `yield: critical loads` over the devices, then the DEM's stages.
pub fn fab_yield(scene: &Scene, p: &YieldParams, progress: &dyn Progress) -> Result<YieldOutcome> {
    let devices = estimate_devices(scene, p, progress)?;
    decide(scene, p, devices, progress)
}

/// Steps 1–2 of [`fab_yield`]: the yield's devices drawn and their critical loads by the
/// estimate (no DEM decision yet), in sample order: what a caller may store to resume
/// ([`Device`] is serialisable; its floats round-trip exactly through JSON). Progress: the
/// stage `yield: critical loads`. Cost: the estimate's part (module docs).
pub fn estimate_devices(
    scene: &Scene,
    p: &YieldParams,
    progress: &dyn Progress,
) -> Result<Vec<Device>> {
    estimate_range(scene, p, 0..p.samples, "yield: critical loads", progress)
}

/// The devices of samples `range` and their critical loads by the estimate, in sample order
/// (the check's devices are `samples..samples + check`, [`Device::check`] set). The one way a
/// yield draws its devices. Cost: `range.len()` × one device's estimate / threads.
pub fn estimate_range(
    scene: &Scene,
    p: &YieldParams,
    range: Range<usize>,
    stage: &str,
    progress: &dyn Progress,
) -> Result<Vec<Device>> {
    let samples: Vec<Sample> = range
        .clone()
        .map(|i| p.fabrication.sample(scene, i))
        .collect();
    progress.stage(stage, samples.len() as u64, "devices");
    let estimated: Vec<Result<CriticalLoad>> = samples
        .par_iter()
        .map(|s| {
            let solver = Solver::new(&s.scene(scene))?;
            let c = critical_load(
                &solver,
                label(p.theta_deg + s.theta_offset_deg),
                label(p.direction_deg + s.direction_offset_deg),
                &p.limit,
                p.resolution,
            );
            progress.advance(1);
            c
        })
        .collect();
    progress.finish();
    let mut devices = Vec::with_capacity(samples.len());
    for (sample, c) in samples.into_iter().zip(estimated) {
        devices.push(Device {
            check: sample.index >= p.samples,
            sample,
            estimate: c?,
            dem: Vec::new(),
        });
    }
    Ok(devices)
}

/// Steps 3–5 of [`fab_yield`] on `devices` from [`estimate_devices`] (same `scene` and `p`):
/// the DEM rounds and check when `p.dem` is set, then the curve and the summary.
pub fn decide(
    scene: &Scene,
    p: &YieldParams,
    mut devices: Vec<Device>,
    progress: &dyn Progress,
) -> Result<YieldOutcome> {
    let dem = match &p.dem {
        Some(d) => Some(dem_part::run(scene, p, d, &mut devices, progress)?),
        None => None,
    };
    Ok(summary::outcome(scene, p, &devices, dem.as_ref()))
}
