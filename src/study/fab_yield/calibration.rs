//! The estimate calibrated for one design by its own DEM runs ([`Pair`], [`Band`]).
//!
//! Every DEM run of a yield is a pair: the DEM's P_max and μ on a device at a load, beside the
//! estimate's on the same device at the same load ([`super::margin::estimate_at`]). From the
//! pairs' ratios ρ = P_DEM/P_est and m = μ_est/μ_DEM the design gets its own band: the
//! smallest and the largest ratio seen (split-conformal with the full range as the interval:
//! for ratios of d exchangeable devices, a fresh device's ratio lies inside [min, max] with
//! probability ≥ (d − 1)/(d + 1); d counts devices, not pairs, since one device's runs at
//! nearby loads repeat its ratio), and its bias correction, the median ratio.
//!
//! **The stated coverage counts the devices drawn at random**: the check's, run first at the
//! estimate's quote ([`super::dem_part`]). The rounds' devices are chosen by their estimate (the
//! lowest first), so their ratios are not exchangeable with a fresh device's; they can only
//! widen the range. With c ≥ 2 check devices among the pairs the coverage is (c − 1)/(c + 1);
//! without (no check) it counts every device.
//!
//! The band maps the estimate onto the DEM where the DEM's verdict turns, so it is made from
//! the pairs of that regime:
//! - **the coating held** (P_DEM ≤ P_crit): once a contact passes P_crit the DEM switches its
//!   μ, and the run's P_max and μ then measure the failure, not the estimate's error (on the
//!   default tri-tri design ρ jumps from 1.005 to 1.018 and m from 0.97 to 0.84 at the
//!   failing load). Such a run is censored: it shows ρ ≥ P_crit/P_est, which the band's upper
//!   ρ covers;
//! - **for ρ, the estimate within [`NEAR_P_CRIT`] of P_crit** (a class of the pairs by their
//!   estimate, as in Mondrian conformal prediction): the crossing ρ·P_est = P_crit lies there,
//!   and a device far below P_crit (high friction, a stiffer contact set) has a ρ of its own
//!   (1.044 at P_est = 0.82 P_crit on the default tri-tri design). With fewer than
//!   [`MIN_PAIRS`] such pairs, every pair whose coating held.
//!
//! Below [`MIN_PAIRS`] pairs whose coating held the global band of the verdict (`P_RATIO`,
//! `MU_RATIO`, measured over the study's DEM comparisons) stands, with the pairs' median ratio
//! as its centre (the identity without pairs). Cost: a sort of the pairs.

use super::margin::Ratios;
use crate::study::verdict::{MU_RATIO, P_RATIO};
use serde::{Deserialize, Serialize};

/// Fewest pairs for a design's own band (from 10 devices, coverage (d − 1)/(d + 1) = 82 %).
pub const MIN_PAIRS: usize = 10;

/// The pairs of the band's ρ: those whose estimated P_max is at least this fraction of P_crit
/// (the crossing ρ·P_est = P_crit lies there for ρ up to 1/0.95 = 1.053, above the global
/// band's 1.048).
pub const NEAR_P_CRIT: f64 = 0.95;

/// One DEM run beside the estimate at the same device and load.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct Pair {
    /// The device (its sample index).
    pub sample: usize,
    /// Load (mN).
    pub load_mN: f64,
    /// The estimate's path P_max there (GPa, interpolated between its probes).
    pub p_max_estimate_GPa: f64,
    /// The DEM's largest P_max (GPa).
    pub p_max_dem_GPa: f64,
    /// μ_est there (interpolated).
    pub mu_estimate: f64,
    /// μ_DEM.
    pub mu_dem: f64,
    /// The device's P_crit (GPa).
    pub p_crit_GPa: f64,
    /// Whether its device is one of the check's: drawn at random, not chosen by its estimate.
    #[serde(default)]
    pub check: bool,
}

impl Pair {
    /// ρ = P_DEM/P_est.
    pub fn p_ratio(&self) -> f64 {
        self.p_max_dem_GPa / self.p_max_estimate_GPa
    }

    /// m = μ_est/μ_DEM.
    pub fn mu_ratio(&self) -> f64 {
        self.mu_estimate / self.mu_dem
    }

