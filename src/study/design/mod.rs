//! # `superlube design`: screen → shortlist → α scan and friction estimate → ranking → DEM
//!
//! For one or more pattern pairs, a range of orientations θ and a list of loads, the design
//! answers: *which orientation θ and pulling direction α keep friction ultra-low without coating
//! failure, up to which load, and how sure are we?* [`design`] runs the stages in order:
//!
//! 1. **Symmetry cut** ([`symmetry`]): θ is cut to the pair's fundamental domain (square-tri
//!    0–15°, tri-tri 0–30°); the α scan covers one α period.
//! 2. **Screen** every θ × W ([`crate::study::screen`]): contacts, P_max, coating failure.
//! 3. **Shortlist** ([`shortlist`]): per θ the load `W_c` up to which the coating stays intact;
//!    every orientation that survives the highest load, plus the best few of each lower load
//!    level, evaluated level by level from the top until no lower level can reach the best
//!    superlubric load found.
//! 4. **α scan and friction estimate** per shortlisted θ ([`scan`]): contact line, corrugation
//!    versus α (coarse grid, then refined near the minimum), the friction estimate μ_est
//!    (`surrogate::friction`) along the best α's at every load.
//! 5. **Ranking** ([`rank`]): score = the robust limit, the highest load up to which
//!    superlubric (coating intact on the sliding path AND μ_est < 0.02 at every load up to it)
//!    at every sample of the tolerance box ([`robust`]), then the θ window, the direction
//!    window, μ_est, contacts.
//! 6. **DEM confirmation** ([`confirm`]): the top `confirm` designs of each pattern at the
//!    confirmation loads and at the corners of their tolerance boxes (borderline designs
//!    first), independent `slide` runs side by side, one thread each (plus, with a
//!    protocol shorter than the study's, the design the report recommends once with the study's
//!    protocol to measure the difference there: [`protocol_check_design`]).
//! 7. **Outputs**: [`design`] hands each pattern's result to the command's hook as soon as the
//!    pattern is complete (its own CSVs and PNGs are written then), keeps only what the later
//!    stages and the report need of it ([`PatternResult::trim`]: memory flat in the number of
//!    patterns) and returns the [`DesignOutcome`]; the command then writes `report.md` (the
//!    answer first) and the global CSVs with sidecars (`crate::present::design_report`, a
//!    layer above this one).
//!
//! Every stage is stored under the output directory with the inputs that made it
//! ([`store`]): a re-run with the same `--out-dir` reuses every finished stage and DEM run, and one
//! with other inputs is refused with the differences named.

pub mod answer;
pub mod best;
pub mod confirm;
pub mod params;
pub mod rank;
pub mod robust;
pub mod scan;
pub mod shortlist;
pub mod store;
pub mod symmetry;
pub mod trim;

pub use params::{DesignParams, DesignScene};

use super::meta::{scene_file, Inputs};
use super::progress::Progress;
use super::record;
use super::rows::{label, ScreenRow};
use super::screen::{screen, ScreenParams};
use super::sink::csv_bytes;
use super::tolerance::{LimitParams, ToleranceBox};
use anyhow::{bail, Result};
use confirm::{confirm_estimates, confirm_jobs, confirm_stage, run_batch, SlideOutcome};
pub use confirm::{dem_params, loads_to_confirm, protocol_check_design, run_name};
use rank::Candidate;
use rayon::prelude::*;
use scan::ThetaEval;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use shortlist::{Level, Orientation};
use std::time::Instant;
use store::Store;
use surrogate::solver::{Model, SearchKind, Solver};
use surrogate::units::{deg_to_rad, m_to_um, n_to_mn, rad_to_deg};
use symmetry::PairSymmetry;

