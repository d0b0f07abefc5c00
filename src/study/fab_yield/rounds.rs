//! Where the DEM runs of a yield go ([`Rounds`]): to the devices that can set the quote and its
//! bound, until each of those is located by the DEM or shown above them.
//!
//! The quote is the critical load of rank ρ_q = n − ⌈q n⌉ + 1 from the bottom, its bound that of
//! the Wilks rank r ([`super::interval`]): only the lowest K = max(ρ_q, r) critical loads set
//! them ([`setting_ranks`]). Each device's DEM critical load lies in [low, high]
//! ([`super::Device::bounds`]: the band transferred through its estimate, narrowed by its DEM
//! runs). With T the K-th lowest `high`, a device whose `low` ≥ T·(1 − resolution) cannot be
//! among the lowest K by more than the resolution; every other one is **undecided**. Each
//! round, the K + 1 undecided devices with the lowest predictions
//! ([`super::Device::predicted`]) get runs, side by side:
//! - one predicted at or above T: a run at T (held: it is above; failed: it is located next);
//! - else its location: while no run's coating has held anywhere (the band's centre is not
//!   calibrated), one run [`GUARD`] resolutions below its prediction, which it should hold
//!   and whose pair calibrates the centre; then two runs a resolution apart around the
//!   prediction its own margin (or the calibrated centre) gives, W*·(1 ∓ r/2) inside what is
//!   known, so that a good prediction locates it in one round; bisection once its bracket is
//!   within twice the resolution, once its runs put the prediction outside what they know (a
//!   prediction shown wrong is not walked after a resolution at a time), or after
//!   [`STRADDLES`] such rounds. Where only one side is known, the bisection's other end is
//!   the band's end, or [`GUARD`] resolutions beyond the known side once the runs crossed it.
//!
//! After each round the band is calibrated again on every run's pair ([`super::calibration`]),
//! which narrows the other devices' brackets. It ends when no device is undecided, or when
//! the runs allowed are spent (the undecided then keep the lower end of what is known, and the
//! summary counts them). Cost: about 2–3 runs per located device and 1 per device shown above
//! T.

use super::calibration::{Band, BandSource, Pair};
use super::dem_decide::{Ask, Decision, DemDecider};
use super::device::{Bounds, Device, Floor};
use super::interval;
use super::row::DecidedBy;
use crate::runs::progress::Progress;
use anyhow::Result;
use surrogate::units::n_to_mn;

/// Rounds of straddles a located device may get before bisection takes over.
pub const STRADDLES: usize = 2;

/// Resolutions within which the rounds of a yield call its quote and bound sharp
/// ([`Rounds::stopping_when_sharp`]): the DEM's own accuracy, twice the resolution of a
/// located load.
pub const SHARP: f64 = 2.0;

/// Resolutions the bisection's open end is set beyond the known side where the runs have
/// crossed the band's end.
pub const GUARD: f64 = 8.0;

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
    quote_sorted(&w, q)
}

/// [`quote`] of loads already sorted ascending.
fn quote_sorted(sorted: &[f64], q: f64) -> Option<f64> {
    interval::quantile_load(sorted, q).filter(|&w| w > 0.0)
}

/// The quote at `q` ([`quote`]) and its bound at confidence `g` (the Wilks rank's order
/// statistic) of the critical loads `w` (N), each `None` where it does not exist (no load
/// held; too few devices for the bound). Cost: one sort.
pub fn answer(w: &[f64], q: f64, g: f64) -> (Option<f64>, Option<f64>) {
    let mut w = w.to_vec();
    w.sort_by(f64::total_cmp);
    let bound = interval::wilks_rank(w.len(), q, g).map(|r| w[r - 1]);
    (quote_sorted(&w, q), bound)
}

/// How far more DEM runs could still move an answer: its quote and bound as counted now
/// (undecided devices at the lower end of what is known) and at their ceiling (every
/// undecided device at the upper end), N.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sharpness {
    /// The quote and its bound as counted now.
    pub now: (Option<f64>, Option<f64>),
    /// The quote and its bound with every undecided device at its upper end.
    pub ceiling: (Option<f64>, Option<f64>),
}

