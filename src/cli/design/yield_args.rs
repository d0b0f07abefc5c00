//! The flags of `design`'s yield stage ([`crate::study::design::yield_stage`]), on by default.

use crate::study::design::yield_stage::RankBy;
use crate::study::design::yield_stage::YieldStageParams;
use crate::study::fab_yield::{
    bound_samples, BadKnob, YieldDem, YieldParams, DEFAULT_MAX_RUNS, DEFAULT_RESOLUTION,
};
use anyhow::{bail, Result};

/// The yield stage's flags: `--no-yield` turns it off, the others set its knobs.
#[derive(clap::Args, Debug, Clone)]
#[group(skip)]
pub struct YieldArgs {
    /// No yield: the answer table gives no load at yield, and no yield_<p> files are written
    /// (saves the estimate's part, seconds per answer, and with the DEM up to 40 DEM runs
    /// per answer).
    #[arg(long = "no-yield", conflicts_with_all = ["yield_samples", "rank_by"])]
    pub no_yield: bool,
    /// Devices drawn per answer for its yield over fabrication (θ and pull-direction offsets
    /// uniform over the tolerance box, each on a fresh substrate whose seed the design did not
    /// search). The answer table gets the load at --yield-quantile yield with its confidence
    /// bound and the DEM check; yield_<p>.csv/.json/.png are written. The default gives the
    /// one-sided 95 %/95 % bound (Wilks) [default: 59].
    #[arg(long = "yield-samples", value_name = "N")]
    pub yield_samples: Option<usize>,
    /// q in (0, 1): the fraction of devices the quoted load must hold.
    #[arg(
        long = "yield-quantile",
        value_name = "Q",
        default_value_t = 0.95,
        allow_hyphen_values = true
    )]
    pub yield_quantile: f64,
    /// γ in (0, 1): confidence of the yield's interval and of the quoted load's bound.
    #[arg(
        long = "yield-confidence",
        value_name = "G",
        default_value_t = 0.95,
        allow_hyphen_values = true
    )]
    pub yield_confidence: f64,
    /// Seed of the devices' draws (the same seed gives the same devices).
    #[arg(long = "yield-sample-seed", value_name = "SEED", default_value_t = 1)]
    pub yield_seed: u64,
    /// With the DEM: fresh devices run with the DEM at each answer's estimated quote, first,
    /// as a check and to calibrate the estimate on random devices, then pooled into its yield
    /// (0: none).
    #[arg(long = "yield-dem-check", value_name = "N", default_value_t = 10)]
    pub yield_dem_check: usize,
    /// With the DEM: most DEM runs per answer's yield, the check's included. Devices still
    /// undecided when they are spent count at the lower end of what is known (safe, less
    /// sharp; the log says how far more runs could lift the quote). On rough substrates a sharp
    /// bound needs about one run per device.
    #[arg(long = "yield-dem-max-runs", value_name = "N", default_value_t = DEFAULT_MAX_RUNS)]
    pub yield_dem_max_runs: usize,
    /// What orders each pattern's designs: `worst-case` (the robust limit over the tolerance
    /// box and the searched seeds) or `yield` (the top max(--confirm, 3) designs by the load
    /// at --yield-quantile yield, its confidence bound, by the estimate; the robust order among
    /// equals). `yield` costs the estimate's part of a yield per ranked design (seconds each)
    /// [default: worst-case]
    #[arg(long = "rank-by", value_name = "ORDER", value_enum)]
    pub rank_by: Option<RankByArg>,
}

/// `--rank-by`: what orders each pattern's designs.
#[derive(clap::ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub enum RankByArg {
    /// The robust limit: the worst case over the tolerance box and the searched seeds.
    WorstCase,
    /// The load at --yield-quantile yield over fabrication (its confidence bound).
    Yield,
}

impl YieldArgs {
    /// The stage's knobs, checked (`None`: `--no-yield`, the stage does not run).
    pub fn params(&self) -> Result<Option<YieldStageParams>> {
        if self.no_yield {
            return Ok(None);
        }
        let rank_by = match self.rank_by {
            None | Some(RankByArg::WorstCase) => RankBy::WorstCase,
            Some(RankByArg::Yield) => RankBy::Yield,
        };
        let samples = self.yield_samples.unwrap_or_else(bound_samples);
        let (q, g) = (self.yield_quantile, self.yield_confidence);
        match YieldParams::bad_knob(samples, q, g, DEFAULT_RESOLUTION) {
            Some(BadKnob::Samples) => bail!(
                "`--yield-samples`: 0 devices; give at least 1 ({} for a 95 %/95 % bound), or --no-yield",
                bound_samples()
            ),
            Some(BadKnob::Quantile) => bail!("`--yield-quantile`: {q} must lie strictly between 0 and 1"),
            Some(BadKnob::Confidence) => bail!("`--yield-confidence`: {g} must lie strictly between 0 and 1"),
            Some(BadKnob::Resolution) | None => {}
        }
        if !YieldDem::runs_hold_check(self.yield_dem_max_runs, self.yield_dem_check) {
            bail!(
                "`--yield-dem-max-runs`: {} runs cannot hold the check's {} (--yield-dem-check); give at least {}, or --no-yield",
                self.yield_dem_max_runs,
                self.yield_dem_check,
                self.yield_dem_check.max(1)
            );
        }
        Ok(Some(YieldStageParams {
            samples,
            quantile: q,
            confidence: g,
            resolution: DEFAULT_RESOLUTION,
            seed: self.yield_seed,
            dem_check: self.yield_dem_check,
            dem_max_runs: self.yield_dem_max_runs,
            rank_by,
        }))
    }
}