/// Default θ step (degrees) over a domain up to [`WIDE_DOMAIN_DEG`] wide (the study's 0.1°).
pub const THETA_STEP_DEG: f64 = 0.1;
/// Width (degrees) above which a domain is screened at [`WIDE_THETA_STEP_DEG`] by default.
pub const WIDE_DOMAIN_DEG: f64 = 60.0;
/// Default θ step (degrees) over a wider domain (the full 360° of an underived symmetry: 1 440
/// θ, about 1.7 s of screen for a 3 500-sphere slider at 1.2 ms per θ × 11 loads,
/// `docs/validation/screen.md`).
pub const WIDE_THETA_STEP_DEG: f64 = 0.25;

/// Without `--theta` (`p.theta_default`) and with the cut: the θ list of the whole fundamental
/// domain of `sym` at the default step ([`THETA_STEP_DEG`], [`WIDE_THETA_STEP_DEG`] over a
/// domain wider than [`WIDE_DOMAIN_DEG`]) when the default list `0:30:0.1` does not span the
/// domain (a pattern whose symmetry was not derived, or a domain wider than 30°); `None` where
/// the default list spans it (the presets: their cut default list, unchanged). Also the step.
pub fn default_domain(sym: &PairSymmetry, p: &DesignParams) -> Option<(Vec<f64>, f64)> {
    if !p.theta_default || !p.symmetry_cut {
        return None;
    }
    let cut: Vec<f64> = p
        .thetas_deg
        .iter()
        .copied()
        .filter(|&t| sym.contains(t))
        .collect();
    if !cut.is_empty() && sym.unscreened(&cut).is_empty() {
        return None;
    }
    let (lo, hi, closed) = sym.domain();
    let step = if hi - lo > WIDE_DOMAIN_DEG + 1e-9 {
        WIDE_THETA_STEP_DEG
    } else {
        THETA_STEP_DEG
    };
    let text = format!("{}:{}:{}", symmetry::fmt(lo), symmetry::fmt(hi), step);
    let mut v = super::range::parse_list_or_range(&text, "--theta").ok()?;
    if !closed {
        v.retain(|&t| t < hi - 1e-9);
    }
    Some((v, step))
}

/// What the log and the report say of a pattern's θ list beside its symmetry: that `--theta`
/// was not given and the whole domain is screened at the default step (when
/// [`default_domain`] applies), or which part of the domain the θ list leaves out
/// ([`PairSymmetry::unscreened`]); `None` when the list spans the domain as asked.
pub fn theta_note(sym: &PairSymmetry, thetas_deg: &[f64], p: &DesignParams) -> Option<String> {
    let gaps = sym.unscreened(thetas_deg);
    if !gaps.is_empty() {
        let (lo, hi, closed) = sym.domain();
        return Some(format!(
            "the θ list does not cover the domain [{}°, {}°{}: {} not screened (give --theta over the whole domain{})",
            symmetry::fmt(lo),
            symmetry::fmt(hi),
            if closed { "]" } else { ")" },
            sym.gaps_text(&gaps),
            if p.theta_default {
                ""
            } else {
                ", or leave --theta out to screen it at the default step"
            }
        ));
    }
    let (_, step) = default_domain(sym, p)?;
    Some(format!(
        "no --theta given: the whole domain at {step}° ({} θ{})",
        thetas_deg.len(),
        if step == WIDE_THETA_STEP_DEG {
            format!(
                "; {step}° rather than {THETA_STEP_DEG}° for a domain wider than {WIDE_DOMAIN_DEG}°"
            )
        } else {
            String::new()
        }
    ))
}

/// Without `--line-deg`, for a pattern with a site file: that α is measured from the substrate
/// x axis, since the file's body has no lattice for the moiré contact-line estimate
/// ([`crate::study::corrugation::contact_line`]); `None` otherwise.
pub fn line_note(ds: &DesignScene, p: &DesignParams) -> Option<String> {
    if p.line.is_some() {
        return None;
    }
    let why = super::corrugation::site_file_body(&ds.scene)?;
    Some(format!(
        "{why}, which has no lattice for the moiré contact-line estimate: α is measured from the substrate x axis (0°; --line-deg sets the line), and the α scan covers a whole α period from it"
    ))
}

