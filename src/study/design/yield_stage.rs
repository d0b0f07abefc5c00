//! Stage 8 of a design, the yield, on by default ([`DesignParams::fab_yield`]): the yield
//! of each pattern's answer — the fraction of fabricated devices that stay superlubric at a
//! load, and the load that a fraction q of them hold with its one-sided confidence bound
//! ([`crate::study::fab_yield`]).
//!
//! Each answer (θ, pull direction, its pattern's scene or recipe) is handed to
//! [`fab_yield`](crate::study::fab_yield::fab_yield) with the design's tolerance box as the
//! fabrication tolerance (θ and pull-direction offsets uniform over ± the design's
//! `--theta-tol-deg` × `--direction-tol-deg`), a fresh substrate per device at the scene's σ_h whose seed is never the scene's own nor one
//! of the design's searched `--seeds` ([`FabricationModel::excluded_seeds`]), the design's load
//! ladder, μ_sl, contact line and estimate knobs. With the DEM, the devices that can set the
//! quoted load or its bound get their DEM critical load, located with the design's protocol
//! and model, and `dem_check` fresh devices a DEM check at the quote, pooled in (at most 40
//! runs; in `yield/<pattern>/`, reused by a re-run); without (`--no-dem`), the estimate's part
//! only. The estimate's part (each device's
//! critical load) is stored per design (`stages/<pattern>/yield_<θ>_<direction>.json`,
//! [`stored_devices`]) and reused by a re-run and by the answer's own yield after
//! `--rank-by yield` ranked it.
//!
//! Cost per answer: samples × (one ladder path + 8–15 single-load estimates) / threads for the
//! estimate (seconds on the study's scenes), plus at most 40 DEM runs, the check's included.

pub use super::answer_yield::AnswerYield;
use super::ctx::Ctx;
use super::limit::limit_record;
use super::observer::Event;
use super::outcome::DesignOutcome;
use super::params::DesignParams;
pub use super::yield_params::YieldStageParams;
use crate::runs::meta::{scene_file, Inputs};
use crate::study::fab_yield::{
    decide, estimate_devices, Device, FabricationModel, OffsetLaw, YieldDem, YieldParams,
};
use anyhow::Result;
use serde_json::json;
use surrogate::units::deg_to_rad;

/// The devices of the yield `yp` of pattern `name` (its scene `scene` with θ set) with their
/// critical loads by the estimate ([`estimate_devices`]): from the store when a run of the
/// same inputs made them, else computed and stored (`stages/<name>/yield_<θ>_<direction>.json`).
/// Cost: the estimate's part of a yield, or reading one JSON file.
pub fn stored_devices(
    ctx: Ctx,
    name: &str,
    scene: &surrogate::Scene,
    yp: &YieldParams,
) -> Result<Vec<Device>> {
    let Ctx { p, store, obs } = ctx;
    let inputs = Inputs {
        workflow: "design/yield-devices".into(),
        scene: Some(scene_file(scene)),
        params: json!({
            "theta_deg": yp.theta_deg,
            "direction_deg": yp.direction_deg,
            "fabrication": yp.fabrication.record(scene),
            "samples": yp.samples,
            "resolution": yp.resolution,
            "limit": limit_record(p),
        }),
    };
    let rel = format!(
        "stages/{name}/yield_{}_{}.json",
        yp.theta_deg, yp.direction_deg
    );
    if let Some(d) = store.load_json::<Vec<Device>>(&rel, &inputs)? {
        return Ok(d);
    }
    let d = estimate_devices(scene, yp, obs.progress())?;
    store.save_json(&rel, &inputs, &d)?;
    Ok(d)
}

/// The yield stage (see the module docs).
pub struct YieldStage<'a> {
    ctx: Ctx<'a>,
    params: &'a YieldStageParams,
}

/// The yield of the answer (θ, direction in degrees) of a pattern whose scene is `scene`, with
/// the design's knobs `p` and the stage's `y`; the DEM runs (without `--no-dem`) in `dem_dir`.
pub fn yield_params(
    p: &DesignParams,
    y: &YieldStageParams,
    scene: &surrogate::Scene,
    (theta_deg, direction_deg): (f64, f64),
    dem_dir: std::path::PathBuf,
) -> YieldParams {
    let mut excluded = vec![scene.substrate.seed];
    excluded.extend(
        p.tolerance
            .seeds
            .iter()
            .copied()
            .filter(|s| *s != scene.substrate.seed),
    );
    YieldParams {
        theta_deg,
        direction_deg,
        fabrication: FabricationModel {
            theta: OffsetLaw::Uniform {
                half_width_deg: p.tolerance.theta_tol_deg,
            },
            direction: OffsetLaw::Uniform {
                half_width_deg: p.tolerance.direction_tol_deg,
            },
            sphere_diameter_cv: 0.0,
            p_crit_sigma: 0.0,
            seed: y.seed,
            excluded_seeds: excluded,
        },
        samples: y.samples,
        quantile: y.quantile,
        confidence: y.confidence,
        resolution: y.resolution,
        limit: p.limit(),
        dem: (!p.confirm.no_dem).then(|| {
            YieldDem::new(
                p.confirm.dem.clone(),
                (y.dem_check, None),
                p.confirm.jobs,
                dem_dir,
            )
        }),
    }
}

impl<'a> YieldStage<'a> {
    /// The stage in `ctx` with its knobs.
    pub fn new(ctx: Ctx<'a>, params: &'a YieldStageParams) -> Self {
        YieldStage { ctx, params }
    }

    /// The yield of each pattern's answer of `o`, in pattern order (`None` for a pattern with
    /// no answer superlubric at any load: nothing to fabricate).
    pub fn run(&self, o: &DesignOutcome) -> Result<Vec<Option<AnswerYield>>> {
        let Ctx { p, store, obs } = self.ctx;
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
                p,
                self.params,
                &scene,
                (c.theta_deg, c.direction_deg),
                store.path(&format!("yield/{}", pr.scene.name)),
            );
            let devices = stored_devices(self.ctx, &pr.scene.name, &scene, &yp)?;
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
