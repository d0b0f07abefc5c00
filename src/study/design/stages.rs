//! The stages of one pattern as [`super::design`] runs them: screen, evaluation of an
//! orientation, the seed solvers and the answer's tolerance map, each stored with its inputs.

use super::domain::{default_domain, line_note};
use super::observer::{Event, Observer, Stage};
use super::outcome::{AnswerMap, EvalStage, Timing};
use super::rank::Candidate;
use super::scan::ThetaEval;
use super::shortlist::Orientation;
use super::store::Store;
use super::symmetry::PairSymmetry;
use super::{DesignParams, DesignScene};
use crate::runs::meta::{scene_file, Inputs};
use crate::runs::sink::csv_bytes;
use crate::study::record;
use crate::study::rows::{label, ScreenRow};
use crate::study::screen::{screen, ScreenParams};
use crate::study::tolerance::{LimitParams, ToleranceBox};
use anyhow::Result;
use rayon::prelude::*;
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
    obs: &dyn Observer,
) -> Result<AnswerMap> {
    let progress = obs.progress();
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
    obs: &dyn Observer,
) -> Result<(Vec<ScreenRow>, Option<f64>)> {
    let sp = screen_params(thetas_deg, p);
    let inputs = screen_inputs(ds, &sp);
    let rel = format!("screen_{}.csv", ds.name);
    let timing = format!("stages/{}/screen.json", ds.name);
    if let Some(rows) = store.load_csv::<ScreenRow>(&rel, &inputs)? {
        let t = store.load_json::<Timing>(&timing, &inputs)?;
        obs.event(&Event::ScreenReused {
            pattern: &ds.name,
            file: &rel,
            rows: rows.len(),
        });
        return Ok((rows, t.map(|t| t.wall_s)));
    }
    let t0 = Instant::now();
    let mut rows: Vec<ScreenRow> = Vec::new();
    let mut scene = ds.scene.clone();
    scene.slider.theta = 0.0;
    screen(&scene, &sp, &mut rows, obs.progress())?;
    let wall_s = t0.elapsed().as_secs_f64();
    store.save(&rel, &inputs, csv_bytes(&rows)?, Some(rows.len() as u64))?;
    store.save_json(&timing, &inputs, &Timing { wall_s })?;
    obs.event(&Event::Screened {
        pattern: &ds.name,
        thetas: thetas_deg.len(),
        loads: p.loads.len(),
        wall_s,
    });
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

/// Stages 4a and 4b for the orientations `picks` of one shortlist level, scanned at
/// `scan_load` (N): each one's stored evaluation (`stages/<name>/theta_<θ>.json`) where
/// finished, else its α scan ([`Stage::AlphaScan`], every orientation side by side), then its
/// friction estimate ([`Stage::Estimate`], likewise), stored. `per` paths per orientation are
/// reported through the observer's bar. Returns per pick (in order) the evaluation, its wall
/// time (s) and whether it was reused.
#[allow(clippy::too_many_arguments)]
pub(super) fn eval_level(
    ds: &DesignScene,
    picks: &[Orientation],
    scan_load: f64,
    sym: &PairSymmetry,
    p: &DesignParams,
    store: &Store,
    solver: &Solver,
    per: usize,
    obs: &dyn Observer,
) -> Result<Vec<(ThetaEval, f64, bool)>> {
    use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};
    let progress = obs.progress();
    let rel =
        |o: &Orientation| format!("stages/{}/theta_{}.json", ds.name, super::tag(o.theta_deg));
    let inputs: Vec<Inputs> = picks
        .iter()
        .map(|o| eval_inputs(ds, o.theta_deg, scan_load, sym, p))
        .collect();
    let stored: Vec<Option<EvalStage>> = picks
        .iter()
        .zip(&inputs)
        .map(|(o, i)| store.load_json::<EvalStage>(&rel(o), i))
        .collect::<Result<_>>()?;
    let reused = stored.iter().flatten().count();
    if reused > 0 {
        progress.advance((reused * per) as u64);
    }
    // at most `per` ticks per orientation; the rest when it is done
    let ticks: Vec<AtomicUsize> = picks.iter().map(|_| AtomicUsize::new(0)).collect();
    let tick = |k: usize| {
        if ticks[k].fetch_add(1, Relaxed) < per {
            progress.advance(1);
        }
    };
    let todo: Vec<usize> = (0..picks.len()).filter(|&k| stored[k].is_none()).collect();
    obs.stage(Stage::AlphaScan, &ds.name);
    let scans: Vec<Result<(super::scan::AlphaScan, f64)>> = todo
        .par_iter()
        .map(|&k| {
            let t0 = Instant::now();
            let s = super::scan::scan_alpha(
                solver,
                &ds.scene,
                picks[k].theta_deg,
                scan_load,
                p,
                sym,
                &|| tick(k),
            )?;
            Ok((s, t0.elapsed().as_secs_f64()))
        })
        .collect();
    let scans: Vec<(super::scan::AlphaScan, f64)> = scans.into_iter().collect::<Result<_>>()?;
    obs.stage(Stage::Estimate, &ds.name);
    let estimates: Vec<Result<(Vec<crate::study::rows::FrictionRow>, f64)>> = todo
        .par_iter()
        .zip(&scans)
        .map(|(&k, (s, _))| {
            let t0 = Instant::now();
            let f = super::scan::estimate(
                solver,
                &ds.scene,
                picks[k].theta_deg,
                scan_load,
                s,
                p,
                &|| tick(k),
            )?;
            Ok((f, t0.elapsed().as_secs_f64()))
        })
        .collect();
    let mut fresh: Vec<Option<EvalStage>> = picks.iter().map(|_| None).collect();
    for ((&k, (s, scan_s)), e) in todo.iter().zip(scans).zip(estimates) {
        let (friction, est_s) = e?;
        let done = ticks[k].load(Relaxed);
        if done < per {
            progress.advance((per - done) as u64);
        }
        let st = EvalStage {
            eval: ThetaEval {
                theta_deg: label(picks[k].theta_deg),
                scan_load_mN: label(n_to_mn(scan_load)),
                line_deg: rad_to_deg(s.line),
                scan: s.scan,
                alphas_deg: s.alphas_deg,
                friction,
            },
            wall_s: scan_s + est_s,
        };
        store.save_json(&rel(&picks[k]), &inputs[k], &st)?;
        fresh[k] = Some(st);
    }
    stored
        .into_iter()
        .zip(fresh)
        .map(|(old, new)| match (old, new) {
            (Some(st), _) => Ok((st.eval, st.wall_s, true)),
            (None, Some(st)) => Ok((st.eval, st.wall_s, false)),
            (None, None) => Err(anyhow::anyhow!(
                "an orientation was neither stored nor evaluated"
            )),
        })
        .collect()
}
