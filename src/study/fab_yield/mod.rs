//! The yield of one design: the fraction of fabricated devices that stay superlubric at a
//! load, and the load that a fraction q of them hold, with its confidence bound
//! ([`fab_yield`]).
//!
//! 1. **Devices** — `samples` devices are drawn from the fabrication model
//!    ([`fabrication`]: θ and pull-direction offsets, a fresh substrate at the scene's σ_h,
//!    optionally sphere-diameter and P_crit scatter).
//! 2. **Critical loads** — each device's critical load W_c by the estimate, on the design's
//!    load ladder then bisected to the resolution, with its band bracket [W_low, W_high]
//!    ([`critical`]); the devices are estimated in parallel, each on its own solver.
//! 3. **Yield** — yield(W) = fraction of devices with W_c ≥ W, with its exact
//!    (Clopper–Pearson) interval; the quoted load W_q = the load a fraction q hold, and its
//!    one-sided lower bound at confidence γ from the order statistics (Wilks; [`interval`]).
//! 4. **DEM** — devices whose bracket contains W_q get a DEM run there ([`dem_decide`]), which
//!    decides them (every such device is run, so the yield at W_q is one binomial count of
//!    estimate- and DEM-decided devices); then a DEM check of `check` fresh devices at the
//!    final W_q (or a load of its own) gives passed/total with its interval.
//!
//! Same inputs and seed give the same result whatever the number of threads: each device's
//! draw comes from its own stream, its estimates depend on it alone, and the DEM's do not
//! depend on the thread count. Cost: the estimate's part ≈ samples × (one ladder path + 8–15
//! single-load estimates) / threads; the DEM's ≈ (devices in the band + check) DEM runs.

pub mod critical;
pub mod dem_decide;
pub mod device;
pub mod fabrication;
pub mod interval;
pub mod row;

pub use critical::{critical_load, CriticalLoad, Limit, DEFAULT_RESOLUTION};
pub use dem_decide::YieldDem;
pub use device::Device;
pub use fabrication::{FabricationModel, FabricationRecord, OffsetLaw, Sample};
pub use row::{CurvePoint, DecidedBy, DemCheckRun, YieldRow, YieldSummary};

use crate::runs::progress::Progress;
use crate::study::rows::label;
use crate::study::tolerance::LimitParams;
use anyhow::Result;
use dem_decide::{Ask, DemDecider};
use rayon::prelude::*;
use surrogate::solver::Solver;
use surrogate::units::n_to_mn;
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
    /// One row per device (`yield.csv`).
    pub rows: Vec<YieldRow>,
    /// The answer (`summary.json`).
    pub summary: YieldSummary,
    /// Single-load estimates made (cost).
    pub estimates: usize,
}

/// The devices' critical loads (N), ascending.
fn sorted_loads(devices: &[Device], resolution: f64) -> Vec<f64> {
    let mut w: Vec<f64> = devices.iter().map(|d| d.critical(resolution)).collect();
    w.sort_by(f64::total_cmp);
    w
}

/// How many devices decided by `by` (their `rows`) hold the quoted load `w_q` (N; none
/// without one).
fn stratum_holding(
    devices: &[Device],
    rows: &[YieldRow],
    (w_q, resolution): (Option<f64>, f64),
    by: DecidedBy,
) -> usize {
    let Some(w) = w_q else { return 0 };
    devices
        .iter()
        .zip(rows)
        .filter(|(d, r)| r.decided_by == by && d.critical(resolution) >= w)
        .count()
}

/// How many of the `sorted` critical loads are ≥ `w` (the devices holding `w`).
fn holding(sorted: &[f64], w: f64) -> usize {
    sorted.len() - sorted.partition_point(|&x| x < w)
}

