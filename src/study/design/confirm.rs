//! Stage 6 of a design, the DEM confirmation: which runs (the top designs at the confirmation
//! loads and at the corners of their tolerance boxes, borderline designs first), the friction estimates
//! they are compared with, and the batch of independent `slide` runs side by side, one thread
//! each, through the study layer's batch runner [`crate::study::batch`].
//!
//! Each run writes into `dir/<name>/`: `slide.csv`, `slide.json` (or `failed.json`), each with
//! its sidecar; a finished run is reused by its input hash, an interrupted one resumes from its
//! checkpoint `slide.ckpt`; a failing run does not stop the others. Progress: one stage
//! `confirm (DEM)`.

pub use super::dem_entry::{ConfirmEntry, DemEntry, DemProtocol};
pub use crate::study::batch::{
    job_inputs, run_batch, Failure, SlideJob, SlideOutcome, SlideResult,
};

use super::observer::{Event, Observer};
use super::rank::{self, Candidate};
use super::store::Store;
use super::{answer, tag, tolerance_box, DesignParams, PatternResult};
use crate::runs::meta::{scene_file, Inputs};
use crate::study::load::{Load, LoadKey};
use crate::study::record;
use crate::study::rows::label;
use anyhow::Result;
use serde_json::json;
use surrogate::solver::Solver;
use surrogate::units::{deg_to_rad, n_to_mn, rad_to_deg};

/// The DEM parameters of one confirmation run at α (degrees) and `load` (N) with `protocol`.
pub fn dem_params(
    p: &DesignParams,
    alpha_deg: f64,
    load: f64,
    protocol: DemProtocol,
) -> crate::study::dem_run::DemParams {
    let mut d = p.confirm.dem.clone();
    d.sim.protocol.load = load;
    d.alpha = deg_to_rad(alpha_deg);
    d.line = p.alpha_scan.line;
    if protocol == DemProtocol::Study {
        let s = dem::SimParams::default();
        d.sim.protocol.equilibrate_time = s.protocol.equilibrate_time;
        d.sim.protocol.relax_time = s.protocol.relax_time;
        d.sim.protocol.slide_time = s.protocol.slide_time;
        d.sim.protocol.support_speed = s.protocol.support_speed;
    }
    d
}

/// The DEM parameters of a confirmation run of the design `c` of `pr` ([`dem_params`]): for a
/// recipe outside the validated range ([`answer::outside_range`]) the model `auto` where
/// `reduced` was asked, so that the DEM that decides it uses rigid-z only inside that model's
/// own measured limits (`dem::reduction`: κ, coating near failure, stick-slip), the full model
/// elsewhere.
pub fn design_dem_params(
    pr: &PatternResult,
    c: &Candidate,
    p: &DesignParams,
    alpha_deg: f64,
    load: f64,
    protocol: DemProtocol,
) -> crate::study::dem_run::DemParams {
    let mut d = dem_params(p, alpha_deg, load, protocol);
    d.model = dem_model(pr, c, p);
    d
}

/// The DEM model of the runs of the design `c` of `pr` (see [`design_dem_params`]).
pub fn dem_model(
    pr: &PatternResult,
    c: &Candidate,
    p: &DesignParams,
) -> crate::study::dem_run::ModelSpec {
    let mut m = p.confirm.dem.model;
    if m.request == dem::ModelRequest::Reduced && !answer::outside_range(pr, c).is_empty() {
        m.request = dem::ModelRequest::Auto;
    }
    m
}

/// The run directory name of a confirmation run (θ, α in degrees, `load` in N).
pub fn run_name(
    pattern: &str,
    theta_deg: f64,
    alpha_deg: f64,
    load: f64,
    protocol: DemProtocol,
) -> String {
    format!(
        "{pattern}_theta{}_alpha{}_W{}{}",
        tag(theta_deg),
        tag(alpha_deg),
        tag(n_to_mn(load)),
        match protocol {
            DemProtocol::Study => "_study-protocol",
            DemProtocol::Design => "",
        }
    )
}