/// The θ values (degrees) of `ds` after the symmetry cut, and the pair's symmetry. Without
/// `--theta`, the whole domain where the default list does not span it ([`default_domain`]).
/// Errors (naming `--theta`) when none is left.
pub fn cut(ds: &DesignScene, p: &DesignParams) -> Result<(Vec<f64>, PairSymmetry)> {
    let sym = PairSymmetry::of_scene(&ds.scene);
    if let Some((v, _)) = default_domain(&sym, p) {
        return Ok((v, sym));
    }
    if !p.symmetry_cut {
        return Ok((p.thetas_deg.clone(), sym));
    }
    let kept: Vec<f64> = p
        .thetas_deg
        .iter()
        .copied()
        .filter(|&t| sym.contains(t))
        .collect();
    if kept.is_empty() {
        let (lo, hi, closed) = sym.domain();
        let t = p.thetas_deg[0];
        bail!(
            "`--theta`: none of `{}` lies in the fundamental domain [{}°, {}°{} of {} ({}); every orientation is equivalent to one in it (e.g. {}° ≡ {}°): give θ in [{}, {}], or pass --no-symmetry-cut",
            p.theta_text,
            symmetry::fmt(lo),
            symmetry::fmt(hi),
            if closed { "]" } else { ")" },
            ds.name,
            sym.describe(),
            symmetry::fmt(t),
            symmetry::fmt(sym.fold(t)),
            symmetry::fmt(lo),
            symmetry::fmt(hi)
        );
    }
    Ok((kept, sym))
}

/// A stage's record of its own wall time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Timing {
    /// Wall time of the stage when it was computed (s).
    pub wall_s: f64,
}

/// An orientation's evaluation as stored (`stages/<pattern>/theta_<θ>.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EvalStage {
    /// The evaluation.
    pub eval: ThetaEval,
    /// Its wall time when computed (s).
    pub wall_s: f64,
}

/// One evaluated orientation of a pattern.
#[derive(Debug, Clone)]
pub struct Evaluated {
    /// The screen's view of it.
    pub orientation: Orientation,
    /// Why it was shortlisted.
    pub reason: String,
    /// The α scan and friction estimate.
    pub eval: ThetaEval,
    /// Wall time when computed (s).
    pub wall_s: f64,
    /// Reused from an earlier run.
    pub reused: bool,
    /// α of each row of the scan (degrees, scan order): kept when [`PatternResult::trim`]
    /// drops `eval.scan`.
    pub scan_alphas_deg: Vec<f64>,
    /// Number of friction estimates (rows of `eval.friction`, kept when trimmed).
    pub estimates: usize,
}

/// Everything the design found for one pattern.
#[derive(Debug, Clone)]
pub struct PatternResult {
    /// The pattern.
    pub scene: DesignScene,
    /// Its symmetry.
    pub sym: PairSymmetry,
    /// θ screened (degrees, after the cut).
    pub thetas_deg: Vec<f64>,
    /// The screen rows (θ outer, loads inner).
    pub screen: Vec<ScreenRow>,
    /// Wall time of the screen when computed (s; `None` if not recorded).
    pub screen_wall_s: Option<f64>,
    /// The orientations (θ order) and the levels of the shortlist.
    pub orientations: Vec<Orientation>,
    /// The levels of the shortlist, highest first.
    pub levels: Vec<Level>,
    /// How many levels were evaluated (from the top).
    pub levels_evaluated: usize,
    /// Why the evaluation stopped.
    pub stop: String,
    /// The evaluated orientations, in evaluation order.
    pub evaluated: Vec<Evaluated>,
    /// The candidates, best first (below the top few, each with its lowest-load friction
    /// row only once trimmed: [`PatternResult::trim`]).
    pub ranking: Vec<Candidate>,
    /// Candidates with a load whose failed contacts sit on a mount in resonance (counted over
    /// every friction row before the rows are trimmed; [`trim::resonance_flagged`]).
    pub resonance_flagged: usize,
    /// Whether [`PatternResult::trim`] dropped the bulky rows (screen, orientations, α scans,
    /// friction rows below the top few).
    pub trimmed: bool,
}

