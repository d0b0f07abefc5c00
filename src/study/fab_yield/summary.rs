//! Step 5 of a yield ([`outcome`]): each device's critical load as the yield counts it, the
//! quote and its bound, the check's agreement with the quote, the curve and the summary.
//!
//! **The check agrees** with a quote W_q when the check's devices holding W_q, k of c, are
//! not too few for q at confidence γ: the upper end of their Clopper–Pearson interval is
//! ≥ q. When it does not, the quote is lowered to the highest critical load of a check device
//! below it at which the check agrees, and the bound with it (`quote_lowered_by_check`); the
//! summary states `dem_check_consistent` for the final quote. At a check load of its own, the
//! check agrees when its interval holds the yield there. Cost: a sort of the devices and
//! about 100 binomial CDFs per interval.

use super::dem_part::DemPart;
use super::device::Device;
use super::interval;
use super::params::{YieldOutcome, YieldParams};
use super::rounds::{answer, Knowledge};
use super::row::{CurvePoint, DecidedBy, DemCheckRun, DemFailure, YieldSummary};
use crate::study::rows::label;
use surrogate::units::n_to_mn;
use surrogate::Scene;

/// How many of the `sorted` critical loads are ≥ `w` (the devices holding `w`).
fn holding(sorted: &[f64], w: f64) -> usize {
    sorted.len() - sorted.partition_point(|&x| x < w)
}

/// Whether k of n devices holding a load agree with a quote at q (confidence γ).
fn agrees(k: usize, n: usize, q: f64, confidence: f64) -> bool {
    interval::clopper_pearson(k, n, confidence).1 >= q
}

/// The quote, its bound and the check's word on them (N).
struct Quote {
    load: Option<f64>,
    bound: Option<f64>,
    consistent: Option<bool>,
    lowered: bool,
}

/// The quote of `values` and its bound, lowered until the check agrees (module docs).
fn quote_checked(
    p: &YieldParams,
    devices: &[Device],
    values: &[(f64, DecidedBy)],
    dem: Option<&DemPart>,
) -> Quote {
    let (q, g) = (p.quantile, p.confidence);
    let mut sorted: Vec<f64> = values.iter().map(|v| v.0).collect();
    sorted.sort_by(f64::total_cmp);
    let (mut load, mut bound) = answer(&sorted, q, g);
    let checked: Vec<f64> = devices
        .iter()
        .zip(values)
        .filter(|(d, _)| d.check)
        .map(|(_, v)| v.0)
        .collect();
    let c = checked.len();
    let k_at = |w: f64| checked.iter().filter(|&&v| v >= w).count();
    let Some(part) = dem.filter(|_| c > 0) else {
        return Quote {
            load,
            bound,
            consistent: None,
            lowered: false,
        };
    };
    if part.check_load_given {
        let at = part.check_load.unwrap_or(0.0);
        let y = holding(&sorted, at) as f64 / sorted.len() as f64;
        let (lo, hi) = interval::clopper_pearson(k_at(at), c, g);
        let consistent = Some(lo <= y && y <= hi);
        return Quote {
            load,
            bound,
            consistent,
            lowered: false,
        };
    }
    let mut lowered = false;
    if let Some(w) = load.filter(|&w| !agrees(k_at(w), c, q, g)) {
        let mut below: Vec<f64> = checked.iter().copied().filter(|&v| v < w).collect();
        below.sort_by(|a, b| b.total_cmp(a));
        if let Some(&v) = below.iter().find(|&&v| v > 0.0 && agrees(k_at(v), c, q, g)) {
            load = Some(v);
            bound = bound.map(|b| b.min(v));
            lowered = true;
        }
    }
    Quote {
        consistent: load.map(|w| agrees(k_at(w), c, q, g)),
        load,
        bound,
        lowered,
    }
}

/// The curve at each distinct critical load and at the quote (N).
fn curve(sorted: &[f64], quoted: Option<f64>, confidence: f64) -> Vec<CurvePoint> {
    let n = sorted.len();
    let mut at: Vec<f64> = sorted.to_vec();
    at.extend(quoted);
    at.sort_by(f64::total_cmp);
    at.dedup();
    at.iter()
        .map(|&w| {
            let k = holding(sorted, w);
            let (lo, hi) = interval::clopper_pearson(k, n, confidence);
            CurvePoint {
                load_mN: label(n_to_mn(w)),
                fraction: k as f64 / n as f64,
                low: lo,
                high: hi,
            }
        })
        .collect()
}

/// The check's runs: each check device's first DEM run, with why it failed.
fn check_runs(devices: &[Device], dem: Option<&DemPart>) -> Vec<DemCheckRun> {
    let why = dem.map_or(&[][..], |d| &d.check_why[..]);
    devices
        .iter()
        .filter(|d| d.check && !d.dem.is_empty())
        .zip(why)
        .map(|(d, why)| DemCheckRun {
            sample: d.sample.index,
            theta_offset_deg: d.sample.theta_offset_deg,
            direction_offset_deg: d.sample.direction_offset_deg,
            seed: d.sample.substrate_seed,
            superlubric: d.dem[0].superlubric,
            why: why.clone(),
        })
        .collect()
}

