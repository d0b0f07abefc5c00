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
mod domain;
mod outcome;
pub mod params;
pub mod rank;
pub mod robust;
pub mod scan;
pub mod shortlist;
mod stages;
pub mod store;
pub mod symmetry;
pub mod trim;

pub use domain::{
    cut, default_domain, line_note, theta_note, ThetaNote, THETA_STEP_DEG, WIDE_DOMAIN_DEG,
    WIDE_THETA_STEP_DEG,
};
pub use outcome::{
    AnswerMap, DemEntry, DesignOutcome, EvalStage, Evaluated, PatternResult, Timing,
};
pub use stages::{answer_map, inputs, screen_params, tolerance_box};
use stages::{eval_stage, limit_record, screen_stage, seed_solvers};

pub use params::{DesignParams, DesignScene};

use super::rows::label;
use super::tolerance::LimitParams;
use crate::runs::progress::Progress;
use anyhow::Result;
use confirm::{confirm_estimates, confirm_jobs, confirm_stage, run_batch, SlideOutcome};
pub use confirm::{dem_params, loads_to_confirm, protocol_check_design, run_name};
use rank::Candidate;
use rayon::prelude::*;
use scan::ThetaEval;
use store::Store;
use surrogate::solver::Solver;
use surrogate::units::n_to_mn;

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
    if store.claim(&inputs(scenes, p, false))? {
        progress.note(&format!(
            "{}: a design of the same inputs is there: finished stages are reused",
            store.dir().display()
        ));
    }
    // 1–5 per pattern: cut, screen, shortlist, α scan + friction, ranking
    // (with the DEM: the estimates it is compared with, per pattern), then the pattern's own
    // outputs through the hook, then only what the rest needs is kept; with many patterns and
    // a tolerance, in the order of their nominal limits, each robust search above a floor
    // ([`robust_order`])
    let (order, cross) = robust_order(scenes, p, store, progress)?;
    let mut done: Vec<Option<PatternResult>> = vec![None; scenes.len()];
    let mut best_robust: Vec<f64> = Vec::new();
    for i in order {
        let ds = &scenes[i];
        let floor = if cross && best_robust.len() >= best::BEST_PATTERNS {
            best_robust[best::BEST_PATTERNS - 1]
        } else {
            0.0
        };
        let search = Search::Robust {
            floor_mn: floor,
            // across many patterns only each one's best counts (without the DEM, which
            // confirms each pattern's top designs)
            keep: if cross && p.no_dem {
                1
            } else {
                p.confirm.max(3)
            },
        };
        let mut pr = pattern(ds, p, store, progress, search)?;
        pr.robust_floor_mn = floor;
        if let Some(c) = pr.ranking.first().filter(|c| c.score.exact) {
            best_robust.push(c.score.superlubric_to_mn);
            best_robust.sort_by(|a, b| b.total_cmp(a));
        }
        if !p.no_dem {
            confirm_estimates(std::slice::from_mut(&mut pr), p, store)?;
        }
        pr.resonance_flagged = trim::resonance_flagged(&pr.ranking);
        if p.dem_shard.is_all() {
            on_pattern(&pr)?;
        }
        pr.trim(p);
        done[i] = Some(pr);
    }
    let patterns: Vec<PatternResult> = done.into_iter().flatten().collect();
    // 6. DEM confirmation
    if !p.no_dem && !p.dem_shard.is_all() {
        // a shard of the DEM stage: its share of the runs, no report
        let (jobs, _) = confirm_jobs(&patterns, p);
        let part = p.dem_shard.range(jobs.len());
        progress.note(&format!(
            "DEM shard {}/{}: runs {}..{} of {} into {}; run the design without {} (same {}, every shard's dem/ runs in it) to write the report",
            p.dem_shard.index,
            p.dem_shard.count,
            part.start,
            part.end,
            jobs.len(),
            store.path("dem").display(),
            crate::study::input::Input::Shard,
            crate::study::input::Input::OutDir
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
    let mut o = DesignOutcome {
        patterns,
        dem,
        dem_ran: !p.no_dem,
        answers,
        maps: Vec::new(),
    };
    // the tolerance maps: every pattern's answer, or with the floor, the best patterns' only
    let mapped = best::best_order(&o, best::BEST_PATTERNS);
    for (i, (pr, a)) in o.patterns.iter().zip(&o.answers).enumerate() {
        let c = a.index.and_then(|i| pr.ranking.get(i));
        o.maps.push(match c {
            Some(c)
                if !tolerance_box(p).is_point()
                    && c.score.nominal_to_mn > 0.0
                    && (!cross || mapped.contains(&i)) =>
            {
                Some(answer_map(&pr.scene, c, p, store, progress)?)
            }
            _ => None,
        });
    }
    Ok(o)
}

/// The order in which [`design`] takes the patterns, and whether a robust floor applies.
///
/// With more than [`best::BEST_PATTERNS`] patterns and a tolerance, every pattern is first
/// evaluated at its nominal orientation only (stages 1–5 without the robust search; stored,
/// so the second pass reuses them): the patterns are then taken best nominal design first
/// ([`rank::compare`]), and a pattern's candidates whose nominal limit is at most the
/// [`best::BEST_PATTERNS`]-th best robust limit found so far are not searched over the
/// tolerance box (the robust limit never exceeds the nominal one, so they cannot enter the
/// top). Otherwise the order given, no floor. Cost: the nominal pass, about the design at
/// tolerance 0 (docs/validation/tolerance-cost.md).
fn robust_order(
    scenes: &[DesignScene],
    p: &DesignParams,
    store: &Store,
    progress: &dyn Progress,
) -> Result<(Vec<usize>, bool)> {
    let given: Vec<usize> = (0..scenes.len()).collect();
    if tolerance_box(p).is_point() || scenes.len() <= best::BEST_PATTERNS {
        return Ok((given, false));
    }
    progress.note(&format!(
        "design: {} patterns: each at its nominal orientation first, to search the tolerance boxes best first across patterns",
        scenes.len()
    ));
    let mut firsts: Vec<(usize, Option<Candidate>)> = Vec::new();
    for (i, ds) in scenes.iter().enumerate() {
        let pr = pattern(ds, p, store, progress, Search::Nominal)?;
        firsts.push((
            i,
            pr.ranking.into_iter().next().map(|mut c| {
                c.friction.truncate(1);
                c
            }),
        ));
    }
    // best first; a stable sort keeps the order given among equals
    firsts.sort_by(|(_, a), (_, b)| match (a, b) {
        (Some(x), Some(y)) => rank::compare(x, y),
        (Some(_), None) => std::cmp::Ordering::Less,
        (None, Some(_)) => std::cmp::Ordering::Greater,
        (None, None) => std::cmp::Ordering::Equal,
    });
    Ok((firsts.into_iter().map(|(i, _)| i).collect(), true))
}

/// How [`pattern`] searches the tolerance box.
#[derive(Debug, Clone, Copy)]
enum Search {
    /// No robust search: the nominal limits only (the first pass of [`robust_order`]).
    Nominal,
    /// The robust search ([`robust::robust_stage`]) above `floor_mn` (mN; 0: none), until the
    /// best `keep` designs of the pattern are exact.
    Robust { floor_mn: f64, keep: usize },
}

/// Stages 1–5 for one pattern, searching the tolerance box as `search` says.
fn pattern(
    ds: &DesignScene,
    p: &DesignParams,
    store: &Store,
    progress: &dyn Progress,
    search: Search,
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
            "{name}: {}; {} θ screened{}; {}",
            sym.describe(),
            thetas_deg.len(),
            if p.symmetry_cut {
                ""
            } else {
                " (no symmetry cut)"
            },
            note.text
        )),
    }
    if let Some(n) = line_note(ds, p) {
        progress.note(&format!("{name}: note: {n}"));
    }
    if p.symmetry_cut && (ds.scene.substrate.sigma_h > 0.0 || ds.scene.slider.offset != [0.0; 2]) {
        progress.note(&format!(
            "{name}: note: the symmetry cut is exact for a flat substrate with the slider centred on a site; {}",
            if ds.scene.slider.offset != [0.0; 2] {
                format!(
                    "this slider is offset, so the cut is approximate ({} screens the whole range)",
                    crate::study::input::Input::NoSymmetryCut
                )
            } else {
                "with σ_h > 0 it holds statistically".to_string()
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
    let (robust, floor_mn, keep) = match search {
        Search::Nominal => (false, 0.0, 0),
        Search::Robust { floor_mn, keep } => (!bx.is_point(), floor_mn, keep),
    };
    let limit = LimitParams {
        loads: p.loads.clone(),
        mu_superlubric: p.mu_superlubric,
        line: p.line,
        friction: p.friction,
    };
    let solvers: Vec<Solver> = if !robust {
        Vec::new()
    } else {
        seed_solvers(ds, p, None)?
    };
    let mut searches = robust::Searches::new(ds, p, &solvers, &limit, store)?;
    let mut levels_skipped: Vec<usize> = Vec::new();
    for (li, level) in levels.iter().enumerate() {
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
        // with a floor (many patterns): a level whose orientations cannot exceed it over the
        // tolerance box is evaluated only where the nominal pass evaluated it (stored), for
        // the pattern's own ranking, and skipped otherwise
        if robust && floor_mn > 0.0 {
            let reach = if w_mn <= floor_mn {
                w_mn
            } else {
                robust::level_reach(solver_of(&mut solver, ds)?, level, &bx, p)
            };
            let nominal_best = ranking
                .iter()
                .map(|c| c.score.nominal_to_mn)
                .fold(best, f64::max);
            if reach <= floor_mn && w_mn < nominal_best && ranking.len() >= need {
                levels_skipped.push(li);
                levels_evaluated += 1;
                continue;
            }
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
        if robust && ranking[from..].iter().any(|c| c.score.nominal_to_mn > 0.0) {
            robust::robust_stage(
                ds,
                &mut ranking,
                &mut searches,
                p,
                store,
                progress,
                floor_mn,
                keep,
            )?;
        }
        best = ranking
            .iter()
            .filter(|c| c.score.exact)
            .map(|c| c.score.superlubric_to_mn)
            .fold(best, f64::max);
    }
    if !levels_skipped.is_empty() {
        if stop == "every level evaluated" {
            stop = "every level taken".into();
        }
        stop = format!(
            "{stop}; {} levels skipped: their orientations cannot be superlubric beyond {floor_mn} mN over the tolerance box, the floor of the best {} patterns",
            levels_skipped.len(),
            best::BEST_PATTERNS
        );
    }
    // 5. ranking (by the robust limit with a tolerance: computed level by level above)
    ranking.sort_by(rank::compare);
    let floored = ranking
        .iter()
        .filter(|c| {
            c.score.nominal_to_mn > 0.0 && !c.score.exact && c.score.superlubric_to_mn <= floor_mn
        })
        .count();
    if robust && floored > 0 {
        progress.note(&format!(
            "{name}: {floored} designs searched over the tolerance box only until their bound fell to {floor_mn} mN, the lowest of the best {} patterns' robust limits so far: they cannot enter the best {}",
            best::BEST_PATTERNS,
            best::BEST_PATTERNS
        ));
    }
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
        levels_skipped,
        stop,
        evaluated,
        ranking,
        resonance_flagged: 0,
        robust_floor_mn: 0.0,
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

#[cfg(test)]
mod tests;
