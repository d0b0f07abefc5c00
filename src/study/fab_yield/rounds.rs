//! Where the DEM runs of a yield go ([`Rounds`]): to the devices that can set the quote and its
//! bound, until each of those is located by the DEM or shown above them.
//!
//! The quote is the critical load of rank ρ_q = n − ⌈q n⌉ + 1 from the bottom, its bound that of
//! the Wilks rank r ([`super::interval`]): only the lowest K = max(ρ_q, r) critical loads set
//! them ([`setting_ranks`]). Each device's DEM critical load lies in [low, high]
//! ([`super::Device::bounds`]: the band transferred through its estimate, narrowed by its DEM
//! runs). With T the K-th lowest `high`, a device whose `low` ≥ T cannot be among the lowest K;
//! every other one is **undecided**. Each round, the undecided devices with the lowest
//! predictions ([`super::Device::predicted`]) get runs, side by side:
//! - one predicted at or above T: a run at T (held: it is above; failed: it is located next);
//! - else its location: a first run at its prediction (the band's bias-corrected centre
//!   transferred through its estimate), then three runs a resolution apart around the
//!   prediction its own margin gives (W*·(1 − r), W*, W*·(1 + r), inside what is known), so
//!   that a good prediction locates it in one round; bisection once its bracket is within
//!   twice the resolution, or after [`STRADDLES`] such rounds.
//!
//! After each round the band is calibrated again on every run's pair ([`super::calibration`]),
//! which narrows the other devices' brackets. It ends when no device is undecided, or when
//! the runs allowed are spent (the undecided then keep the lower end of what is known, and the
//! summary counts them). Cost: about 3 runs per located device and 1 per device shown above
//! T, plus the first rounds' runs under the global band.

use super::calibration::{Band, BandSource, Pair};
use super::dem_decide::{Ask, Decision, DemDecider};
use super::device::{Bounds, Device};
use super::interval;
use super::row::DecidedBy;
use crate::runs::progress::Progress;
use anyhow::Result;
use surrogate::units::n_to_mn;

/// Runs a located device may get as straddles before bisection takes over.
pub const STRADDLES: usize = 2;

/// The number of lowest critical loads that set the quote at `q` and its bound at confidence
/// `confidence` among `n` devices: max(n − ⌈q n⌉ + 1, Wilks rank), at least 1.
pub fn setting_ranks(n: usize, q: f64, confidence: f64) -> usize {
    let need = ((q * n as f64) - 1e-9).ceil().clamp(1.0, n.max(1) as f64) as usize;
    let quote_rank = n.saturating_sub(need) + 1;
    quote_rank
        .max(interval::wilks_rank(n, q, confidence).unwrap_or(0))
        .max(1)
}

/// The quoted load (N) of `values` at q: the load a fraction q hold ([`interval::quantile_load`];
/// `None` when none holds any load).
pub fn quote(values: &[(f64, DecidedBy)], q: f64) -> Option<f64> {
    let mut w: Vec<f64> = values.iter().map(|v| v.0).collect();
    w.sort_by(f64::total_cmp);
    interval::quantile_load(&w, q).filter(|&w| w > 0.0)
}

/// What is known of every device at one moment: the band, each device's bounds and the
/// threshold T (N).
#[derive(Debug, Clone)]
pub struct Knowledge {
    /// The band calibrated on every pair so far.
    pub band: Band,
    /// Every pair so far.
    pub pairs: Vec<Pair>,
    /// Each device's bounds.
    pub bounds: Vec<Bounds>,
    /// The K-th lowest upper end (N).
    pub threshold: f64,
}

impl Knowledge {
    /// What `devices` tell with `k` setting ranks, μ_sl `mu_sl` and the resolution.
    pub fn of(devices: &[Device], k: usize, mu_sl: f64, resolution: f64) -> Knowledge {
        let pairs: Vec<Pair> = devices.iter().flat_map(Device::pairs).collect();
        let band = Band::calibrated(&pairs);
        let bounds: Vec<Bounds> = devices
            .iter()
            .map(|d| d.bounds(&band, mu_sl, resolution))
            .collect();
        let mut highs: Vec<f64> = bounds.iter().map(|b| b.high).collect();
        highs.sort_by(f64::total_cmp);
        let threshold = highs
            .get(k.clamp(1, highs.len().max(1)) - 1)
            .copied()
            .unwrap_or(0.0);
        Knowledge {
            band,
            pairs,
            bounds,
            threshold,
        }
    }