impl Sharpness {
    /// The largest relative rise of the quote or the bound from `now` to `ceiling` (0 when
    /// neither can rise; infinite where one is 0 or missing now but not at the ceiling).
    pub fn gain(&self) -> f64 {
        let rise = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) if a > 0.0 => (b / a - 1.0).max(0.0),
            (_, None) => 0.0,
            _ => f64::INFINITY,
        };
        rise(self.now.0, self.ceiling.0).max(rise(self.now.1, self.ceiling.1))
    }
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
    /// The resolution (a fraction of the load): a device whose lower end lies within it below
    /// the threshold counts as above it ([`Knowledge::above`]).
    pub resolution: f64,
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
            resolution,
        }
    }

    /// Whether a device of bounds `b` lies above the lowest K: its lower end at or above T,
    /// or, where the DEM has not failed it, within the resolution below T (held a resolution
    /// below T, it sets the quote no lower than a located one would; one the DEM failed is
    /// decided by the DEM's location alone).
    pub fn above(&self, b: &Bounds) -> bool {
        let t = if b.failed {
            self.threshold
        } else {
            self.threshold * (1.0 - self.resolution)
        };
        b.low >= t
    }

    /// The devices that could still be among the lowest K: not located, not above them.
    pub fn undecided(&self) -> Vec<usize> {
        (0..self.bounds.len())
            .filter(|&i| !self.bounds[i].located && !self.above(&self.bounds[i]))
            .collect()
    }

    /// Each device's critical load (N) as the yield counts it and who set it: located → its
    /// DEM value; held within the resolution below T → the load it held; at or above T → the
    /// estimate's (its W_c under the global band, else the
    /// band's centre transferred), kept inside its bounds; undecided (the runs were spent) →
    /// the lower end of its bounds, less twice the `resolution` where that end is transferred
    /// through the estimate rather than held by the DEM (where the DEM failed it below its
    /// band, its own margin's prediction less twice the `resolution`).
    pub fn values(&self, devices: &[Device], mu_sl: f64, resolution: f64) -> Vec<(f64, DecidedBy)> {
        devices
            .iter()
            .zip(&self.bounds)
            .map(|(d, b)| {
                if b.located {
                    (b.low, DecidedBy::Located)
                } else if self.above(b) && b.low < self.threshold {
                    // held within the resolution below T: counted at the load it held
                    (b.low, DecidedBy::Dem)
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
                } else {
                    // the runs are spent: the floor of what is known (conservative); a floor
                    // transferred through the estimate, not held by the DEM, less twice the
                    // resolution, as a prediction; no floor (the DEM failed it below its band,
                    // or nothing transfers): its own margin's prediction, less twice the
                    // resolution
                    let w = match b.floor {
                        Floor::Held => b.low,
                        Floor::Transferred if b.low > 0.0 => b.low * (1.0 - 2.0 * resolution),
                        _ => {
                            let w = d.predicted(&self.band, mu_sl) * (1.0 - 2.0 * resolution);
                            w.clamp(0.0, b.high)
                        }
                    };
                    (w, DecidedBy::Undecided)
                }
            })
            .collect()
    }

    /// The quote at `q` and its bound at confidence `g` of `values` (as [`Knowledge::values`]
    /// gives them), and the same with every undecided device at the upper end of its bounds
    /// ([`Sharpness`]).
    pub fn sharpness(&self, values: &[(f64, DecidedBy)], q: f64, g: f64) -> Sharpness {
        let now: Vec<f64> = values.iter().map(|v| v.0).collect();
        let ceiling: Vec<f64> = values
            .iter()
            .zip(&self.bounds)
            .map(|(v, b)| match v.1 {
                DecidedBy::Undecided => b.high.max(v.0),
                _ => v.0,
            })
            .collect();
        Sharpness {
            now: answer(&now, q, g),
            ceiling: answer(&ceiling, q, g),
        }
    }
}

