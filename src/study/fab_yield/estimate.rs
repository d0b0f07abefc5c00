//! The devices of a yield drawn and estimated ([`estimate_range`]): the one way a yield, its
//! check, the Monte Carlo and `design --rank-by yield` draw a design's devices.

use super::critical::{critical_load, CriticalLoad};
use super::device::Device;
use super::fabrication::Sample;
use super::params::YieldParams;
use crate::runs::progress::Progress;
use crate::study::rows::label;
use anyhow::Result;
use rayon::prelude::*;
use std::ops::Range;
use surrogate::solver::Solver;
use surrogate::Scene;

/// Steps 1–2 of [`super::fab_yield`]: the yield's devices drawn and their critical loads by the
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