/// One DEM confirmation run and what it is compared with.
#[derive(Debug, Clone)]
pub struct DemEntry {
    /// Pattern name.
    pub pattern: String,
    /// Rank of the design within its pattern.
    pub rank: usize,
    /// θ (degrees).
    pub theta_deg: f64,
    /// α (degrees).
    pub alpha_deg: f64,
    /// Load (N).
    pub load: f64,
    /// The study's protocol (the protocol-check run) rather than the design's.
    pub study_protocol: bool,
    /// θ offset (degrees) from the design for a tolerance-corner run (0: the design itself).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees, substrate frame) for a tolerance-corner run.
    pub direction_offset_deg: f64,
    /// The run.
    pub outcome: SlideOutcome,
}

/// What [`design`] found.
#[derive(Debug, Clone)]
pub struct DesignOutcome {
    /// Per pattern, in the order given; trimmed ([`PatternResult::trim`]) once handed to the
    /// design's hook.
    pub patterns: Vec<PatternResult>,
    /// The DEM runs (empty with `--no-dem`).
    pub dem: Vec<DemEntry>,
    /// Whether the DEM stage ran.
    pub dem_ran: bool,
    /// The answer per pattern (the ranking checked against the DEM, [`answer`]).
    pub answers: Vec<answer::Answer>,
    /// Per pattern, the tolerance map around its answer (θ points per row, rows) when the
    /// design has a tolerance ([`answer_map`]).
    pub maps: Vec<Option<AnswerMap>>,
}

/// The tolerance map around a pattern's answer (`tolerance_<pattern>.csv/.png`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AnswerMap {
    /// θ (degrees) and pulling direction (degrees from x) of the answer.
    pub nominal: (f64, f64),
    /// Grid points along θ (the rows run direction outer, θ inner).
    pub theta_points: usize,
    /// The map's rows.
    pub rows: Vec<crate::study::tolerance::ToleranceRow>,
}

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
/// (recorded in the final outputs' sidecars). Never recorded: `--confirm`, `--confirm-loads`,
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

/// File-name form of a number (`0.35`, `-15`).
pub fn tag(v: f64) -> String {
    format!("{}", label(v))
}

/// What [`design`] calls with each pattern's complete result (its friction estimates for the
/// DEM included), in pattern order, before trimming it: the command writes the pattern's own
/// files there. Not called in a DEM shard (`--shard`: no outputs).
pub type PatternHook<'a> = &'a dyn Fn(&PatternResult) -> Result<()>;

