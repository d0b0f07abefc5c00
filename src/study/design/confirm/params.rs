//! [`ConfirmParams`]: the knobs of the design's DEM confirmation ([`super::ConfirmStage`]).

use crate::study::dem_run::DemParams;

/// The DEM confirmation's knobs (the loads it picks from are the design's own).
#[derive(Debug, Clone)]
pub struct ConfirmParams {
    /// Designs per pattern confirmed with the DEM (0 only with `no_dem`).
    pub designs: usize,
    /// Loads (N) of the DEM confirmation, each one of the design's loads.
    pub loads: Vec<f64>,
    /// Stop before the DEM.
    pub no_dem: bool,
    /// DEM runs side by side (one thread each).
    pub jobs: usize,
    /// Shard of the DEM confirmation runs to compute ([`crate::runs::shard::Shard::ALL`]: every
    /// run, then the report). With a part, the design computes its share of the runs into
    /// `--out-dir/dem/` and stops before the report; a call without a shard (all shards' `dem/`
    /// runs in the same `--out-dir`) reuses them and writes the report.
    pub dem_shard: crate::runs::shard::Shard,
    /// The DEM protocol of every confirmation run (α and line are set per run).
    pub dem: DemParams,
    /// The study's protocol (10 + 10 + 300 µs) is used; otherwise the report says it is shorter.
    pub dem_is_study_protocol: bool,
    /// Also run the study protocol on the best design at the middle confirmation load, to
    /// measure the shorter protocol's friction difference (only when the protocol is shorter).
    pub protocol_check: bool,
}