/// Where device `d`'s bisection runs (N): between its highest held and lowest failed load;
/// where only one side is known, the other is its bracket's end `b`, or, where the runs have
/// crossed that end, the known side moved by [`GUARD`] resolutions.
fn bracket(d: &Device, b: &Bounds, r: f64) -> (f64, f64) {
    let lo = |f: f64| {
        if b.low > 0.0 && b.low < f * (1.0 - 2.0 * r) {
            b.low
        } else {
            f * (1.0 - GUARD * r)
        }
    };
    let hi = |a: f64| {
        if b.high > a * (1.0 + 2.0 * r) {
            b.high
        } else {
            a * (1.0 + GUARD * r)
        }
    };
    match (d.held(), d.failed()) {
        (Some(a), Some(f)) => (a, f),
        (None, Some(f)) => (lo(f), f),
        (Some(a), None) => (a, hi(a)),
        (None, None) => (b.low, b.high),
    }
}

/// The `n` entries of `ids` with the lowest `key` (same order), ties by id.
fn lowest_of(ids: &[usize], key: &[f64], n: usize) -> Vec<usize> {
    let mut order: Vec<usize> = (0..ids.len()).collect();
    order.sort_by(|&x, &y| key[x].total_cmp(&key[y]).then(ids[x].cmp(&ids[y])));
    order.into_iter().map(|x| ids[x]).take(n).collect()
}

/// When the rounds of a yield may stop before every device is decided
/// ([`Rounds::stopping_when_sharp`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SharpStop {
    /// q of the quote.
    pub quantile: f64,
    /// γ of its bound.
    pub confidence: f64,
    /// The largest rise of either (a fraction) that more runs may still bring.
    pub within: f64,
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
    /// Stop once the undecided devices could lift neither the quote nor its bound by more
    /// than [`SharpStop::within`] and none of them has failed a DEM run (a failed device is
    /// always located); `None`: run until every device is decided or the runs are spent.
    pub sharp: Option<SharpStop>,
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
            sharp: None,
        }
    }

    /// These rounds, stopping once the quote at `q` and its bound at confidence `g` are sharp
    /// to [`SHARP`] resolutions (the undecided devices could lift neither by more).
    pub fn stopping_when_sharp(mut self, q: f64, g: f64) -> Self {
        self.sharp = Some(SharpStop {
            quantile: q,
            confidence: g,
            within: SHARP * self.resolution,
        });
        self
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
        let x = if pred > 0.0 {
            pred
        } else {
            0.5 * d.estimate.load
        };
        if x <= 0.0 {
            return Vec::new();
        }
        if d.dem.is_empty() && k.band.held_pairs == 0 {
            // nothing calibrated yet: a run the device should hold, whose pair calibrates
            return vec![(x * (1.0 - GUARD * r)).max(b.low)];
        }
        let (lo, hi) = bracket(d, b, r);
        let near = x > lo && x < hi;
        if hi - lo <= 2.0 * r * hi || !near || d.dem.len() > 3 * STRADDLES {
            // located to twice the resolution, or the prediction proved wrong: bisection
            return vec![0.5 * (lo + hi)];
        }
        // two runs a resolution apart around the prediction, inside the bracket: if they
        // disagree they locate it
        let h = 0.5 * r;
        let x = x.max(lo / (1.0 - h)).min(hi / (1.0 + h));
        [x * (1.0 - h), x * (1.0 + h)]
            .into_iter()
            .filter(|&w| a.is_none_or(|a| w > a) && f.is_none_or(|f| w < f))
            .collect()
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
            let failed = todo.iter().any(|&i| devices[i].failed().is_some());
            if let Some(stop) = self.sharp.filter(|_| !failed) {
                let values = kn.values(devices, self.mu_sl, self.resolution);
                let sharp = kn.sharpness(&values, stop.quantile, stop.confidence);
                if sharp.gain() <= stop.within {
                    progress.note(&format!(
                        "yield: DEM rounds stop: the {} undecided device(s) could lift the quote and its bound by at most {:.1} %",
                        todo.len(),
                        100.0 * sharp.gain()
                    ));
                    break;
                }
            }
            let pred: Vec<f64> = todo
                .iter()
                .map(|&i| devices[i].predicted(&kn.band, self.mu_sl))
                .collect();
            todo = lowest_of(&todo, &pred, k + 1);
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