/// Whether the estimate of device `s` at load `w` (N) has failing contacts on the mount's
/// resonance (a fresh device of the DEM check: the rule of the decisions,
/// [`CriticalLoad::resonant_at`]). Cost: one solver build and one single-load estimate.
fn resonant_at(scene: &Scene, p: &YieldParams, s: &Sample, w: f64) -> Result<bool> {
    let solver = Solver::new(&s.scene(scene))?;
    let mut lp = p.limit.clone();
    lp.loads = vec![w];
    let rows = crate::study::tolerance::rows_at(
        &solver,
        label(p.theta_deg + s.theta_offset_deg),
        label(p.direction_deg + s.direction_offset_deg),
        &[0],
        &lp,
    )?;
    Ok(rows
        .first()
        .is_some_and(|r| r.mount_resonance == Some(true)))
}

/// The yield of the design (θ, direction) of `scene` (see the module docs). Progress: the
/// stage `yield: critical loads` over the devices, then the DEM's stages.
pub fn fab_yield(scene: &Scene, p: &YieldParams, progress: &dyn Progress) -> Result<YieldOutcome> {
    let devices = estimate_devices(scene, p, progress)?;
    decide(scene, p, devices, progress)
}

/// Steps 1–2 of [`fab_yield`]: the devices drawn and their critical loads by the estimate (no
/// DEM decision yet), in sample order: what a caller may store to resume ([`Device`] is
/// serialisable; its floats round-trip exactly through JSON). Progress: the stage
/// `yield: critical loads`. Cost: the estimate's part (module docs).
pub fn estimate_devices(
    scene: &Scene,
    p: &YieldParams,
    progress: &dyn Progress,
) -> Result<Vec<Device>> {
    let samples: Vec<Sample> = (0..p.samples)
        .map(|i| p.fabrication.sample(scene, i))
        .collect();
    progress.stage("yield: critical loads", p.samples as u64, "devices");
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
            sample,
            estimate: c?,
            dem: Vec::new(),
        });
    }
    Ok(devices)
}