/// The friction estimate of the designs to confirm at the confirmation loads that the
/// evaluation did not estimate (above the screen's coating-intact load, or above the lowest
/// load of a candidate not superlubric there): one stage file per (θ, α, W), added to the
/// candidate's rows for the comparison with the DEM (the score is not changed).
pub(super) fn confirm_estimates(
    patterns: &mut [PatternResult],
    p: &DesignParams,
    store: &Store,
) -> Result<()> {
    for pr in patterns.iter_mut() {
        let mut solver: Option<Solver> = None;
        let ds = &pr.scene;
        for c in pr.ranking.iter_mut().take(p.confirm.designs) {
            for w in loads_to_confirm(c, &p.confirm.loads, &p.loads) {
                let wm = Load::from_n(w).mn();
                if c.friction.iter().any(|r| Load::from_n(w).is(r.load_mN)) {
                    continue;
                }
                let theta = deg_to_rad(c.theta_deg);
                let inputs = Inputs {
                    workflow: "design/estimate".into(),
                    scene: Some(scene_file(&ds.scene.with_theta(theta))),
                    params: json!({
                        "theta_deg": c.theta_deg,
                        "alpha_deg": c.alpha_deg,
                        "load_mN": wm,
                        "line_deg": p.alpha_scan.line.map(rad_to_deg),
                        "friction": record::friction_knobs(&p.friction),
                    }),
                };
                let rel = format!(
                    "stages/{}/estimate_theta{}_alpha{}_W{}.json",
                    ds.name,
                    tag(c.theta_deg),
                    tag(c.alpha_deg),
                    tag(wm)
                );
                let row = match store.load_json::<crate::study::rows::FrictionRow>(&rel, &inputs)? {
                    Some(r) => r,
                    None => {
                        let s = super::limit::solver_of(&mut solver, ds)?;
                        let line = crate::study::corrugation::contact_line(
                            &ds.scene.with_theta(theta),
                            p.alpha_scan.line,
                        );
                        let alpha = deg_to_rad(c.alpha_deg);
                        let est = surrogate::friction::estimate_friction_loads(
                            s,
                            theta,
                            line.angle + alpha,
                            &[w],
                            &p.friction,
                        )?;
                        let mut r = crate::study::rows::FrictionRow::new(
                            &ds.scene.pattern,
                            theta,
                            alpha,
                            line.angle,
                            w,
                            &est[0],
                        );
                        r.alpha_deg = c.alpha_deg;
                        store.save_json(&rel, &inputs, &r)?;
                        r
                    }
                };
                c.friction.push(row);
                c.friction.sort_by(|a, b| a.load_mN.total_cmp(&b.load_mN));
            }
        }
    }
    Ok(())
}

/// The DEM loads (N, ascending) of a design to confirm: the confirmation loads plus its own
/// superlubric load (`superlubric_to`, the load its answer would name), so the claimed limit
/// itself is run, not only the confirmation loads around it. `confirm_loads` and `loads` (the
/// design's loads, one of which the superlubric load is) in N.
pub fn loads_to_confirm(c: &rank::Candidate, confirm_loads: &[f64], loads: &[f64]) -> Vec<f64> {
    let mut w = confirm_loads.to_vec();
    let own = Load::position(loads, c.score.superlubric_to_mn)
        .filter(|_| c.score.superlubric_to_mn > 0.0)
        .map(|k| loads[k]);
    if let Some(own) = own {
        if !w.iter().any(|&x| Load::from_n(x) == Load::from_n(own)) {
            w.push(own);
        }
    }
    w.sort_by(f64::total_cmp);
    w
}

