//! Steps 3–4 of a yield with the DEM ([`run`]): the check on fresh devices at the estimate's
//! quote, then the DEM rounds over the pool.
//!
//! The check comes first: its devices are drawn after the yield's own (samples
//! `samples..samples + check`), estimated like them, and run at the estimate's quote of the
//! yield's own devices (or the load asked for). Drawn at random, not chosen by their estimate,
//! their pairs calibrate the band ([`super::calibration`]) on devices like those it is applied
//! to; the rounds' own runs go to the devices the estimate puts lowest, which, where the
//! estimate ranks the devices backwards, are unlike those that fail first
//! (`docs/validation/yield.md`). The check's devices are then pooled (DEM-decided devices of
//! the same model) and the rounds run over the pool with what is left of `max_runs`; a check
//! device that failed may be among the lowest critical loads and gets located like any other.
//! Cost: at most `max_runs` DEM runs (the check's included) and `check` devices' estimates.

use super::dem_decide::{DemDecider, YieldDem};
use super::device::Device;
use super::estimate::estimate_range;
use super::params::YieldParams;
use super::rounds::{answer, setting_ranks, DemOracle, Rounds};
use crate::runs::progress::Progress;
use anyhow::Result;
use surrogate::Scene;

/// What the DEM part of a yield did.
#[derive(Debug, Clone)]
pub struct DemPart {
    /// DEM runs made, the check's included.
    pub runs: usize,
    /// Most runs allowed.
    pub allowed: usize,
    /// Rounds made.
    pub rounds: usize,
    /// The load of the check (N; `None`: no check ran).
    pub check_load: Option<f64>,
    /// Whether the check ran at a load of its own (not the quote).
    pub check_load_given: bool,
    /// Why each check device was not superlubric at the check load (empty where it was), in
    /// device order.
    pub check_why: Vec<String>,
    /// The setting ranks over the final pool.
    pub k: usize,
}

/// How many DEM runs a yield may make and where its check goes.
#[derive(Debug, Clone, Copy)]
pub struct Plan {
    /// Fresh devices of the check (0: none).
    pub check: usize,
    /// The check's load (N; `None`: the estimate's quote).
    pub check_load: Option<f64>,
    /// Most DEM runs, the check's included.
    pub max_runs: usize,
}

/// Runs the DEM part of the yield `p` (its DEM `d`) on `devices` (the yield's own, estimated),
/// appending the check's devices to them (module docs).
pub fn run(
    scene: &Scene,
    p: &YieldParams,
    d: &YieldDem,
    devices: &mut Vec<Device>,
    progress: &dyn Progress,
) -> Result<DemPart> {
    let decider = DemDecider {
        scene,
        theta_deg: p.theta_deg,
        direction_deg: p.direction_deg,
        mu_superlubric: p.limit.mu_superlubric,
        dem: d,
    };
    let plan = Plan {
        check: d.check,
        check_load: d.check_load,
        max_runs: d.max_runs,
    };
    let range = p.samples..p.samples + d.check;
    let fresh = || estimate_range(scene, p, range, "yield: check devices", progress);
    run_with(&decider, p, plan, devices, fresh, progress)
}

/// [`run`] with the DEM `oracle` and the check's devices from `fresh` (estimated, drawn after
/// the yield's own).
pub fn run_with(
    oracle: &dyn DemOracle,
    p: &YieldParams,
    plan: Plan,
    devices: &mut Vec<Device>,
    fresh: impl FnOnce() -> Result<Vec<Device>>,
    progress: &dyn Progress,
) -> Result<DemPart> {
    let mu_sl = p.limit.mu_superlubric;
    let mut rounds =
        Rounds::new(oracle, mu_sl, p.resolution).stopping_when_sharp(p.quantile, p.confidence);
    let allowed = plan.max_runs.max(plan.check);
    let ranks = |n: usize| setting_ranks(n, p.quantile, p.confidence);
    let mut check_why = Vec::new();
    let mut check_load = None;
    if plan.check > 0 {
        // the estimate's own quote of the yield's devices (the global band's centre is 1)
        let estimated: Vec<f64> = devices.iter().map(|d| d.estimate.load).collect();
        if let Some(w) = plan
            .check_load
            .or(answer(&estimated, p.quantile, p.confidence).0)
        {
            let start = devices.len();
            devices.extend(fresh()?);
            let asks: Vec<(usize, f64)> = (start..devices.len()).map(|i| (i, w)).collect();
            check_why = rounds.execute(devices, &asks, "yield: DEM check", progress)?;
            check_load = Some(w);
        }
    }
    let k = ranks(devices.len());
    rounds.run(devices, k, allowed, progress)?;
    Ok(DemPart {
        runs: rounds.runs,
        allowed,
        rounds: rounds.rounds,
        check_load,
        check_load_given: plan.check_load.is_some(),
        check_why,
        k: ranks(devices.len()),
    })
}