/// Runs the design (see the module docs) into `store`; reports progress through `progress`;
/// hands each pattern to `on_pattern` when complete, then trims it ([`PatternResult::trim`]),
/// so memory does not grow with the pattern's rows: the outcome's patterns are trimmed.
pub fn design(
    scenes: &[DesignScene],
    p: &DesignParams,
    store: &Store,
    progress: &dyn Progress,
    on_pattern: PatternHook,
) -> Result<DesignOutcome> {
    if store.claim(&inputs(scenes, p, false), "--out-dir")? {
        progress.note(&format!(
            "{}: a design of the same inputs is there: finished stages are reused",
            store.dir().display()
        ));
    }
    // 1–5 per pattern: cut, screen, shortlist, α scan + friction, ranking
    // (with the DEM: the estimates it is compared with, per pattern), then the pattern's own
    // outputs through the hook, then only what the rest needs is kept
    let mut patterns: Vec<PatternResult> = Vec::new();
    for ds in scenes {
        let mut pr = pattern(ds, p, store, progress)?;
        if !p.no_dem {
            confirm_estimates(std::slice::from_mut(&mut pr), p, store)?;
        }
        pr.resonance_flagged = trim::resonance_flagged(&pr.ranking);
        if p.dem_shard.is_all() {
            on_pattern(&pr)?;
        }
        pr.trim(p);
        patterns.push(pr);
    }
    // 6. DEM confirmation
    if !p.no_dem && !p.dem_shard.is_all() {
        // a shard of the DEM stage: its share of the runs, no report
        let (jobs, _) = confirm_jobs(&patterns, p);
        let part = p.dem_shard.range(jobs.len());
        progress.note(&format!(
            "DEM shard {}/{}: runs {}..{} of {} into {}; run the design without --shard (same --out-dir, every shard's dem/ runs in it) to write the report",
            p.dem_shard.index,
            p.dem_shard.count,
            part.start,
            part.end,
            jobs.len(),
            store.path("dem").display()
        ));
        let dem: Vec<SlideOutcome> = if part.is_empty() {
            Vec::new()
        } else {
            run_batch(&jobs[part], p.jobs, &store.path("dem"), progress)?
        };
        let failed = dem.iter().filter(|o| o.error.is_some()).count();
        if failed > 0 {
            progress.note(&format!("DEM shard: {failed} run(s) failed"));
        }
        return Ok(DesignOutcome {
            patterns,
            dem: Vec::new(),
            dem_ran: false,
            answers: Vec::new(),
            maps: Vec::new(),
        });
    }
    let dem = if p.no_dem {
        Vec::new()
    } else {
        confirm_stage(&patterns, p, store, progress)?
    };
    let answers = patterns
        .iter()
        .map(|pr| answer::answer(pr, &dem, !p.no_dem, p))
        .collect();
    let answers: Vec<answer::Answer> = answers;
    let mut maps = Vec::new();
    for (pr, a) in patterns.iter().zip(&answers) {
        let c = a.index.and_then(|i| pr.ranking.get(i));
        maps.push(match c {
            Some(c) if !tolerance_box(p).is_point() && c.score.nominal_to_mn > 0.0 => {
                Some(answer_map(&pr.scene, c, p, store, progress)?)
            }
            _ => None,
        });
    }
    Ok(DesignOutcome {
        patterns,
        dem,
        dem_ran: !p.no_dem,
        answers,
        maps,
    })
}

