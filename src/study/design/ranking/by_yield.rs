//! With `--rank-by yield` ([`crate::study::design::yield_stage::RankBy::Yield`]), after a pattern's robust
//! search: its top designs ranked by the load that a fraction q of fabricated devices hold
//! instead of the worst case over the tolerance box.
//!
//! The first `max(confirm, 3)` designs of the robust order whose limits are exact and
//! superlubric at their nominal (θ, α) (the designs the robust search made exact) each get the
//! estimate's part of their yield ([`crate::study::fab_yield`] without the DEM, the yield
//! stage's devices and knobs, [`crate::study::design::yield_stage::yield_params`]); its one-sided lower bound
//! of the load at yield q (the quoted load itself where the devices are too few for a bound)
//! becomes [`Score::yield_to_mn`](crate::study::design::model::Score::yield_to_mn), which
//! [`crate::study::design::model::rank::compare`] puts before everything else: those designs lead, best yield first,
//! the robust order breaking ties; the rest keep the robust order behind them. The answer's
//! own yield, with the DEM deciding the band, is then the yield stage's
//! ([`crate::study::design::yield_stage`]).
//!
//! The devices' critical loads are stored ([`crate::study::design::yield_stage::stored_devices`]): a re-run, and the answer's own
//! yield, reuse them. Cost: per ranked design the estimate's part of a yield
//! (samples × about 21 single-load estimates / threads; seconds on the study's scenes).

use crate::study::design::model::{rank, PatternResult};
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use crate::study::design::yield_stage::{stored_devices, yield_params, YieldStageParams};
use crate::study::fab_yield::decide;
use anyhow::Result;
use surrogate::units::deg_to_rad;

/// Sets the top `keep` designs' [`Score::yield_to_mn`](crate::study::design::model::Score::yield_to_mn)
/// of `pr` with the yield's knobs `y` and sorts its ranking again ([`rank::compare`]; see the
/// module docs). Returns how many were ranked by yield.
pub fn rank_by_yield(
    env: StageEnv,
    y: &YieldStageParams,
    keep: usize,
    pr: &mut PatternResult,
) -> Result<usize> {
    let StageEnv { limit, store, obs } = env;
    let top: Vec<usize> = (0..pr.ranking.len())
        .filter(|&i| {
            let s = &pr.ranking[i].score;
            s.exact && s.nominal_to_mn > 0.0
        })
        .take(keep)
        .collect();
    if top.is_empty() {
        return Ok(0);
    }
    obs.event(&Event::YieldRank {
        pattern: &pr.scene.name,
        designs: top.len(),
    });
    for &i in &top {
        let c = &pr.ranking[i];
        let scene = pr.scene.scene.with_theta(deg_to_rad(c.theta_deg));
        // the estimate's part only: no DEM
        let yp = yield_params(
            limit,
            (y, None),
            &scene,
            (c.theta_deg, c.direction_deg),
            store.path(&format!("yield/{}", pr.scene.name)),
        );
        let devices = stored_devices(env, &pr.scene.name, &scene, &yp)?;
        let s = decide(&scene, &yp, devices, obs.progress())?.summary;
        let to = s
            .load_at_quantile_bound_mN
            .or(s.load_at_quantile_mN)
            .unwrap_or(0.0);
        pr.ranking[i].score.yield_to_mn = Some(to);
    }
    pr.ranking.sort_by(rank::compare);
    obs.event(&Event::YieldRanked {
        pattern: &pr.scene.name,
        best: &pr.ranking[0],
    });
    Ok(top.len())
}
