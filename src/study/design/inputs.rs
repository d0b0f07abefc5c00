//! The design's recorded inputs ([`inputs`]: `design.json` and the final outputs' sidecars).
//! Each stored stage records its own in its folder (the screen's, an orientation's
//! evaluation); the α scan's and estimate's knobs are written by one function
//! ([`evaluation_record`]) into both, and a pattern's scene by one ([`DesignScene::record`]).
//! User units (mN, µm, degrees), as every sidecar. Cost: building a few small JSON objects.

use super::evaluate::evaluation_record;
use super::model::DesignScene;
use super::params::DesignParams;
use super::screen::domain::{default_domain, line_note};
use super::symmetry_words::PairSymmetry;
use super::yield_stage::{RankBy, YieldStageParams};
use crate::runs::meta::Inputs;
use crate::study::record;
use serde_json::{json, Value};

/// `base` (a JSON object) with the evaluation's knobs added.
fn with_evaluation(mut base: Value, p: &DesignParams) -> Value {
    if let Value::Object(m) = &mut base {
        m.extend(evaluation_record(&p.alpha_scan, &p.friction));
    }
    base
}

/// The design's inputs: with `with_dem` false, those of the surrogate tiers (recorded in
/// `design.json`: a re-run with other values is refused), with it true also the DEM protocol
/// (recorded in the final outputs' sidecars). Never recorded: `--confirm`, `--confirm-loads-mn`,
/// `--no-dem`, `--jobs`, `--no-protocol-check` — they choose which DEM runs are made, and each
/// run is stored with its own inputs (a run of the same name made with another protocol is
/// refused, never mixed).
pub fn inputs(scenes: &[DesignScene], p: &DesignParams, with_dem: bool) -> Inputs {
    let sc: Vec<Value> = scenes
        .iter()
        .map(|d| json!({"name": d.name, "scene": d.record()}))
        .collect();
    let mut dem = record::dem(&scenes[0].scene, &p.confirm.dem);
    if let Some(o) = dem.as_object_mut() {
        // set per run
        for k in ["load_mN", "alpha_deg", "line_deg"] {
            o.remove(k);
        }
        if let Some(e) = o.get_mut("engine_si").and_then(Value::as_object_mut) {
            e.remove("load");
            e.remove("alpha");
        }
    }
    let mut params = with_evaluation(
        json!({
            "patterns": sc,
            "theta_deg": record::axis(&p.screen.thetas_deg),
            "symmetry_cut": p.screen.symmetry_cut,
            "load_mN": record::axis(&p.loads.labels_mn()),
            "mu_superlubric": p.mu_superlubric,
            "per_level": p.shortlist.per_level,
            "max_top": p.shortlist.max_top,
            "theta_tol_deg": p.tolerance.theta_tol_deg,
            "direction_tol_deg": p.tolerance.direction_tol_deg,
            "theta_tol_step_deg": p.tolerance.theta_tol_step_deg,
            "direction_tol_step_deg": p.tolerance.direction_tol_step_deg,
            "seeds": p.tolerance.seeds,
        }),
        p,
    );
    // without --theta, a pattern screened over its whole domain (not the default list) says so
    // (absent otherwise: the presets' records are unchanged)
    if p.screen.theta_default
        && scenes
            .iter()
            .any(|d| default_domain(&PairSymmetry::of_scene(&d.scene), &p.screen).is_some())
    {
        params["theta_default"] = json!("the whole domain where 0:30:0.1 does not span it");
    }
    // a site file's pattern measures α from the x axis (absent otherwise: records unchanged)
    let lines: Vec<Value> = scenes
        .iter()
        .filter_map(|d| line_note(d, p.alpha_scan.line).map(|n| json!({"name": d.name, "line": n})))
        .collect();
    if !lines.is_empty() {
        params["line_site_files"] = json!(lines);
    }
    if with_dem {
        params["dem"] = dem;
    }
    // the yield's devices: what draws them and how finely their critical loads are found
    let devices = |y: &YieldStageParams| {
        json!({
            "samples": y.samples,
            "quantile": y.quantile,
            "confidence": y.confidence,
            "resolution": y.resolution,
            "sample_seed": y.seed,
        })
    };
    // the yield stage's knobs, when it runs (absent otherwise: records unchanged)
    if let (true, Some(y)) = (with_dem, &p.fab_yield) {
        params["yield"] = devices(y);
        params["yield"]["dem_check"] = json!(y.dem_check);
    }
    // ranking by yield changes the surrogate's answers: part of the design's inputs with or
    // without the DEM (absent otherwise: records unchanged)
    if let Some(y) = p.fab_yield.as_ref().filter(|y| y.rank_by == RankBy::Yield) {
        params["rank_by_yield"] = devices(y);
    }
    Inputs {
        workflow: "design".into(),
        scene: None,
        params,
    }
}