    /// The ratios of this pair (the margin of its run).
    pub fn ratios(&self) -> Ratios {
        Ratios {
            p: self.p_ratio(),
            mu: self.mu_ratio(),
        }
    }

    /// Whether the DEM's coating held in this run (P_DEM ≤ P_crit): its ratios measure the
    /// estimate's error (module docs).
    pub fn coating_held(&self) -> bool {
        self.p_max_dem_GPa <= self.p_crit_GPa
    }

    /// Whether its estimate lies where the coating's verdict turns (P_est ≥ [`NEAR_P_CRIT`]·P_crit).
    pub fn near_p_crit(&self) -> bool {
        self.p_max_estimate_GPa >= NEAR_P_CRIT * self.p_crit_GPa
    }

    /// The least ρ that explains a coating failure, P_crit/P_est (a censored ρ).
    fn censored_p_ratio(&self) -> f64 {
        self.p_crit_GPa / self.p_max_estimate_GPa
    }
}

/// Where a band comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum BandSource {
    /// The verdict's global band (too few pairs).
    Global,
    /// This design's own DEM runs.
    Design,
}

/// The estimate's band for one design: the ratios a fresh device's DEM may take.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Band {
    /// Where it comes from.
    pub source: BandSource,
    /// Pairs its ρ was made from (module docs).
    pub pairs: usize,
    /// Pairs whose coating held: those of its m, and of its centre (0: the centre is not
    /// calibrated).
    pub held_pairs: usize,
    /// [lowest, highest] ρ = P_DEM/P_est.
    pub p_ratio: [f64; 2],
    /// [lowest, highest] m = μ_est/μ_DEM.
    pub mu_ratio: [f64; 2],
    /// The bias correction: median ρ and m of the pairs (1 without pairs).
    pub centre: [f64; 2],
    /// Devices its ρ pairs come from (d).
    pub devices: usize,
    /// Of those, the check's, drawn at random (c).
    #[serde(default)]
    pub random_devices: usize,
    /// Probability that a fresh device's ratio lies in the band: (c − 1)/(c + 1) with c ≥ 2,
    /// else (d − 1)/(d + 1) (module docs; `null`: global band, whose coverage is that of the
    /// study's comparison).
    pub coverage: Option<f64>,
}

/// The median of `v` (non-empty).
fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

impl Band {
    /// The verdict's global band.
    pub fn global() -> Band {
        Band {
            source: BandSource::Global,
            pairs: 0,
            p_ratio: [P_RATIO.0, P_RATIO.1],
            mu_ratio: [MU_RATIO.0, MU_RATIO.1],
            centre: [1.0, 1.0],
            coverage: None,
            held_pairs: 0,
            devices: 0,
            random_devices: 0,
        }
    }