/// Stages 1–5 for one pattern.
fn pattern(
    ds: &DesignScene,
    p: &DesignParams,
    store: &Store,
    progress: &dyn Progress,
) -> Result<PatternResult> {
    let name = &ds.name;
    let (thetas_deg, sym) = cut(ds, p)?;
    match theta_note(&sym, &thetas_deg, p) {
        // the presets' line, unchanged
        None => progress.note(&format!(
            "{name}: {}; {} of {} θ screened{}",
            sym.describe(),
            thetas_deg.len(),
            p.thetas_deg.len(),
            if p.symmetry_cut {
                ""
            } else {
                " (no symmetry cut)"
            }
        )),
        Some(note) => progress.note(&format!(
            "{name}: {}; {} θ screened{}; {note}",
            sym.describe(),
            thetas_deg.len(),
            if p.symmetry_cut {
                ""
            } else {
                " (no symmetry cut)"
            }
        )),
    }
    if let Some(n) = line_note(ds, p) {
        progress.note(&format!("{name}: note: {n}"));
    }
    if p.symmetry_cut && (ds.scene.substrate.sigma_h > 0.0 || ds.scene.slider.offset != [0.0; 2]) {
        progress.note(&format!(
            "{name}: note: the symmetry cut is exact for a flat substrate with the slider centred on a site; {}",
            if ds.scene.slider.offset != [0.0; 2] {
                "this slider is offset, so the cut is approximate (--no-symmetry-cut screens the whole range)"
            } else {
                "with σ_h > 0 it holds statistically"
            }
        ));
    }
    // 2. screen
    let (screen_rows, screen_wall_s) = screen_stage(ds, &thetas_deg, p, store, progress)?;
    // 3. shortlist
    let orientations = shortlist::orientations(&screen_rows, &p.loads, ds.scene.coating.p_crit);
    let levels = shortlist::levels(&orientations, &p.loads, p.per_level, p.max_top);
    if levels.is_empty() {
        progress.note(&format!(
            "{name}: no orientation keeps the coating intact even at the lowest load"
        ));
    }
    // 4. α scan + friction, level by level
    let need = p.confirm.max(3);
    let mut evaluated: Vec<Evaluated> = Vec::new();
    let mut ranking: Vec<Candidate> = Vec::new();
    let mut best = 0.0f64; // best superlubric load so far (mN)
    let mut levels_evaluated = 0;
    let mut stop = "every level evaluated".to_string();
    let mut solver: Option<Solver> = None;
    let bx = tolerance_box(p);
    let limit = LimitParams {
        loads: p.loads.clone(),
        mu_superlubric: p.mu_superlubric,
        line: p.line,
        friction: p.friction,
    };
    let solvers: Vec<Solver> = if bx.is_point() {
        Vec::new()
    } else {
        seed_solvers(ds, p, None)?
    };
    let mut searches = robust::Searches::new(ds, p, &solvers, &limit, store)?;
    for level in &levels {
        let from = ranking.len();
        let w_mn = label(n_to_mn(level.load));
        if w_mn < best && ranking.len() >= need {
            stop = format!(
                "stopped before level {}: its orientations cannot be superlubric beyond {} mN < the best found, {} mN",
                shortlist::mn(level.load),
                w_mn,
                best
            );
            break;
        }
        levels_evaluated += 1;
        let reason = if level.top {
            "survives the highest load".to_string()
        } else {
            format!("best of level {}", shortlist::mn(level.load))
        };
        let per = scan::paths_per_scan(p, &sym) + p.alphas_per_theta;
        progress.stage(
            &format!(
                "{name}: α scan + friction, level {} ({} of {} θ)",
                shortlist::mn(level.load),
                level.picks.len(),
                level.size
            ),
            (level.picks.len() * per) as u64,
            "paths",
        );
        let s = solver_of(&mut solver, ds)?;
        // the level's orientations in parallel (each also parallel inside), results in order
        let done: Vec<Result<(ThetaEval, f64, bool)>> = level
            .picks
            .par_iter()
            .map(|o| eval_stage(ds, o, level.load, &sym, p, store, s, per, progress))
            .collect();
        for (o, r) in level.picks.iter().zip(done) {
            let (eval, wall_s, reused) = r?;
            let scan_alphas_deg = eval.scan.iter().map(|r| r.alpha_deg).collect();
            let estimates = eval.friction.len();
            ranking.extend(rank::candidates(
                name,
                &eval,
                label(n_to_mn(level.load)),
                &reason,
                ds.scene.coating.p_crit,
                p.mu_superlubric,
            ));
            evaluated.push(Evaluated {
                orientation: o.clone(),
                reason: reason.clone(),
                eval,
                wall_s,
                reused,
                scan_alphas_deg,
                estimates,
            });
        }
        progress.finish();
        // the robust limits of this level's candidates (the stop rule above then compares
        // each level's bound with the best robust limit: a robust design may sit lower)
        if !bx.is_point() && ranking[from..].iter().any(|c| c.score.nominal_to_mn > 0.0) {
            robust::robust_stage(ds, &mut ranking, &mut searches, p, store, progress)?;
        }
        best = ranking
            .iter()
            .filter(|c| c.score.exact)
            .map(|c| c.score.superlubric_to_mn)
            .fold(best, f64::max);
    }
    // 5. ranking (by the robust limit with a tolerance: computed level by level above)
    ranking.sort_by(rank::compare);
    if let Some(b) = ranking.first() {
        progress.note(&format!(
            "{name}: the estimate's best design: θ = {}°, α = {}°, superlubric up to {} mN (μ_est ≤ {:.4}); {} orientations evaluated ({stop})",
            b.theta_deg,
            b.alpha_deg,
            b.score.superlubric_to_mn,
            b.score.mu_worst,
            evaluated.len()
        ));
    }
    Ok(PatternResult {
        scene: ds.clone(),
        sym,
        thetas_deg,
        screen: screen_rows,
        screen_wall_s,
        orientations,
        levels,
        levels_evaluated,
        stop,
        evaluated,
        ranking,
        resonance_flagged: 0,
        trimmed: false,
    })
}

