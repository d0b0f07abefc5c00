//! The yield of one design as the design's stages ask for it: its knobs ([`yield_params`]: the
//! design's tolerance box as the fabrication tolerance, its ladder and estimate knobs) and its
//! devices' critical loads by the estimate, stored and reused ([`stored_devices`]). The yield
//! stage and the ranking by yield ([`crate::study::design::ranking::by_yield`]) share them.

use super::params::{YieldDemParams, YieldStageParams};
use crate::runs::meta::{scene_file, Inputs};
use crate::study::design::limit::LimitKnobs;
use crate::study::design::stage_env::StageEnv;
use crate::study::fab_yield::{
    estimate_devices, Device, FabricationModel, OffsetLaw, YieldDem, YieldParams,
};
use anyhow::Result;
use serde_json::json;

/// The devices of the yield `yp` of pattern `name` (its scene `scene` with θ set) with their
/// critical loads by the estimate ([`estimate_devices`]): from the store when a run of the
/// same inputs made them, else computed and stored (`stages/<name>/yield_<θ>_<direction>.json`).
/// Cost: the estimate's part of a yield, or reading one JSON file.
pub fn stored_devices(
    env: StageEnv,
    name: &str,
    scene: &surrogate::Scene,
    yp: &YieldParams,
) -> Result<Vec<Device>> {
    let StageEnv { limit, store, obs } = env;
    let inputs = Inputs {
        workflow: "design/yield-devices".into(),
        scene: Some(scene_file(scene)),
        params: json!({
            "theta_deg": yp.theta_deg,
            "direction_deg": yp.direction_deg,
            "fabrication": yp.fabrication.record(scene),
            "samples": yp.samples,
            "resolution": yp.resolution,
            "limit": limit.record(),
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

/// The yield of the answer (θ, direction in degrees) of a pattern whose scene is `scene`, with
/// the shared knobs `limit` and the stage's `y`; with `dem` (the design's DEM, not
/// `--no-dem`), its runs in `dem_dir`. Cost: a few small copies.
pub fn yield_params(
    limit: &LimitKnobs,
    (y, dem): (&YieldStageParams, Option<&YieldDemParams>),
    scene: &surrogate::Scene,
    (theta_deg, direction_deg): (f64, f64),
    dem_dir: std::path::PathBuf,
) -> YieldParams {
    let tol = &limit.tolerance;
    let mut excluded = vec![scene.substrate.seed];
    excluded.extend(
        tol.seeds
            .iter()
            .copied()
            .filter(|s| *s != scene.substrate.seed),
    );
    YieldParams {
        theta_deg,
        direction_deg,
        fabrication: FabricationModel {
            theta: OffsetLaw::Uniform {
                half_width_deg: tol.theta_tol_deg,
            },
            direction: OffsetLaw::Uniform {
                half_width_deg: tol.direction_tol_deg,
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
        limit: limit.limit(),
        dem: dem.map(|d| {
            let check = (y.dem_check, None);
            YieldDem::new(d.dem.clone(), check, y.dem_max_runs, d.jobs, dem_dir)
        }),
    }
}
