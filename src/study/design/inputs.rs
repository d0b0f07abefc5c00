//! The design's recorded inputs, in one place: those of the whole design ([`inputs`]:
//! `design.json` and the final outputs' sidecars) and those each stored stage is reused by
//! (a pattern's screen, an orientation's evaluation). The α scan's and estimate's knobs are
//! written by one function ([`evaluation_record`]) into both, and a pattern's scene by one
//! ([`scene_record`]). User units (mN, µm, degrees), as every sidecar. Cost: building a few
//! small JSON objects.

use super::domain::{default_domain, line_note};
use super::params::{DesignParams, DesignScene};
use super::symmetry_words::PairSymmetry;
use crate::runs::meta::{scene_file, Inputs};
use crate::study::record;
use crate::study::rows::label;
use crate::study::screen::ScreenParams;
use serde_json::{json, Map, Value};
use surrogate::scene::SceneFile;
use surrogate::solver::{Model, SearchKind};
use surrogate::units::{deg_to_rad, m_to_um, n_to_mn, rad_to_deg};

/// A pattern's scene as recorded: its scene file with θ left out (θ is swept).
pub(super) fn scene_record(ds: &DesignScene) -> SceneFile {
    let mut f = scene_file(&ds.scene);
    f.slider.theta_deg = None;
    f
}

/// The knobs of an orientation's evaluation (α scan and friction estimate), as recorded both
/// in the design's inputs and in each stored evaluation's.
fn evaluation_record(p: &DesignParams) -> Map<String, Value> {
    let v = json!({
        "alpha_step_deg": p.alpha_scan.alpha_step_deg,
        "alpha_refine_deg": p.alpha_scan.alpha_refine_deg,
        "line_deg": p.alpha_scan.line.map(rad_to_deg),
        "scan_um": label(m_to_um(p.alpha_scan.scan_length)),
        "scan_step_um": label(m_to_um(p.alpha_scan.scan_step)),
        "alphas_per_theta": p.alpha_scan.alphas_per_theta,
        "friction": record::friction_knobs(&p.friction),
    });
    match v {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}

/// `base` (a JSON object) with the evaluation's knobs added.
fn with_evaluation(mut base: Value, p: &DesignParams) -> Value {
    if let Value::Object(m) = &mut base {
        m.extend(evaluation_record(p));
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
        .map(|d| json!({"name": d.name, "scene": scene_record(d)}))
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
            "load_mN": record::axis(&p.load_labels_mn()),
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
    let devices = |y: &super::yield_params::YieldStageParams| {
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
    if let Some(y) = p
        .fab_yield
        .as_ref()
        .filter(|y| y.rank_by == super::yield_params::RankBy::Yield)
    {
        params["rank_by_yield"] = devices(y);
    }
    Inputs {
        workflow: "design".into(),
        scene: None,
        params,
    }
}

/// The screen's parameters for θ (degrees): every θ × every load of the design.
pub fn screen_params(thetas_deg: &[f64], p: &DesignParams) -> ScreenParams {
    ScreenParams {
        thetas: thetas_deg.iter().map(|&t| deg_to_rad(t)).collect(),
        loads: p.loads.to_vec(),
        model: Model::Auto,
        search: SearchKind::Grid,
    }
}

/// The inputs of a pattern's screen (the same as `superlube screen` records).
pub(super) fn screen_inputs(ds: &DesignScene, sp: &ScreenParams) -> Inputs {
    Inputs {
        workflow: "screen".into(),
        scene: Some(scene_record(ds)),
        params: record::screen(sp),
    }
}

/// The inputs of one orientation's evaluation: θ (degrees), its scan load (N) and the pair's
/// α period, with the evaluation's knobs.
pub(super) fn eval_inputs(
    ds: &DesignScene,
    theta_deg: f64,
    scan_load: f64,
    sym: &PairSymmetry,
    p: &DesignParams,
) -> Inputs {
    Inputs {
        workflow: "design/orientation".into(),
        scene: Some(scene_file(&ds.scene.with_theta(deg_to_rad(theta_deg)))),
        params: with_evaluation(
            json!({
                "theta_deg": theta_deg,
                "scan_load_mN": label(n_to_mn(scan_load)),
                "load_mN": p.load_labels_mn(),
                "alpha_period_deg": sym.alpha_period_deg,
            }),
            p,
        ),
    }
}