/// The confirmation runs (top [`super::ConfirmParams::designs`] designs × confirmation loads,
/// and the corners of each one's tolerance box, `corner_jobs`), with what each one is; the runs
/// of borderline designs and of recipes outside the validated range
/// ([`answer::outside_range`]: the DEM decides them) first, else in ranking order.
pub fn confirm_jobs(
    patterns: &[PatternResult],
    p: &DesignParams,
) -> (Vec<SlideJob>, Vec<ConfirmEntry>) {
    // (not first, job, entry): DEM runs go first to borderline designs and to recipes the
    // DEM decides
    let mut all: Vec<(bool, SlideJob, ConfirmEntry)> = Vec::new();
    for pr in patterns {
        for (k, c) in pr.ranking.iter().take(p.confirm.designs).enumerate() {
            let borderline = c.score.verdict == crate::study::verdict::Verdict::Borderline
                || !answer::outside_range(pr, c).is_empty();
            for w in loads_to_confirm(c, &p.confirm.loads, &p.loads) {
                all.push((
                    !borderline,
                    SlideJob {
                        name: run_name(
                            &pr.scene.name,
                            c.theta_deg,
                            c.alpha_deg,
                            w,
                            DemProtocol::Design,
                        ),
                        scene: pr.scene.scene.with_theta(deg_to_rad(c.theta_deg)),
                        params: design_dem_params(pr, c, p, c.alpha_deg, w, DemProtocol::Design),
                    },
                    ConfirmEntry {
                        pattern: pr.scene.name.clone(),
                        rank: k + 1,
                        theta_deg: c.theta_deg,
                        alpha_deg: c.alpha_deg,
                        load: w,
                        protocol: DemProtocol::Design,
                        theta_offset_deg: 0.0,
                        direction_offset_deg: 0.0,
                    },
                ));
            }
            // every design that the answer can name (any of the top K) has its corners run
            for (job, entry) in corner_jobs(pr, c, k + 1, p) {
                all.push((!borderline, job, entry));
            }
        }
    }
    all.sort_by_key(|x| x.0); // stable: the order within each group is kept
    all.into_iter().map(|(_, j, e)| (j, e)).unzip()
}

/// The DEM runs of the tolerance box's corners of the design `c` at `rank`: θ ± tol × pull
/// direction ± tol ([`crate::study::tolerance::ToleranceBox::corners`]; the direction fixed in
/// the substrate frame: α' = direction' − line(θ')), at its robust limit load and the next load
/// above. None without a tolerance or a limit.
pub(super) fn corner_jobs(
    pr: &PatternResult,
    c: &Candidate,
    rank: usize,
    p: &DesignParams,
) -> Vec<(SlideJob, ConfirmEntry)> {
    let mut out = Vec::new();
    if c.score.superlubric_to_mn <= 0.0 {
        return out;
    }
    let Some(k) = p.loads.position(LoadKey::of_mn(c.score.superlubric_to_mn)) else {
        return out;
    };
    let loads = &p.loads[k..(k + 2).min(p.loads.len())];
    let corners = tolerance_box(p).corners();
    for &w in loads {
        for &(dt, dd) in &corners {
            let theta = label(c.theta_deg + dt);
            let scene = pr.scene.scene.with_theta(deg_to_rad(theta));
            let line =
                crate::study::friction::line_at(&scene, deg_to_rad(theta), p.alpha_scan.line);
            let alpha = label(c.direction_deg + dd - rad_to_deg(line.angle));
            out.push((
                SlideJob {
                    name: run_name(&pr.scene.name, theta, alpha, w, DemProtocol::Design),
                    scene,
                    params: design_dem_params(pr, c, p, alpha, w, DemProtocol::Design),
                },
                ConfirmEntry {
                    pattern: pr.scene.name.clone(),
                    rank,
                    theta_deg: theta,
                    alpha_deg: alpha,
                    load: w,
                    protocol: DemProtocol::Design,
                    theta_offset_deg: dt,
                    direction_offset_deg: dd,
                },
            ));
        }
    }
    out
}