/// Steps 3–4 of [`fab_yield`] on `devices` from [`estimate_devices`] (same `scene` and `p`):
/// the DEM decisions and check when `p.dem` is set, the yield and its summary.
pub fn decide(
    scene: &Scene,
    p: &YieldParams,
    mut devices: Vec<Device>,
    progress: &dyn Progress,
) -> Result<YieldOutcome> {
    let estimates = devices.iter().map(|d| d.estimate.estimates).sum();
    let q = p.quantile;
    let quoted = |devices: &[Device]| {
        interval::quantile_load(&sorted_loads(devices, p.resolution), q).filter(|&w| w > 0.0)
    };
    // the DEM decides the devices in the band at the quoted load, until none is left
    let mut dem_runs = 0;
    let mut rounds = 0;
    let decider = p.dem.as_ref().map(|dem| DemDecider {
        scene,
        theta_deg: p.theta_deg,
        direction_deg: p.direction_deg,
        mu_superlubric: p.limit.mu_superlubric,
        dem,
    });
    if let Some(dd) = &decider {
        while rounds < dd.dem.max_rounds {
            let Some(w) = quoted(&devices) else { break };
            let todo: Vec<usize> = (0..devices.len())
                .filter(|&i| devices[i].in_band(w) && devices[i].dem_at(w).is_none())
                .collect();
            if todo.is_empty() {
                break;
            }
            rounds += 1;
            progress.note(&format!(
                "yield: {} device(s) lie in the estimate's band at {} mN: the DEM decides them (round {rounds})",
                todo.len(),
                label(n_to_mn(w))
            ));
            let asks: Vec<Ask> = todo
                .iter()
                .map(|&i| Ask {
                    sample: &devices[i].sample,
                    load: w,
                    mount_resonance: devices[i].estimate.resonant_at(w),
                })
                .collect();
            let verdicts = dd.run(&asks, "yield: DEM decisions", progress)?;
            dem_runs += verdicts.len();
            for (&i, v) in todo.iter().zip(verdicts) {
                devices[i].dem.push((w, v.is_ok()));
            }
        }
    }
    let sorted = sorted_loads(&devices, p.resolution);
    let w_q = quoted(&devices);
    let n = devices.len();
    let rank = interval::wilks_rank(n, q, p.confidence);
    let bound = rank.map(|r| sorted[r - 1]);
    let mn = |w: f64| label(n_to_mn(w));
    // the curve at each distinct critical load and at the quoted load
    let mut at: Vec<f64> = sorted.clone();
    at.extend(w_q);
    at.sort_by(f64::total_cmp);
    at.dedup();
    let point = |w: f64| {
        let k = holding(&sorted, w);
        let (lo, hi) = interval::clopper_pearson(k, n, p.confidence);
        CurvePoint {
            load_mN: mn(w),
            fraction: k as f64 / n as f64,
            low: lo,
            high: hi,
        }
    };
    let curve: Vec<CurvePoint> = at.iter().map(|&w| point(w)).collect();
    // the DEM check on fresh devices at the quoted load
    let mut check_runs = Vec::new();
    let check_load = decider.as_ref().and_then(|dd| dd.dem.check_load.or(w_q));
    if let (Some(dd), Some(w)) = (&decider, check_load) {
        let fresh: Vec<Sample> = (n..n + dd.dem.check)
            .map(|i| p.fabrication.sample(scene, i))
            .collect();
        // the model rule of the decisions: the estimate at w says whether the mount resonates
        let resonant: Vec<bool> = fresh
            .par_iter()
            .map(|s| resonant_at(scene, p, s, w))
            .collect::<Result<_>>()?;
        let asks: Vec<Ask> = fresh
            .iter()
            .zip(resonant)
            .map(|(s, r)| Ask {
                sample: s,
                load: w,
                mount_resonance: r,
            })
            .collect();
        let verdicts = dd.run(&asks, "yield: DEM check", progress)?;
        for (s, v) in fresh.iter().zip(verdicts) {
            check_runs.push(DemCheckRun {
                sample: s.index,
                theta_offset_deg: s.theta_offset_deg,
                direction_offset_deg: s.direction_offset_deg,
                seed: s.substrate_seed,
                superlubric: v.is_ok(),
                why: v.err().unwrap_or_default(),
            });
        }
    }
    let passed = check_runs.iter().filter(|r| r.superlubric).count();
    let total = check_runs.len();
    let rows: Vec<YieldRow> = devices.iter().map(|d| d.row(p.resolution, w_q)).collect();
    let summary = YieldSummary {
        pattern: scene.pattern.clone(),
        theta_deg: p.theta_deg,
        direction_deg: p.direction_deg,
        quantile: q,
        confidence: p.confidence,
        samples: n,
        resolution: p.resolution,
        load_at_quantile_mN: w_q.map(mn),
        load_at_quantile_bound_mN: bound.map(mn),
        bound_rank: rank,
        min_samples_for_bound: interval::min_samples(q, p.confidence),
        yield_at_quantile_load: w_q.map(|w| holding(&sorted, w) as f64 / n as f64),
        yield_at_quantile_load_interval: w_q.map(|w| {
            let (lo, hi) = interval::clopper_pearson(holding(&sorted, w), n, p.confidence);
            [lo, hi]
        }),
        dem_decided: rows
            .iter()
            .filter(|r| r.decided_by == DecidedBy::Dem)
            .count(),
        dem_decided_holding: stratum_holding(&devices, &rows, (w_q, p.resolution), DecidedBy::Dem),
        estimate_decided_holding: stratum_holding(
            &devices,
            &rows,
            (w_q, p.resolution),
            DecidedBy::Estimate,
        ),
        dem_runs,
        dem_rounds: rounds,
        dem_check_passed: passed,
        dem_check_total: total,
        dem_check_interval: (total > 0).then(|| {
            let (lo, hi) = interval::clopper_pearson(passed, total, p.confidence);
            [lo, hi]
        }),
        dem_check_runs: check_runs,
        dem_check_load_mN: check_load.filter(|_| total > 0).map(mn),
        dem: decider.is_some(),
        censored: devices.iter().filter(|d| d.estimate.censored).count(),
        fabrication: p.fabrication.record(scene),
        curve,
    };
    Ok(YieldOutcome {
        rows,
        summary,
        estimates,
    })
}