/// The pattern's solver (slider at θ = 0, each query rotates it), built on first use in `slot`.
/// Cost: one scene build and pair-search setup, once.
pub(super) fn solver_of<'a>(slot: &'a mut Option<Solver>, ds: &DesignScene) -> Result<&'a Solver> {
    if slot.is_none() {
        let mut sc = ds.scene.clone();
        sc.slider.theta = 0.0;
        *slot = Some(Solver::new(&sc)?);
    }
    slot.as_ref().ok_or_else(|| anyhow::anyhow!("no solver"))
}

/// The tolerance box of the design's `--theta-tol` × `--direction-tol`.
pub fn tolerance_box(p: &DesignParams) -> ToleranceBox {
    ToleranceBox::new(
        p.theta_tol_deg,
        p.direction_tol_deg,
        p.theta_tol_step_deg,
        p.direction_tol_step_deg,
    )
}

/// The recorded inputs of a superlubric limit (loads, threshold, contact line, estimate knobs).
fn limit_record(p: &DesignParams) -> Value {
    json!({
        "load_mN": p.loads.iter().map(|&w| label(n_to_mn(w))).collect::<Vec<_>>(),
        "mu_superlubric": p.mu_superlubric,
        "line_deg": p.line.map(rad_to_deg),
        "friction": record::friction_knobs(&p.friction),
    })
}

