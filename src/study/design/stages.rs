//! The stages of one pattern as [`super::design`] runs them: screen, evaluation of an
//! orientation, the seed solvers and the answer's tolerance map, each stored with its inputs.

use super::domain::{default_domain, line_note};
use super::outcome::{AnswerMap, EvalStage, Timing};
use super::rank::Candidate;
use super::scan::ThetaEval;
use super::shortlist::Orientation;
use super::store::Store;
use super::symmetry::PairSymmetry;
use super::{DesignParams, DesignScene};
use crate::runs::meta::{scene_file, Inputs};
use crate::runs::progress::Progress;
use crate::runs::sink::csv_bytes;
use crate::study::record;
use crate::study::rows::{label, ScreenRow};
use crate::study::screen::{screen, ScreenParams};
use crate::study::tolerance::{LimitParams, ToleranceBox};
use anyhow::Result;
use serde_json::{json, Value};
use std::time::Instant;
use surrogate::solver::{Model, SearchKind, Solver};
use surrogate::units::{deg_to_rad, m_to_um, n_to_mn, rad_to_deg};

/// The tolerance map around the answer `c` of `ds`: θ ±2·tol in 17 points × direction ±2·tol
/// in 9 points (at least ±0.1° and ±0.5°), at the design's loads; stored and reused.
pub fn answer_map(
    ds: &DesignScene,
    c: &Candidate,
    p: &DesignParams,
    store: &Store,
    progress: &dyn Progress,
) -> Result<AnswerMap> {
    let grid = |tol: f64, min: f64, n: usize| -> Vec<f64> {
        let r = (2.0 * tol).max(min);
        (0..n)
            .map(|k| label(-r + 2.0 * r * k as f64 / (n - 1) as f64))
            .collect()
    };
    let mp = crate::study::tolerance::MapParams {
        theta_deg: c.theta_deg,
        direction_deg: c.direction_deg,
        theta_offsets_deg: grid(p.theta_tol_deg, 0.1, 17),
        direction_offsets_deg: grid(p.direction_tol_deg, 0.5, 9),
        limit: LimitParams {
            loads: p.loads.clone(),
            mu_superlubric: p.mu_superlubric,
            line: p.line,
            friction: p.friction,
        },
    };
    let inputs = Inputs {
        workflow: "design/tolerance-map".into(),
        scene: Some(scene_file(&ds.scene.with_theta(deg_to_rad(c.theta_deg)))),
        params: json!({
            "theta_deg": c.theta_deg,
            "direction_deg": c.direction_deg,
            "theta_offsets_deg": mp.theta_offsets_deg,
            "direction_offsets_deg": mp.direction_offsets_deg,
            "limit": limit_record(p),
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
    progress.stage(
        &format!("{}: tolerance map around the answer", ds.name),
        n as u64,
        "points",
    );
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

/// The design's inputs: with `with_dem` false, those of the surrogate tiers (recorded in
/// `design.json`: a re-run with other values is refused), with it true also the DEM protocol
/// (recorded in the final outputs' sidecars). Never recorded: `--confirm`, `--confirm-loads-mn`,
/// `--no-dem`, `--jobs`, `--no-protocol-check` — they choose which DEM runs are made, and each
/// run is stored with its own inputs (a run of the same name made with another protocol is
/// refused, never mixed).
pub fn inputs(scenes: &[DesignScene], p: &DesignParams, with_dem: bool) -> Inputs {
    let w: Vec<f64> = p.loads.iter().map(|&w| label(n_to_mn(w))).collect();
    let sc: Vec<Value> = scenes
        .iter()
        .map(|d| {
            let mut f = scene_file(&d.scene);
            f.slider.theta_deg = None;
            json!({"name": d.name, "scene": f})
        })
        .collect();
    let mut dem = record::dem(&scenes[0].scene, &p.dem);
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
    let mut params = json!({
            "patterns": sc,
            "theta_deg": record::axis(&p.thetas_deg),
            "symmetry_cut": p.symmetry_cut,
            "load_mN": record::axis(&w),
            "mu_superlubric": p.mu_superlubric,
            "per_level": p.per_level,
            "max_top": p.max_top,
            "alpha_step_deg": p.alpha_step_deg,
            "alpha_refine_deg": p.alpha_refine_deg,
            "line_deg": p.line.map(rad_to_deg),
            "scan_um": label(m_to_um(p.scan_length)),
            "scan_step_um": label(m_to_um(p.scan_step)),
            "alphas_per_theta": p.alphas_per_theta,
            "friction": record::friction_knobs(&p.friction),
            "theta_tol_deg": p.theta_tol_deg,
            "direction_tol_deg": p.direction_tol_deg,
            "theta_tol_step_deg": p.theta_tol_step_deg,
            "direction_tol_step_deg": p.direction_tol_step_deg,
            "seeds": p.seeds,
    });
    // without --theta, a pattern screened over its whole domain (not the default list) says so
    // (absent otherwise: the presets' records are unchanged)
    if p.theta_default
        && scenes
            .iter()
            .any(|d| default_domain(&PairSymmetry::of_scene(&d.scene), p).is_some())
    {
        params["theta_default"] = json!("the whole domain where 0:30:0.1 does not span it");
    }
    // a site file's pattern measures α from the x axis (absent otherwise: records unchanged)
    let lines: Vec<Value> = scenes
        .iter()
        .filter_map(|d| line_note(d, p).map(|n| json!({"name": d.name, "line": n})))
        .collect();
    if !lines.is_empty() {
        params["line_site_files"] = json!(lines);
    }
    if with_dem {
        params["dem"] = dem;
    }
    Inputs {
        workflow: "design".into(),
        scene: None,
        params,
    }
}

/// The tolerance box of the design's `--theta-tol-deg` × `--direction-tol-deg`.
pub fn tolerance_box(p: &DesignParams) -> ToleranceBox {
    ToleranceBox::new(
        p.theta_tol_deg,
        p.direction_tol_deg,
        p.theta_tol_step_deg,
        p.direction_tol_step_deg,
    )
}

/// The recorded inputs of a superlubric limit (loads, threshold, contact line, estimate knobs).
pub(super) fn limit_record(p: &DesignParams) -> Value {
    json!({
        "load_mN": p.loads.iter().map(|&w| label(n_to_mn(w))).collect::<Vec<_>>(),
        "mu_superlubric": p.mu_superlubric,
        "line_deg": p.line.map(rad_to_deg),
        "friction": record::friction_knobs(&p.friction),
    })
}

/// One solver per substrate realisation: the scene's own (reusing `own` when built), then one
/// per extra seed of `p.seeds`.
pub(super) fn seed_solvers(
    ds: &DesignScene,
    p: &DesignParams,
    own: Option<Solver>,
) -> Result<Vec<Solver>> {
    let mut sc = ds.scene.clone();
    sc.slider.theta = 0.0;
    let mut v = vec![match own {
        Some(s) => s,
        None => Solver::new(&sc)?,
    }];
    for &seed in &p.seeds {
        if seed != sc.substrate.seed {
            let mut o = sc.clone();
            o.substrate.seed = seed;
            v.push(Solver::new(&o)?);
        }
    }
    Ok(v)
}

/// The screen's parameters for θ (degrees).
pub fn screen_params(thetas_deg: &[f64], p: &DesignParams) -> ScreenParams {
    ScreenParams {
        thetas: thetas_deg.iter().map(|&t| deg_to_rad(t)).collect(),
        loads: p.loads.clone(),
        model: Model::Auto,
        search: SearchKind::Grid,
    }
}

/// The inputs of a pattern's screen (the same as `superlube screen` records).
pub(super) fn screen_inputs(ds: &DesignScene, sp: &ScreenParams) -> Inputs {
    let mut recorded = scene_file(&ds.scene);
    recorded.slider.theta_deg = None;
    Inputs {
        workflow: "screen".into(),
        scene: Some(recorded),
        params: record::screen(sp),
    }
}

/// Stage 2: the screen of one pattern (`screen_<name>.csv`), reused when finished.
pub(super) fn screen_stage(
    ds: &DesignScene,
    thetas_deg: &[f64],
    p: &DesignParams,
    store: &Store,
    progress: &dyn Progress,
) -> Result<(Vec<ScreenRow>, Option<f64>)> {
    let sp = screen_params(thetas_deg, p);
    let inputs = screen_inputs(ds, &sp);
    let rel = format!("screen_{}.csv", ds.name);
    let timing = format!("stages/{}/screen.json", ds.name);
    if let Some(rows) = store.load_csv::<ScreenRow>(&rel, &inputs)? {
        let t = store.load_json::<Timing>(&timing, &inputs)?;
        progress.note(&format!(
            "{}: screen reused from {rel} ({} rows, input hash matches)",
            ds.name,
            rows.len()
        ));
        return Ok((rows, t.map(|t| t.wall_s)));
    }
    let t0 = Instant::now();
    let mut rows: Vec<ScreenRow> = Vec::new();
    let mut scene = ds.scene.clone();
    scene.slider.theta = 0.0;
    screen(&scene, &sp, &mut rows, progress)?;
    let wall_s = t0.elapsed().as_secs_f64();
    store.save(&rel, &inputs, csv_bytes(&rows)?, Some(rows.len() as u64))?;
    store.save_json(&timing, &inputs, &Timing { wall_s })?;
    progress.note(&format!(
        "{}: screened {} θ × {} loads in {:.2} s",
        ds.name,
        thetas_deg.len(),
        p.loads.len(),
        wall_s
    ));
    Ok((rows, Some(wall_s)))
}

/// The inputs of one orientation's evaluation.
pub(super) fn eval_inputs(
    ds: &DesignScene,
    theta_deg: f64,
    scan_load: f64,
    sym: &PairSymmetry,
    p: &DesignParams,
) -> Inputs {
    let w: Vec<f64> = p.loads.iter().map(|&w| label(n_to_mn(w))).collect();
    Inputs {
        workflow: "design/orientation".into(),
        scene: Some(scene_file(&ds.scene.with_theta(deg_to_rad(theta_deg)))),
        params: json!({
            "theta_deg": theta_deg,
            "scan_load_mN": label(n_to_mn(scan_load)),
            "load_mN": w,
            "alpha_period_deg": sym.alpha_period_deg,
            "alpha_step_deg": p.alpha_step_deg,
            "alpha_refine_deg": p.alpha_refine_deg,
            "line_deg": p.line.map(rad_to_deg),
            "scan_um": label(m_to_um(p.scan_length)),
            "scan_step_um": label(m_to_um(p.scan_step)),
            "alphas_per_theta": p.alphas_per_theta,
            "friction": record::friction_knobs(&p.friction),
        }),
    }
}

/// Stage 4 for one orientation (`stages/<name>/theta_<θ>.json`), reused when finished.
#[allow(clippy::too_many_arguments)]
pub(super) fn eval_stage(
    ds: &DesignScene,
    o: &Orientation,
    scan_load: f64,
    sym: &PairSymmetry,
    p: &DesignParams,
    store: &Store,
    solver: &Solver,
    per: usize,
    progress: &dyn Progress,
) -> Result<(ThetaEval, f64, bool)> {
    let inputs = eval_inputs(ds, o.theta_deg, scan_load, sym, p);
    let rel = format!("stages/{}/theta_{}.json", ds.name, super::tag(o.theta_deg));
    if let Some(st) = store.load_json::<EvalStage>(&rel, &inputs)? {
        progress.advance(per as u64);
        return Ok((st.eval, st.wall_s, true));
    }
    let t0 = Instant::now();
    let ticks = std::sync::atomic::AtomicUsize::new(0);
    let tick = || {
        if ticks.fetch_add(1, std::sync::atomic::Ordering::Relaxed) < per {
            progress.advance(1);
        }
    };
    let eval = super::scan::evaluate(solver, &ds.scene, o.theta_deg, scan_load, p, sym, &tick)?;
    let done = ticks.load(std::sync::atomic::Ordering::Relaxed);
    if done < per {
        progress.advance((per - done) as u64);
    }
    let st = EvalStage {
        eval,
        wall_s: t0.elapsed().as_secs_f64(),
    };
    store.save_json(&rel, &inputs, &st)?;
    Ok((st.eval, st.wall_s, false))
}
