//! Stage 8 of a design, the yield, on by default (`DesignParams::fab_yield`): the yield
//! of each pattern's answer — the fraction of fabricated devices that stay superlubric at a
//! load, and the load that a fraction q of them hold with its one-sided confidence bound
//! ([`crate::study::fab_yield`]).
//!
//! Each answer (θ, pull direction, its pattern's scene or recipe) is handed to
//! [`fab_yield`](crate::study::fab_yield::fab_yield) with the design's tolerance box as the
//! fabrication tolerance (θ and pull-direction offsets uniform over ± the design's
//! `--theta-tol-deg` × `--direction-tol-deg`), a fresh substrate per device at the scene's σ_h whose seed is never the scene's own nor one
//! of the design's searched `--seeds` ([`crate::study::fab_yield::FabricationModel::excluded_seeds`]), the design's load
//! ladder, μ_sl, contact line and estimate knobs. With the DEM, the devices that can set the
//! quoted load or its bound get their DEM critical load, located with the design's protocol
//! and model, after `dem_check` fresh devices' DEM check at the estimate's quote, pooled in (at most 40
//! runs; in `yield/<pattern>/`, reused by a re-run); without (`--no-dem`), the estimate's part
//! only. The estimate's part (each device's
//! critical load) is stored per design (`stages/<pattern>/yield_<θ>_<direction>.json`,
//! [`super::stored_devices`]) and reused by a re-run and by the answer's own yield after
//! `--rank-by yield` ranked it.
//!
//! Cost per answer: samples × (one ladder path + 8–15 single-load estimates) / threads for the
//! estimate (seconds on the study's scenes), plus at most 40 DEM runs, the check's included.

use super::devices::{stored_devices, yield_params};
use super::params::{YieldDemParams, YieldStageParams};
use crate::study::design::model::{AnswerYield, DesignOutcome};
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use crate::study::fab_yield::decide;
use anyhow::Result;
use surrogate::units::deg_to_rad;

/// The yield stage's params: its own knobs and the DEM it locates devices with (`None`:
/// `--no-dem`, the estimate's part only).
#[derive(Debug, Clone)]
pub struct YieldRunParams {
    /// The stage's knobs (`design --yield-*`).
    pub knobs: YieldStageParams,
    /// The DEM (the confirmation's protocol and model); `None` without the DEM.
    pub dem: Option<YieldDemParams>,
}

/// The yield stage (see the module docs); its knobs are [`YieldRunParams`]; it reads the
/// shared limit knobs (the ladder, the estimate's knobs, the tolerance box).
pub struct YieldStage<'a> {
    env: StageEnv<'a>,
    params: &'a YieldRunParams,
}

impl<'a> YieldStage<'a> {
    /// The stage in `env` with its knobs.
    pub fn new(env: StageEnv<'a>, params: &'a YieldRunParams) -> Self {
        YieldStage { env, params }
    }

    /// The yield of each pattern's answer of `o`, in pattern order (`None` for a pattern with
    /// no answer superlubric at any load: nothing to fabricate).
    pub fn run(&self, o: &DesignOutcome) -> Result<Vec<Option<AnswerYield>>> {
        let StageEnv { limit, store, obs } = self.env;
        let mut out = Vec::with_capacity(o.patterns.len());
        for (pr, a) in o.patterns.iter().zip(&o.answers) {
            let Some(c) = a
                .index
                .and_then(|i| pr.ranking.get(i))
                .filter(|c| c.score.nominal_to_mn > 0.0)
            else {
                out.push(None);
                continue;
            };
            let scene = pr.scene.scene.with_theta(deg_to_rad(c.theta_deg));
            let yp = yield_params(
                limit,
                (&self.params.knobs, self.params.dem.as_ref()),
                &scene,
                (c.theta_deg, c.direction_deg),
                store.path(&format!("yield/{}", pr.scene.name)),
            );
            let devices = stored_devices(self.env, &pr.scene.name, &scene, &yp)?;
            let outcome = decide(&scene, &yp, devices, obs.progress())?;
            obs.event(&Event::Yield {
                pattern: &pr.scene.name,
                summary: &outcome.summary,
            });
            out.push(Some(AnswerYield {
                theta_deg: c.theta_deg,
                direction_deg: c.direction_deg,
                outcome,
            }));
        }
        Ok(out)
    }
}