/// The device the DEM failed at the lowest load.
fn lowest_failure(devices: &[Device]) -> Option<DemFailure> {
    devices
        .iter()
        .filter_map(|d| d.lowest_failure().map(|w| (d, w)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(d, w)| DemFailure {
            sample: d.sample.index,
            check: d.check,
            load_mN: label(n_to_mn(w)),
            theta_offset_deg: d.sample.theta_offset_deg,
            direction_offset_deg: d.sample.direction_offset_deg,
            seed: d.sample.substrate_seed,
        })
}

/// The outcome of the yield `p` of `scene` on its `devices` (the check's included) after the
/// DEM part `dem` (`None`: the estimate alone). See the module docs.
pub fn outcome(
    scene: &Scene,
    p: &YieldParams,
    devices: &[Device],
    dem: Option<&DemPart>,
) -> YieldOutcome {
    let mu = p.limit.mu_superlubric;
    let kn = dem.map(|part| Knowledge::of(devices, part.k, mu, p.resolution));
    let values: Vec<(f64, DecidedBy)> = match &kn {
        Some(kn) => kn.values(devices, mu, p.resolution),
        None => devices
            .iter()
            .map(|d| (d.estimate.load, DecidedBy::Estimate))
            .collect(),
    };
    let mut sorted: Vec<f64> = values.iter().map(|v| v.0).collect();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    let qc = quote_checked(p, devices, &values, dem);
    let mn = |w: f64| label(n_to_mn(w));
    let rows = devices
        .iter()
        .zip(&values)
        .map(|(d, &(v, by))| d.row(v, by))
        .collect();
    let runs = check_runs(devices, dem);
    let passed = runs.iter().filter(|r| r.superlubric).count();
    let total = runs.len();
    let count = |by: DecidedBy| values.iter().filter(|v| v.1 == by).count();
    let summary = YieldSummary {
        pattern: scene.pattern.clone(),
        theta_deg: p.theta_deg,
        direction_deg: p.direction_deg,
        quantile: p.quantile,
        confidence: p.confidence,
        samples: p.samples,
        pooled: n,
        resolution: p.resolution,
        load_at_quantile_mN: qc.load.map(mn),
        load_at_quantile_bound_mN: qc.bound.map(mn),
        ceiling_mN: kn.as_ref().map(|k| {
            let c = k.sharpness(&values, p.quantile, p.confidence).ceiling;
            [c.0.map(mn), c.1.map(mn)]
        }),
        bound_rank: interval::wilks_rank(n, p.quantile, p.confidence),
        min_samples_for_bound: interval::min_samples(p.quantile, p.confidence),
        yield_at_quantile_load: qc.load.map(|w| holding(&sorted, w) as f64 / n as f64),
        yield_at_quantile_load_interval: qc.load.map(|w| {
            let (lo, hi) = interval::clopper_pearson(holding(&sorted, w), n, p.confidence);
            [lo, hi]
        }),
        setting_ranks: dem.map_or(0, |d| d.k),
        threshold_mN: kn.as_ref().map(|k| mn(k.threshold)),
        located: devices
            .iter()
            .zip(&values)
            .filter(|(_, v)| v.1 == DecidedBy::Located)
            .map(|(d, _)| d.sample.index)
            .collect(),
        dem_decided: devices.iter().filter(|d| !d.dem.is_empty()).count(),
        undecided: count(DecidedBy::Undecided),
        dem_runs: dem.map_or(0, |d| d.runs),
        dem_runs_allowed: dem.map_or(0, |d| d.allowed),
        dem_rounds: dem.map_or(0, |d| d.rounds),
        band: kn
            .as_ref()
            .map_or_else(super::Band::global, |k| k.band.clone()),
        pairs: kn.map(|k| k.pairs).unwrap_or_default(),
        dem_check_load_mN: dem.and_then(|d| d.check_load).filter(|_| total > 0).map(mn),
        dem_check_load_given: dem.is_some_and(|d| d.check_load_given),
        dem_check_passed: passed,
        dem_check_total: total,
        dem_check_interval: (total > 0).then(|| {
            let (lo, hi) = interval::clopper_pearson(passed, total, p.confidence);
            [lo, hi]
        }),
        dem_check_consistent: qc.consistent,
        quote_lowered_by_check: qc.lowered,
        dem_check_runs: runs,
        lowest_dem_failure: lowest_failure(devices),
        dem: dem.is_some(),
        censored: devices.iter().filter(|d| d.estimate.censored).count(),
        fabrication: p.fabrication.record(scene),
        curve: curve(&sorted, qc.load, p.confidence),
    };
    YieldOutcome {
        rows,
        summary,
        estimates: devices.iter().map(|d| d.estimate.estimates).sum(),
    }
}