    /// The devices that could still be among the lowest K: not located, lower end below T.
    pub fn undecided(&self) -> Vec<usize> {
        (0..self.bounds.len())
            .filter(|&i| !self.bounds[i].located && self.bounds[i].low < self.threshold)
            .collect()
    }

    /// Each device's critical load (N) as the yield counts it and who set it: located → its
    /// DEM value; at or above T → the estimate's (its W_c under the global band, else the
    /// band's centre transferred), kept inside its bounds; undecided (the runs were spent) →
    /// the lower end of its bounds (where the DEM failed it below its band, its own margin's
    /// prediction less twice the `resolution`).
    pub fn values(&self, devices: &[Device], mu_sl: f64, resolution: f64) -> Vec<(f64, DecidedBy)> {
        devices
            .iter()
            .zip(&self.bounds)
            .map(|(d, b)| {
                if b.located {
                    (b.low, DecidedBy::Located)
                } else if b.low >= self.threshold {
                    let w = match self.band.source {
                        BandSource::Global => d.estimate.load,
                        BandSource::Design => d.limit_with(self.band.centre(), mu_sl),
                    };
                    let by = if d.dem.is_empty() {
                        DecidedBy::Estimate
                    } else {
                        DecidedBy::Dem
                    };
                    (w.clamp(b.low, b.high), by)
                } else if b.low > 0.0 {
                    // the runs are spent: the floor of what is known (conservative)
                    (b.low, DecidedBy::Undecided)
                } else {
                    // the DEM failed it below its band: its own margin's prediction, less
                    // twice the resolution
                    let w = d.predicted(&self.band, mu_sl) * (1.0 - 2.0 * resolution);
                    (w.clamp(0.0, b.high), DecidedBy::Undecided)
                }
            })
            .collect()
    }
}

/// What runs the DEM for the rounds: [`DemDecider`], or a known function in the tests.
pub trait DemOracle {
    /// One decision per ask, in order, run under the progress stage `stage`.
    fn decide(&self, asks: &[Ask], stage: &str, progress: &dyn Progress) -> Result<Vec<Decision>>;
}

impl DemOracle for DemDecider<'_> {
    fn decide(&self, asks: &[Ask], stage: &str, progress: &dyn Progress) -> Result<Vec<Decision>> {
        self.run(asks, stage, progress)
    }
}

/// The DEM rounds of one yield (module docs).
pub struct Rounds<'a> {
    /// Runs the DEM.
    pub decider: &'a dyn DemOracle,
    /// μ_sl of the verdict.
    pub mu_sl: f64,
    /// Resolution of a located critical load (fraction of the load).
    pub resolution: f64,
    /// Runs made so far (the check's included).
    pub runs: usize,
    /// Rounds made so far.
    pub rounds: usize,
}

impl<'a> Rounds<'a> {
    /// No rounds yet, on `decider`, with the verdict's μ_sl and the yield's resolution.
    pub fn new(decider: &'a dyn DemOracle, mu_sl: f64, resolution: f64) -> Self {
        Rounds {
            decider,
            mu_sl,
            resolution,
            runs: 0,
            rounds: 0,
        }
    }

    /// The loads (N) device `d` (bounds `b`) is run at this round (module docs).
    fn loads_for(&self, d: &Device, b: &Bounds, k: &Knowledge) -> Vec<f64> {
        let t = k.threshold;
        let pred = d.predicted(&k.band, self.mu_sl);
        let (a, f) = (d.held(), d.failed());
        let r = self.resolution;
        if pred >= t && f.is_none_or(|f| f > t) {
            return vec![t];
        }
        let mut x = if pred > 0.0 {
            pred
        } else {
            0.5 * d.estimate.load
        };
        if d.dem.is_empty() {
            return if x > 0.0 {
                vec![x.max(b.low)]
            } else {
                Vec::new()
            };
        }
        let straddles = d.dem.len().saturating_sub(1) / 3;
        match (a, f) {
            (Some(a), Some(f)) if f - a <= 2.0 * r * f || straddles >= STRADDLES => {
                vec![0.5 * (a + f)]
            }
            (Some(a), None) if straddles >= STRADDLES => vec![x.max(1.05 * a)],
            (None, Some(f)) if straddles >= STRADDLES => vec![x.min(0.95 * f)],
            _ => {
                // three runs a resolution apart around the prediction, inside the bracket:
                // two neighbours that disagree locate it
                if let Some(a) = a {
                    x = x.max(a / (1.0 - r));
                }
                if let Some(f) = f {
                    x = x.min(f / (1.0 + r));
                }
                [x * (1.0 - r), x, x * (1.0 + r)]
                    .into_iter()
                    .filter(|&w| a.is_none_or(|a| w > a) && f.is_none_or(|f| w < f))
                    .collect()
            }
        }
    }