/// One solver per substrate realisation: the scene's own (reusing `own` when built), then one
/// per extra seed of `p.seeds`.
fn seed_solvers(ds: &DesignScene, p: &DesignParams, own: Option<Solver>) -> Result<Vec<Solver>> {
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
fn screen_inputs(ds: &DesignScene, sp: &ScreenParams) -> Inputs {
    let mut recorded = scene_file(&ds.scene);
    recorded.slider.theta_deg = None;
    Inputs {
        workflow: "screen".into(),
        scene: Some(recorded),
        params: record::screen(sp),
    }
}

/// Stage 2: the screen of one pattern (`screen_<name>.csv`), reused when finished.
fn screen_stage(
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
fn eval_inputs(
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
fn eval_stage(
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
    let rel = format!("stages/{}/theta_{}.json", ds.name, tag(o.theta_deg));
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
    let eval = scan::evaluate(solver, &ds.scene, o.theta_deg, scan_load, p, sym, &tick)?;
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

#[cfg(test)]
mod tests {
    use super::answer::{Answer, Check};
    use super::rank::{Candidate, Score};
    use super::*;

    fn pattern(name: &str, n: usize) -> PatternResult {
        let scene = surrogate::Scene::preset(name).unwrap();
        let sym = PairSymmetry::of(&scene.slider.lattice, &scene.substrate.lattice);
        let ranking = (0..n)
            .map(|k| Candidate {
                pattern: name.into(),
                theta_deg: k as f64,
                alpha_deg: 90.0,
                line_deg: 0.0,
                direction_deg: 90.0,
                corrugation_nm: 0.1,
                scan_load_mn: 3.86,
                screen_intact_to_mn: 3.86,
                reason: String::new(),
                friction: vec![],
                corners: vec![],
                score: Score {
                    superlubric_to_mn: 3.86,
                    nominal_to_mn: 3.86,
                    theta_window_deg: None,
                    direction_window_deg: None,
                    verdict: crate::study::verdict::Verdict::Superlubric,
                    exact: true,
                    intact_to_mn: 3.86,
                    mu_worst: 0.01,
                    contacts: 100.0,
                    seed_limits_mn: None,
                },
            })
            .collect();
        PatternResult {
            scene: DesignScene {
                name: name.into(),
                scene,
                flags: vec![],
                warnings: vec![],
                facts: None,
            },
            sym,
            thetas_deg: vec![],
            screen: vec![],
            screen_wall_s: None,
            orientations: vec![],
            levels: vec![],
            levels_evaluated: 0,
            stop: String::new(),
            evaluated: vec![],
            ranking,
            resonance_flagged: 0,
            trimmed: false,
        }
    }

    /// A design is confirmed at the confirmation loads and at its own superlubric load (once,
    /// in order); a design superlubric nowhere only at the confirmation loads.
    #[test]
    fn each_design_is_also_confirmed_at_its_own_limit() {
        let loads = [0.35e-3, 1.75e-3, 2.1e-3, 2.45e-3, 3.86e-3];
        let confirm = [0.35e-3, 2.1e-3, 3.86e-3];
        let mut c = pattern("tri-tri", 1).ranking.remove(0);
        c.score.superlubric_to_mn = 2.45;
        assert_eq!(
            loads_to_confirm(&c, &confirm, &loads),
            vec![0.35e-3, 2.1e-3, 2.45e-3, 3.86e-3]
        );
        c.score.superlubric_to_mn = 2.1;
        assert_eq!(loads_to_confirm(&c, &confirm, &loads), confirm.to_vec());
        c.score.superlubric_to_mn = 0.0;
        assert_eq!(loads_to_confirm(&c, &confirm, &loads), confirm.to_vec());
    }

    /// The study-protocol check runs on the recommended design: the first *confirmed* answer
    /// (not the estimate's rank 1, which the DEM may contradict), at the middle of its confirmed
    /// loads; without a confirmed answer, the first pattern's answer at the middle load.
    #[test]
    fn protocol_check_runs_on_the_recommended_design() {
        let pats = vec![pattern("square-tri", 3), pattern("tri-tri", 3)];
        let loads = [0.35e-3, 2.1e-3, 3.86e-3];
        let contradicted = Answer {
            index: Some(0),
            check: Check::Contradicted("P_max above P_crit".into()),
            others: vec![],
        };
        // square-tri: rank 1 contradicted, rank 3 confirmed at 0.35 and 2.1 mN
        let answers = vec![
            Answer {
                index: Some(2),
                check: Check::Confirmed(vec![0.35, 2.1]),
                others: vec![(1, Check::Contradicted("x".into()))],
            },
            contradicted.clone(),
        ];
        let (pr, i, w) = protocol_check_design(&pats, &answers, &loads).unwrap();
        assert_eq!((pr.scene.name.as_str(), i, w), ("square-tri", 2, 2.1e-3));
        // the first pattern unconfirmed, the second confirmed at one load: the second
        let answers = vec![
            contradicted.clone(),
            Answer {
                index: Some(1),
                check: Check::Confirmed(vec![0.35]),
                others: vec![],
            },
        ];
        let (pr, i, w) = protocol_check_design(&pats, &answers, &loads).unwrap();
        assert_eq!((pr.scene.name.as_str(), i, w), ("tri-tri", 1, 0.35e-3));
        // none confirmed: the first pattern's answer at the middle confirmation load
        let answers = vec![contradicted.clone(), contradicted];
        let (pr, i, w) = protocol_check_design(&pats, &answers, &loads).unwrap();
        assert_eq!((pr.scene.name.as_str(), i, w), ("square-tri", 0, 2.1e-3));
        // no ranked design at all
        let none = Answer {
            index: None,
            check: Check::Unchecked,
            others: vec![],
        };
        assert!(protocol_check_design(&pats, &[none.clone(), none], &loads).is_none());
    }
}
