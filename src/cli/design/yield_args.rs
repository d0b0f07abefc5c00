//! The flags of `design`'s opt-in yield stage ([`crate::study::design::yield_stage`]).

use super::super::checks;
use crate::study::design::yield_params::RankBy;
use crate::study::design::yield_stage::YieldStageParams;
use crate::study::fab_yield::DEFAULT_RESOLUTION;
use anyhow::{bail, Result};

/// `--yield-samples` (turns the stage on) and its knobs.
#[derive(clap::Args, Debug, Clone)]
#[group(skip)]
#[command(group(clap::ArgGroup::new("yield_on").args(["yield_samples", "rank_by"]).multiple(true)))]
pub struct YieldArgs {
    /// Compute the yield of each answer over fabrication with N devices (θ and pull-direction
    /// offsets uniform over the tolerance box, each on a fresh substrate whose seed the design
    /// did not search): the answer table gets the load at yield --yield-quantile with its
    /// confidence bound, and yield_<p>.csv/.json/.png are written (59 gives the one-sided
    /// 95 %/95 % bound). Off by default: with the DEM its decisions take minutes per answer.
    #[arg(long = "yield-samples", value_name = "N")]
    pub yield_samples: Option<usize>,
    /// With --yield-samples: q in (0, 1), the fraction of devices the quoted load must hold.
    #[arg(
        long = "yield-quantile",
        value_name = "Q",
        default_value_t = 0.95,
        allow_hyphen_values = true,
        requires = "yield_on"
    )]
    pub yield_quantile: f64,
    /// With --yield-samples: γ in (0, 1), confidence of the yield's interval and of the quoted
    /// load's bound.
    #[arg(
        long = "yield-confidence",
        value_name = "G",
        default_value_t = 0.95,
        allow_hyphen_values = true,
        requires = "yield_on"
    )]
    pub yield_confidence: f64,
    /// With --yield-samples: seed of the devices' draws (the same seed gives the same devices).
    #[arg(
        long = "yield-sample-seed",
        value_name = "SEED",
        default_value_t = 1,
        requires = "yield_on"
    )]
    pub yield_seed: u64,
    /// With --yield-samples and the DEM: fresh devices run with the DEM at each answer's quoted
    /// load as a check (0: none).
    #[arg(
        long = "yield-dem-check",
        value_name = "N",
        default_value_t = 10,
        requires = "yield_on"
    )]
    pub yield_dem_check: usize,
    /// What orders each pattern's designs: `worst-case` (the robust limit over the tolerance
    /// box and the searched seeds) or `yield` (the top max(--confirm, 3) designs by the load
    /// at --yield-quantile yield, its confidence bound, by the estimate; the robust order among
    /// equals). `yield` turns the yield stage on with --yield-samples devices (59 if not
    /// given) and costs the estimate's part of a yield per ranked design (seconds each)
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

/// Devices of `--rank-by yield` without `--yield-samples`: the fewest that give a one-sided
/// 95 %/95 % bound (Wilks).
const RANK_BY_YIELD_SAMPLES: usize = 59;

impl YieldArgs {
    /// The stage's knobs, checked (`None`: no --yield-samples, the stage does not run).
    pub fn params(&self) -> Result<Option<YieldStageParams>> {
        let rank_by = match self.rank_by {
            None | Some(RankByArg::WorstCase) => RankBy::WorstCase,
            Some(RankByArg::Yield) => RankBy::Yield,
        };
        let samples = match (self.yield_samples, rank_by) {
            (Some(n), _) => n,
            (None, RankBy::Yield) => RANK_BY_YIELD_SAMPLES,
            (None, RankBy::WorstCase) => return Ok(None),
        };
        if samples == 0 {
            bail!("`--yield-samples`: 0 devices; give at least 1 (59 for a 95 %/95 % bound)");
        }
        Ok(Some(YieldStageParams {
            samples,
            quantile: checks::fraction(self.yield_quantile, "--yield-quantile")?,
            confidence: checks::fraction(self.yield_confidence, "--yield-confidence")?,
            resolution: DEFAULT_RESOLUTION,
            seed: self.yield_seed,
            dem_check: self.yield_dem_check,
            rank_by,
        }))
    }
}