    /// The band of `pairs` (module docs): the design's own from [`MIN_PAIRS`] pairs whose
    /// coating held, else the global one.
    pub fn calibrated(pairs: &[Pair]) -> Band {
        let ok: Vec<&Pair> = pairs
            .iter()
            .filter(|p| {
                let (a, b) = (p.p_ratio(), p.mu_ratio());
                a.is_finite() && a > 0.0 && b.is_finite() && b > 0.0
            })
            .collect();
        let held: Vec<&Pair> = ok.iter().copied().filter(|p| p.coating_held()).collect();
        let near: Vec<&Pair> = held.iter().copied().filter(|p| p.near_p_crit()).collect();
        let rho = if near.len() >= MIN_PAIRS {
            near
        } else {
            held.clone()
        };
        let m = rho.len();
        let ratios = |v: &[&Pair], f: fn(&Pair) -> f64| v.iter().map(|p| f(p)).collect::<Vec<_>>();
        if m < MIN_PAIRS {
            // too few for a band, enough for a bias correction of the predictions; where no
            // coating held, the least ρ that explains the failures and no μ correction
            let centre = if !held.is_empty() {
                [
                    median(ratios(&held, Pair::p_ratio)),
                    median(ratios(&held, Pair::mu_ratio)),
                ]
            } else if !ok.is_empty() {
                [median(ratios(&ok, Pair::censored_p_ratio)), 1.0]
            } else {
                return Band::global();
            };
            return Band {
                centre,
                held_pairs: held.len(),
                ..Band::global()
            };
        }
        let range = |v: &[f64]| {
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            [lo, hi]
        };
        let devices = |check_only: bool| {
            let mut s: Vec<usize> = rho
                .iter()
                .filter(|p| p.check || !check_only)
                .map(|p| p.sample)
                .collect();
            s.sort_unstable();
            s.dedup();
            s.len()
        };
        let (d, c) = (devices(false), devices(true));
        let counted = if c >= 2 { c } else { d };
        let (p, mu) = (ratios(&rho, Pair::p_ratio), ratios(&held, Pair::mu_ratio));
        let mut p_ratio = range(&p);
        // a coating failure shows ρ ≥ P_crit/P_est: the upper end covers it
        p_ratio[1] = ok
            .iter()
            .filter(|p| !p.coating_held())
            .map(|p| p.censored_p_ratio())
            .fold(p_ratio[1], f64::max);
        Band {
            source: BandSource::Design,
            pairs: m,
            held_pairs: held.len(),
            p_ratio,
            mu_ratio: range(&mu),
            centre: [median(p), median(mu)],
            devices: d,
            random_devices: c,
            coverage: Some((counted as f64 - 1.0) / (counted as f64 + 1.0)),
        }
    }

    /// The DEM at its worst against the estimate (highest P_DEM, highest μ_DEM).
    pub fn worst(&self) -> Ratios {
        Ratios {
            p: self.p_ratio[1],
            mu: self.mu_ratio[0],
        }
    }

    /// The DEM at its best against the estimate.
    pub fn best(&self) -> Ratios {
        Ratios {
            p: self.p_ratio[0],
            mu: self.mu_ratio[1],
        }
    }