/// Stage 6: the DEM runs of the top designs (one batch, side by side), then — when the
/// confirmation protocol is shorter than the study's — the study's protocol once on the design
/// the report recommends ([`protocol_check_design`]; alone, on every thread), to measure the
/// shorter protocol's difference there.
pub(super) fn confirm_stage(
    patterns: &[PatternResult],
    p: &DesignParams,
    store: &Store,
    obs: &dyn Observer,
) -> Result<Vec<DemEntry>> {
    let (jobs, mut entries) = confirm_jobs(patterns, p);
    if jobs.is_empty() {
        obs.event(&Event::DemNothing);
        return Ok(Vec::new());
    }
    let dir = store.path("dem");
    obs.event(&Event::DemRuns {
        runs: jobs.len(),
        side_by_side: p.confirm.jobs.min(jobs.len()),
        dir: &dir,
    });
    let mut outcomes = run_batch(&jobs, p.confirm.jobs, &dir, obs.progress())?;
    let mut dem = to_entries(&entries, &outcomes);
    // the protocol check, on the design the report recommends
    if p.confirm.protocol_check && !p.confirm.dem_is_study_protocol {
        let answers: Vec<answer::Answer> = patterns
            .iter()
            .map(|pr| answer::answer(pr, &dem, true, p))
            .collect();
        if let Some(ProtocolCheck {
            pattern: pr,
            index: i,
            load: w,
        }) = protocol_check_design(patterns, &answers, &p.confirm.loads)
        {
            let c = &pr.ranking[i];
            let job = SlideJob {
                name: run_name(
                    &pr.scene.name,
                    c.theta_deg,
                    c.alpha_deg,
                    w,
                    DemProtocol::Study,
                ),
                scene: pr.scene.scene.with_theta(deg_to_rad(c.theta_deg)),
                params: design_dem_params(pr, c, p, c.alpha_deg, w, DemProtocol::Study),
            };
            obs.event(&Event::ProtocolCheck {
                pattern: &pr.scene.name,
                theta_deg: c.theta_deg,
                alpha_deg: c.alpha_deg,
                load: w,
            });
            let o = run_batch(std::slice::from_ref(&job), 1, &dir, obs.progress())?;
            entries.push(ConfirmEntry {
                pattern: pr.scene.name.clone(),
                rank: i + 1,
                theta_deg: c.theta_deg,
                alpha_deg: c.alpha_deg,
                load: w,
                protocol: DemProtocol::Study,
                theta_offset_deg: 0.0,
                direction_offset_deg: 0.0,
            });
            outcomes.extend(o);
            dem = to_entries(&entries, &outcomes);
        }
    }
    let reused = outcomes.iter().filter(|o| o.reused).count();
    if reused > 0 {
        obs.event(&Event::DemReused {
            reused,
            runs: outcomes.len(),
        });
    }
    Ok(dem)
}

/// The design and load of the study-protocol check: the answer of the best pattern (ranked by
/// its rank-1 design, [`super::rank::compare`]) whose answer the DEM confirmed (else the best
/// pattern's answer: the report says it is not confirmed), at the middle of its design-protocol runs up to its superlubric load (the
/// confirmed loads), else at the middle confirmation load. So the measured difference is that
/// of the design the report recommends, at a load where the shorter protocol ran on it.
/// `confirm_loads` in N.
pub fn protocol_check_design<'a>(
    patterns: &'a [PatternResult],
    answers: &[answer::Answer],
    confirm_loads: &[f64],
) -> Option<ProtocolCheck<'a>> {
    // the patterns best first, by their rank-1 designs (the ranking's one order), so the
    // design recommended is the one the "Patterns compared" table ranks first
    let mut order: Vec<usize> = (0..patterns.len().min(answers.len())).collect();
    order.sort_by(
        |&a, &b| match (patterns[a].ranking.first(), patterns[b].ranking.first()) {
            (Some(x), Some(y)) => super::rank::compare(x, y),
            (Some(_), None) => std::cmp::Ordering::Less,
            (None, Some(_)) => std::cmp::Ordering::Greater,
            (None, None) => std::cmp::Ordering::Equal,
        },
    );
    let with_index = || {
        order
            .iter()
            .map(|&k| (&patterns[k], &answers[k]))
            .filter_map(|(pr, a)| a.index.map(|i| (pr, i, a)))
    };
    let (pr, i, a) = with_index()
        .find(|(_, _, a)| matches!(a.check, answer::Check::Confirmed(_)))
        .or_else(|| with_index().next())?;
    let w = match &a.check {
        answer::Check::Confirmed(loads) if !loads.is_empty() => {
            let mn = loads[loads.len() / 2];
            confirm_loads[Load::position(confirm_loads, mn)?]
        }
        _ => *confirm_loads.get(confirm_loads.len() / 2)?,
    };
    Some(ProtocolCheck {
        pattern: pr,
        index: i,
        load: w,
    })
}

/// The design and load of the study-protocol check ([`protocol_check_design`]).
#[derive(Debug, Clone, Copy)]
pub struct ProtocolCheck<'a> {
    /// The pattern.
    pub pattern: &'a PatternResult,
    /// The design: an index into the pattern's ranking.
    pub index: usize,
    /// The load (N).
    pub load: f64,
}

/// The DEM entries of the runs `outcomes` made for `entries`, in order.
pub fn to_entries(entries: &[ConfirmEntry], outcomes: &[SlideOutcome]) -> Vec<DemEntry> {
    entries
        .iter()
        .cloned()
        .zip(outcomes.iter().cloned())
        .map(|(run, outcome)| DemEntry { run, outcome })
        .collect()
}
