//! The tolerance map around a pattern's answer ([`tolerance_map`]), part of the report data.

use crate::runs::meta::{scene_file, Inputs};
use crate::study::design::model::{AnswerMap, Candidate, DesignScene};
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use crate::study::rows::label;
use crate::study::tolerance::MapParams;
use anyhow::Result;
use serde_json::json;
use surrogate::solver::Solver;
use surrogate::units::deg_to_rad;

/// The tolerance map around the answer `c` of `ds`: θ ±2·tol in 17 points × direction ±2·tol
/// in 9 points (at least ±0.1° and ±0.5°), at the design's loads; stored
/// (`stages/<name>/tolerance_map.json`) and reused. Cost: 153 points, each the friction
/// estimate at every load up to its limit.
pub fn tolerance_map(env: StageEnv, ds: &DesignScene, c: &Candidate) -> Result<AnswerMap> {
    let StageEnv { limit, store, obs } = env;
    let progress = obs.progress();
    let grid = |tol: f64, min: f64, n: usize| -> Vec<f64> {
        let r = (2.0 * tol).max(min);
        (0..n)
            .map(|k| label(-r + 2.0 * r * k as f64 / (n - 1) as f64))
            .collect()
    };
    let mp = MapParams {
        theta_deg: c.theta_deg,
        direction_deg: c.direction_deg,
        theta_offsets_deg: grid(limit.tolerance.theta_tol_deg, 0.1, 17),
        direction_offsets_deg: grid(limit.tolerance.direction_tol_deg, 0.5, 9),
        limit: limit.limit(),
    };
    let inputs = Inputs {
        workflow: "design/tolerance-map".into(),
        scene: Some(scene_file(&ds.scene.with_theta(deg_to_rad(c.theta_deg)))),
        params: json!({
            "theta_deg": c.theta_deg,
            "direction_deg": c.direction_deg,
            "theta_offsets_deg": mp.theta_offsets_deg,
            "direction_offsets_deg": mp.direction_offsets_deg,
            "limit": limit.record(),
        }),
    };
    let rel = format!("stages/{}/tolerance_map.json", ds.name);
    if let Some(m) = store.load_json::<AnswerMap>(&rel, &inputs)? {
        return Ok(m);
    }
    let mut sc = ds.scene.clone();
    sc.slider.theta = 0.0;
    let solver = Solver::new(&sc)?;
    let n = mp.theta_offsets_deg.len() * mp.direction_offsets_deg.len();
    obs.event(&Event::ToleranceMap {
        pattern: &ds.name,
        points: n as u64,
    });
    let rows = crate::study::tolerance::map(&solver, &mp, &|| progress.advance(1))?;
    progress.finish();
    let m = AnswerMap {
        nominal: (c.theta_deg, c.direction_deg),
        theta_points: mp.theta_offsets_deg.len(),
        rows,
    };
    store.save_json(&rel, &inputs, &m)?;
    Ok(m)
}