    /// The bias-corrected centre.
    pub fn centre(&self) -> Ratios {
        Ratios {
            p: self.centre[0],
            mu: self.centre[1],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn pair(rho: f64, m: f64) -> Pair {
        Pair {
            sample: 0,
            load_mN: 1.0,
            p_max_estimate_GPa: 4.0,
            p_max_dem_GPa: 4.0 * rho,
            mu_estimate: 0.01,
            mu_dem: 0.01 / m,
            p_crit_GPa: 4.0 * rho.max(1.0),
            check: false,
        }
    }

    /// Too few pairs keep the global band (their median its centre); enough give their
    /// range, median and coverage.
    #[test]
    fn the_band_is_the_pairs_range() {
        let few: Vec<Pair> = (0..MIN_PAIRS - 1).map(|_| pair(1.01, 0.9)).collect();
        let b = Band::calibrated(&few);
        assert_eq!(b.source, BandSource::Global);
        assert_eq!(
            (b.p_ratio, b.mu_ratio),
            (Band::global().p_ratio, Band::global().mu_ratio)
        );
        assert!((b.centre[0] - 1.01).abs() < 1e-12 && (b.centre[1] - 0.9).abs() < 1e-12);
        assert_eq!(Band::calibrated(&[]), Band::global());
        let mut many: Vec<Pair> = (0..19).map(|i| pair(1.0 + 0.001 * i as f64, 0.9)).collect();
        for (i, p) in many.iter_mut().enumerate() {
            p.sample = i;
        }
        let b = Band::calibrated(&many);
        assert_eq!(b.source, BandSource::Design);
        assert!((b.p_ratio[0] - 1.0).abs() < 1e-12 && (b.p_ratio[1] - 1.018).abs() < 1e-12);
        assert!((b.centre[0] - 1.009).abs() < 1e-12);
        assert!((b.coverage.unwrap() - 0.9).abs() < 1e-12);
        // the same pairs from 4 devices: the same band, a coverage of (4 − 1)/(4 + 1)
        for (i, p) in many.iter_mut().enumerate() {
            p.sample = i % 4;
        }
        let b = Band::calibrated(&many);
        assert_eq!((b.devices, b.p_ratio[1]), (4, 1.0 + 0.001 * 18.0));
        assert!((b.coverage.unwrap() - 0.6).abs() < 1e-12);
        // 19 devices of which 3 the check's (drawn at random): the coverage counts those 3
        for (i, p) in many.iter_mut().enumerate() {
            p.sample = i;
            p.check = i >= 16;
        }
        let b = Band::calibrated(&many);
        assert_eq!((b.devices, b.random_devices), (19, 3));
        assert!((b.coverage.unwrap() - 0.5).abs() < 1e-12);
    }

    /// The band is made from the regime where the verdict turns: a run whose coating failed
    /// (its P_max and μ jumped with the switched μ) widens neither ratio, except that its
    /// least explaining ρ, P_crit/P_est, bounds the upper ρ; a pair far below P_crit (a
    /// friction-bound device with a ρ of its own) sets no ρ once enough pairs lie near P_crit,
    /// but still sets m.
    #[test]
    fn the_band_leaves_out_failed_coatings_and_far_pairs() {
        let near: Vec<Pair> = (0..MIN_PAIRS)
            .map(|i| pair(1.004 + 0.0002 * i as f64, 0.98))
            .collect();
        let failed = Pair {
            p_max_estimate_GPa: 3.99,
            p_max_dem_GPa: 4.07,
            mu_dem: 0.012,
            ..pair(1.0, 1.0)
        };
        let far = Pair {
            p_max_estimate_GPa: 3.28,
            p_max_dem_GPa: 3.28 * 1.044,
            mu_dem: 0.01 / 0.84,
            ..pair(1.0, 1.0)
        };
        let mut all = near.clone();
        all.extend([failed.clone(), far.clone()]);
        let b = Band::calibrated(&all);
        assert_eq!(
            (b.source, b.pairs, b.held_pairs),
            (BandSource::Design, MIN_PAIRS, MIN_PAIRS + 1)
        );
        assert!((b.p_ratio[0] - 1.004).abs() < 1e-12, "{b:?}");
        // the failure's censored ρ, 4/3.99 = 1.0025, lies inside: the near pairs' 1.0058 stands
        assert!((b.p_ratio[1] - 1.0058).abs() < 1e-12, "{b:?}");
        // m: the far pair (0.84) counts, the failed run's (0.01/0.012 = 0.83) does not
        assert!((b.mu_ratio[0] - 0.84).abs() < 1e-12, "{b:?}");
        // a failure the near pairs do not explain lifts the upper ρ to its censored value
        let deep = Pair {
            p_max_estimate_GPa: 3.9,
            p_max_dem_GPa: 4.1,
            ..pair(1.0, 1.0)
        };
        let mut with = near.clone();
        with.push(deep);
        let b = Band::calibrated(&with);
        assert!((b.p_ratio[1] - 4.0 / 3.9).abs() < 1e-12, "{b:?}");
        // without pairs whose coating held, the centre is the failures' least ρ and no μ
        // correction
        let b = Band::calibrated(&[failed]);
        assert_eq!(b.source, BandSource::Global);
        assert!((b.centre[0] - 4.0 / 3.99).abs() < 1e-12 && b.centre[1] == 1.0);
        assert_eq!(b.held_pairs, 0);
    }

    /// The stated coverage holds: over seeded repeats, a fresh ratio from the same law falls in
    /// the band of 19 pairs at least 90 % of the time (less the Monte Carlo noise).
    #[test]
    fn the_coverage_holds_over_repeats() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let trials = 4000;
        let mut inside = 0;
        for _ in 0..trials {
            let pairs: Vec<Pair> = (0..19)
                .map(|i| Pair {
                    sample: i,
                    ..pair(1.0 + 0.03 * rng.random::<f64>().powi(2), 0.9)
                })
                .collect();
            let b = Band::calibrated(&pairs);
            assert_eq!(b.coverage, Some(0.9));
            let fresh = 1.0 + 0.03 * rng.random::<f64>().powi(2);
            inside += usize::from(fresh >= b.p_ratio[0] && fresh <= b.p_ratio[1]);
        }
        let rate = inside as f64 / trials as f64;
        // 3 σ of a binomial at 0.9 over 4000 trials is 0.014
        assert!(rate >= 0.9 - 0.014, "coverage {rate}");
    }
}