    /// Runs rounds on `devices` with `k` setting ranks until none is undecided or `allowed`
    /// runs are made (module docs). Progress: a note per round and the DEM's stages.
    pub fn run(
        &mut self,
        devices: &mut [Device],
        k: usize,
        allowed: usize,
        progress: &dyn Progress,
    ) -> Result<()> {
        // each device at most a few runs per round; enough rounds for any device to be located
        for _ in 0..64 {
            let kn = Knowledge::of(devices, k, self.mu_sl, self.resolution);
            let mut todo = kn.undecided();
            let budget = allowed.saturating_sub(self.runs);
            if todo.is_empty() || budget == 0 {
                break;
            }
            let pred: Vec<f64> = todo
                .iter()
                .map(|&i| devices[i].predicted(&kn.band, self.mu_sl))
                .collect();
            let mut order: Vec<usize> = (0..todo.len()).collect();
            order.sort_by(|&x, &y| pred[x].total_cmp(&pred[y]).then(todo[x].cmp(&todo[y])));
            todo = order.into_iter().map(|x| todo[x]).take(k + 1).collect();
            let mut plan: Vec<(usize, f64)> = Vec::new();
            for &i in &todo {
                for w in self.loads_for(&devices[i], &kn.bounds[i], &kn) {
                    let fresh = !devices[i].dem.iter().any(|r| r.load == w);
                    if fresh && w > 0.0 && plan.len() < budget {
                        plan.push((i, w));
                    }
                }
            }
            if plan.is_empty() {
                break;
            }
            self.rounds += 1;
            progress.note(&format!(
                "yield: DEM round {}: {} run(s) on {} device(s) that could set the quote or its bound (below {:.3} mN; band {})",
                self.rounds,
                plan.len(),
                todo.len(),
                n_to_mn(kn.threshold),
                match kn.band.source {
                    BandSource::Global => "global".to_string(),
                    BandSource::Design => format!("from {} pairs", kn.band.pairs),
                }
            ));
            self.execute(devices, &plan, "yield: DEM location", progress)?;
        }
        Ok(())
    }

    /// Runs the `plan` (device, load N) side by side and records each run on its device;
    /// returns why each run was not superlubric (empty where it was), in plan order.
    pub fn execute(
        &mut self,
        devices: &mut [Device],
        plan: &[(usize, f64)],
        stage: &str,
        progress: &dyn Progress,
    ) -> Result<Vec<String>> {
        let asks: Vec<Ask> = plan
            .iter()
            .map(|&(i, w)| Ask {
                sample: &devices[i].sample,
                load: w,
                mount_resonance: devices[i].estimate.resonant_at(w),
            })
            .collect();
        let decisions = self.decider.decide(&asks, stage, progress)?;
        self.runs += decisions.len();
        let mut why = Vec::with_capacity(plan.len());
        for (&(i, _), d) in plan.iter().zip(decisions) {
            devices[i].dem.push(d.run);
            why.push(d.why);
        }
        Ok(why)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 59 devices at 95 %/95 %: the quote is the 3rd lowest and the bound the lowest; 69
    /// devices: the 4th and the lowest; 20 devices (no bound): the 2nd; 200: the 11th.
    #[test]
    fn the_setting_ranks_follow_the_order_statistics() {
        assert_eq!(setting_ranks(59, 0.95, 0.95), 3);
        assert_eq!(setting_ranks(69, 0.95, 0.95), 4);
        assert_eq!(setting_ranks(20, 0.95, 0.95), 2);
        assert_eq!(setting_ranks(200, 0.95, 0.95), 11);
    }
}
