//! [`YieldStageParams`]: the knobs of the design's yield stage ([`super::YieldStage`]) as the
//! user sets them, [`YieldDemParams`]: the DEM it locates devices with, and [`RankBy`].

use crate::study::dem_run::DemParams;

/// The knobs of the yield stage (the fabrication tolerance, the ladder and the DEM are the
/// design's own).
#[derive(Debug, Clone, PartialEq)]
pub struct YieldStageParams {
    /// Devices drawn per answer (≥ 1; 59 gives the one-sided 95 %/95 % bound, Wilks).
    pub samples: usize,
    /// q in (0, 1): the fraction of devices the quoted load must hold.
    pub quantile: f64,
    /// γ in (0, 1): confidence of the yield's interval and of the quoted load's bound.
    pub confidence: f64,
    /// Resolution of each device's critical load, a fraction of the load (0 < r ≤ 0.5).
    pub resolution: f64,
    /// Seed of the devices' draws (each device its own stream).
    pub seed: u64,
    /// Fresh devices run with the DEM at the estimate's quote as a check (0: none; ignored without
    /// the DEM).
    pub dem_check: usize,
    /// Most DEM runs per answer's yield, the check's included (≥ `dem_check`, ≥ 1).
    pub dem_max_runs: usize,
    /// What orders each pattern's designs ([`RankBy`]).
    pub rank_by: RankBy,
}

/// What orders a pattern's designs (`design --rank-by`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RankBy {
    /// The worst case over the tolerance box and the searched seeds: the robust limit
    /// ([`crate::study::design::model::rank::compare`]; the default).
    #[default]
    WorstCase,
    /// The load a fraction q of fabricated devices hold, its one-sided lower bound
    /// ([`crate::study::design::ranking::by_yield`]): the top designs' yields by the estimate, then the robust order
    /// among equals.
    Yield,
}

/// The DEM of the yield stage: the design's confirmation protocol and model, and its runs
/// side by side (absent with `--no-dem`: the estimate's part only).
#[derive(Debug, Clone)]
pub struct YieldDemParams {
    /// The DEM protocol and model of every run (α, load and line are set per run).
    pub dem: DemParams,
    /// DEM runs side by side (one thread each).
    pub jobs: usize,
}
