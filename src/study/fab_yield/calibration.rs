//! The estimate calibrated for one design by its own DEM runs ([`Pair`], [`Band`]).
//!
//! Every DEM run of a yield is a pair: the DEM's P_max and μ on a device at a load, beside the
//! estimate's on the same device at the same load ([`super::margin::estimate_at`]). From the
//! pairs' ratios ρ = P_DEM/P_est and m = μ_est/μ_DEM the design gets its own band: the
//! smallest and the largest ratio seen (split-conformal with the full range as the interval:
//! for m exchangeable pairs, a fresh device's ratio lies inside [min, max] with probability
//! ≥ (m − 1)/(m + 1), the band's stated coverage), and its bias correction, the median ratio.
//! Below [`MIN_PAIRS`] pairs the global band of the verdict (`P_RATIO`, `MU_RATIO`, measured
//! over the study's DEM comparisons) stands, with the pairs' median ratio as its centre (the
//! identity without pairs). Cost: a sort of the pairs.

use super::margin::Ratios;
use crate::study::verdict::{MU_RATIO, P_RATIO};
use serde::{Deserialize, Serialize};

/// Fewest pairs for a design's own band (coverage (m − 1)/(m + 1) = 82 % at 10).
pub const MIN_PAIRS: usize = 10;

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
    /// Pairs it was made from.
    pub pairs: usize,
    /// [lowest, highest] ρ = P_DEM/P_est.
    pub p_ratio: [f64; 2],
    /// [lowest, highest] m = μ_est/μ_DEM.
    pub mu_ratio: [f64; 2],
    /// The bias correction: median ρ and m of the pairs (1 without pairs).
    pub centre: [f64; 2],
    /// Probability that a fresh pair lies in the band, (m − 1)/(m + 1) (`null`: global band,
    /// whose coverage is that of the study's comparison).
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
        }
    }

    /// The band of `pairs` (module docs): the design's own from [`MIN_PAIRS`] pairs with finite
    /// ratios on, else the global one.
    pub fn calibrated(pairs: &[Pair]) -> Band {
        let ok: Vec<&Pair> = pairs
            .iter()
            .filter(|p| {
                let (a, b) = (p.p_ratio(), p.mu_ratio());
                a.is_finite() && a > 0.0 && b.is_finite() && b > 0.0
            })
            .collect();
        let m = ok.len();
        if m == 0 {
            return Band::global();
        }
        if m < MIN_PAIRS {
            // too few for a band, enough for a bias correction of the predictions
            return Band {
                centre: [
                    median(ok.iter().map(|p| p.p_ratio()).collect()),
                    median(ok.iter().map(|p| p.mu_ratio()).collect()),
                ],
                ..Band::global()
            };
        }
        let range = |f: fn(&Pair) -> f64| {
            let v: Vec<f64> = ok.iter().map(|p| f(p)).collect();
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            ([lo, hi], median(v))
        };
        let (p_ratio, pc) = range(Pair::p_ratio);
        let (mu_ratio, mc) = range(Pair::mu_ratio);
        Band {
            source: BandSource::Design,
            pairs: m,
            p_ratio,
            mu_ratio,
            centre: [pc, mc],
            coverage: Some((m as f64 - 1.0) / (m as f64 + 1.0)),
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
        let many: Vec<Pair> = (0..19).map(|i| pair(1.0 + 0.001 * i as f64, 0.9)).collect();
        let b = Band::calibrated(&many);
        assert_eq!(b.source, BandSource::Design);
        assert!((b.p_ratio[0] - 1.0).abs() < 1e-12 && (b.p_ratio[1] - 1.018).abs() < 1e-12);
        assert!((b.centre[0] - 1.009).abs() < 1e-12);
        assert!((b.coverage.unwrap() - 0.9).abs() < 1e-12);
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
                .map(|_| pair(1.0 + 0.03 * rng.random::<f64>().powi(2), 0.9))
                .collect();
            let b = Band::calibrated(&pairs);
            let fresh = 1.0 + 0.03 * rng.random::<f64>().powi(2);
            inside += usize::from(fresh >= b.p_ratio[0] && fresh <= b.p_ratio[1]);
        }
        let rate = inside as f64 / trials as f64;
        // 3 σ of a binomial at 0.9 over 4000 trials is 0.014
        assert!(rate >= 0.9 - 0.014, "coverage {rate}");
    }
}
