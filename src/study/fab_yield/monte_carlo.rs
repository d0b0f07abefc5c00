//! The validation of a yield against the DEM alone ([`dem_monte_carlo`]): the DEM's own
//! critical load of `count` fresh devices, each located by the DEM to the resolution (held at
//! it, failed within the resolution above), and the quote and its bound set against that
//! distribution.
//!
//! The devices are drawn far from the yield's own (samples from [`FIRST_SAMPLE`] on), so none
//! was seen by the yield. Each is estimated first, only to place its DEM runs (the rounds of
//! [`super::rounds`] with every device setting the answer, so each is located); its critical
//! load is what the DEM's runs bracket, whatever the estimate said. Reported: the empirical
//! 5th percentile (linear between order statistics, position 0.05·(N − 1)), and the devices
//! holding the quote and the bound with their Clopper–Pearson intervals. Cost: `count`
//! devices' estimates and about 3–6 DEM runs per device.

use super::dem_decide::{DemDecider, YieldDem};
use super::device::Device;
use super::estimate::estimate_range;
use super::interval;
use super::params::YieldParams;
use super::rounds::{Knowledge, Rounds};
use super::row::YieldSummary;
use crate::runs::progress::Progress;
use crate::study::rows::label;
use anyhow::Result;
use serde::{Deserialize, Serialize};
use surrogate::units::n_to_mn;
use surrogate::Scene;

/// The first sample index of the Monte Carlo's devices (far above any yield's own).
pub const FIRST_SAMPLE: usize = 1_000_000;

/// One device of the Monte Carlo (`dem_monte_carlo.csv`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct McRow {
    /// Index of the device.
    pub sample: usize,
    /// θ offset (degrees).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees).
    pub direction_offset_deg: f64,
    /// Substrate seed.
    pub seed: u64,
    /// The DEM's critical load (mN): the highest load it held, failing within the resolution
    /// above.
    pub critical_load_dem_mN: f64,
    /// Whether the DEM located it (false: the runs allowed were spent).
    pub located: bool,
    /// The estimate's critical load (mN), for comparison.
    pub critical_load_estimate_mN: f64,
    /// DEM runs on the device.
    pub dem_runs: usize,
}

/// The Monte Carlo's verdict on a yield's quote.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct McSummary {
    /// Devices.
    pub devices: usize,
    /// Devices the DEM located.
    pub located: usize,
    /// DEM runs made.
    pub dem_runs: usize,
    /// The DEM critical loads' 5th percentile (mN).
    pub p5_mN: f64,
    /// The lowest DEM critical load (mN).
    pub min_mN: f64,
    /// The yield's quote (mN) and the devices holding it, with their interval.
    pub quote_mN: Option<f64>,
    /// Devices holding the quote.
    pub holding_quote: usize,
    /// Clopper–Pearson interval of that fraction.
    pub holding_quote_interval: [f64; 2],
    /// The yield's bound (mN).
    pub bound_mN: Option<f64>,
    /// Devices holding the bound.
    pub holding_bound: usize,
    /// Clopper–Pearson interval of that fraction.
    pub holding_bound_interval: [f64; 2],
    /// bound / p5.
    pub bound_over_p5: Option<f64>,
}

/// The empirical q-quantile of `sorted` (ascending, non-empty): linear between the order
/// statistics at position q·(N − 1).
fn percentile(sorted: &[f64], q: f64) -> f64 {
    let pos = q * (sorted.len() - 1) as f64;
    let (i, f) = (pos.floor() as usize, pos - pos.floor());
    let j = (i + 1).min(sorted.len() - 1);
    sorted[i] + f * (sorted[j] - sorted[i])
}

/// The DEM's own critical loads of `count` fresh devices of the yield `p` (its DEM `d`) and
/// their verdict on the yield's summary `s` (module docs).
pub fn dem_monte_carlo(
    scene: &Scene,
    p: &YieldParams,
    d: &YieldDem,
    s: &YieldSummary,
    count: usize,
    progress: &dyn Progress,
) -> Result<(Vec<McRow>, McSummary)> {
    let mut devices: Vec<Device> = estimate_range(
        scene,
        p,
        FIRST_SAMPLE..FIRST_SAMPLE + count,
        "monte carlo: estimates",
        progress,
    )?;
    let decider = DemDecider {
        scene,
        theta_deg: p.theta_deg,
        direction_deg: p.direction_deg,
        mu_superlubric: p.limit.mu_superlubric,
        dem: d,
    };
    let mut rounds = Rounds::new(&decider, p.limit.mu_superlubric, p.resolution);
    rounds.run(&mut devices, count, 20 * count, progress)?;
    let kn = Knowledge::of(&devices, count, p.limit.mu_superlubric, p.resolution);
    let rows: Vec<McRow> = devices
        .iter()
        .zip(&kn.bounds)
        .map(|(dv, b)| McRow {
            sample: dv.sample.index,
            theta_offset_deg: dv.sample.theta_offset_deg,
            direction_offset_deg: dv.sample.direction_offset_deg,
            seed: dv.sample.substrate_seed,
            critical_load_dem_mN: label(n_to_mn(b.low)),
            located: b.located,
            critical_load_estimate_mN: label(n_to_mn(dv.estimate.load)),
            dem_runs: dv.dem.len(),
        })
        .collect();
    let mut w: Vec<f64> = rows.iter().map(|r| r.critical_load_dem_mN).collect();
    w.sort_by(f64::total_cmp);
    let hold = |x: Option<f64>| x.map_or(0, |x| w.iter().filter(|&&v| v >= x).count());
    let ci = |k: usize| {
        let (lo, hi) = interval::clopper_pearson(k, count, p.confidence);
        [lo, hi]
    };
    let p5 = percentile(&w, 0.05);
    let (q, b) = (s.load_at_quantile_mN, s.load_at_quantile_bound_mN);
    let sum = McSummary {
        devices: count,
        located: rows.iter().filter(|r| r.located).count(),
        dem_runs: rounds.runs,
        p5_mN: label(p5),
        min_mN: w[0],
        quote_mN: q,
        holding_quote: hold(q),
        holding_quote_interval: ci(hold(q)),
        bound_mN: b,
        holding_bound: hold(b),
        holding_bound_interval: ci(hold(b)),
        bound_over_p5: b.map(|b| label(b / p5)),
    };
    Ok((rows, sum))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_percentile_interpolates_between_order_statistics() {
        let v: Vec<f64> = (1..=41).map(f64::from).collect();
        assert_eq!(percentile(&v, 0.05), 3.0);
        assert_eq!(percentile(&v, 0.0), 1.0);
        assert_eq!(percentile(&[1.0, 2.0], 0.5), 1.5);
    }
}
