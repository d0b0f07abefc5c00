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
//! 3. **Check** — `check` fresh devices are estimated and run with the DEM at the estimate's
//!    quote; drawn at random, their pairs calibrate the band on devices not chosen by their
//!    estimate; they are pooled into the yield (DEM-decided devices of the same model)
//!    ([`dem_part`]).
//! 4. **DEM rounds** — only the lowest K critical loads of the pool set the quote and its bound; the DEM
//!    locates those devices' own critical loads to the resolution and shows the others above
//!    them, its runs placed by the DEM's margin transferred through each device's estimate
//!    ([`margin`]), with a band calibrated on the design's own DEM runs ([`calibration`],
//!    [`rounds`]).
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
pub mod estimate;
pub mod fabrication;
pub mod interval;
pub mod margin;
pub mod monte_carlo;
pub mod params;
pub mod rounds;
pub mod row;
pub mod summary;
#[cfg(test)]
mod synthetic_tests;

pub use calibration::{Band, BandSource, Pair};
pub use critical::{critical_load, CriticalLoad, Limit, Probe, DEFAULT_RESOLUTION};
pub use dem_decide::{YieldDem, DEFAULT_MAX_RUNS};
pub use device::{DemRun, Device};
pub use estimate::{estimate_devices, estimate_range};
pub use fabrication::{FabricationModel, FabricationRecord, OffsetLaw, Sample};
pub use params::{bound_samples, BadKnob, YieldOutcome, YieldParams};
pub use row::{CurvePoint, DecidedBy, DemCheckRun, DemFailure, YieldRow, YieldSummary};

use crate::runs::progress::Progress;
use anyhow::Result;
use surrogate::Scene;

/// The yield of the design (θ, direction) of `scene` (see the module docs). Progress: the
/// stage `yield: critical loads` over the devices, then the DEM's stages.
pub fn fab_yield(scene: &Scene, p: &YieldParams, progress: &dyn Progress) -> Result<YieldOutcome> {
    let devices = estimate_devices(scene, p, progress)?;
    decide(scene, p, devices, progress)
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
