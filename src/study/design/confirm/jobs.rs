//! The DEM confirmation's runs: which (the top designs at the confirmation loads and at their
//! own limit, and the corners of their tolerance boxes: [`confirm_jobs`]), with which DEM
//! parameters ([`dem_params`], [`design_dem_params`]) and under which name ([`run_name`]).

use super::params::ConfirmParams;
use crate::study::batch::{SlideJob, SlideOutcome};
use crate::study::design::limit::LimitKnobs;
use crate::study::design::model::answer::outside_range;
use crate::study::design::model::{Candidate, ConfirmEntry, DemEntry, DemProtocol, PatternResult};
use crate::study::design::store::tag;
use crate::study::load::{Load, LoadKey};
use crate::study::rows::label;
use surrogate::units::{deg_to_rad, n_to_mn, rad_to_deg};

/// The DEM parameters of one confirmation run at α (degrees) and `load` (N) with `protocol`.
/// `line`: the design's contact line (rad from x; `None`: the moiré estimate).
pub fn dem_params(
    cp: &ConfirmParams,
    line: Option<f64>,
    (alpha_deg, load): (f64, f64),
    protocol: DemProtocol,
) -> crate::study::dem_run::DemParams {
    let mut d = cp.dem.clone();
    d.sim.protocol.load = load;
    d.alpha = deg_to_rad(alpha_deg);
    d.line = line;
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
/// recipe outside the validated range ([`outside_range`]) the model `auto` where
/// `reduced` was asked, so that the DEM that decides it uses rigid-z only inside that model's
/// own measured limits (`dem::reduction`: κ, coating near failure, stick-slip), the full model
/// elsewhere.
pub fn design_dem_params(
    (pr, c): (&PatternResult, &Candidate),
    (cp, line): (&ConfirmParams, Option<f64>),
    (alpha_deg, load): (f64, f64),
    protocol: DemProtocol,
) -> crate::study::dem_run::DemParams {
    let mut d = dem_params(cp, line, (alpha_deg, load), protocol);
    d.model = dem_model(pr, c, cp);
    d
}

/// The DEM model of the runs of the design `c` of `pr` (see [`design_dem_params`]).
pub fn dem_model(
    pr: &PatternResult,
    c: &Candidate,
    cp: &ConfirmParams,
) -> crate::study::dem_run::ModelSpec {
    let mut m = cp.dem.model;
    if m.request == dem::ModelRequest::Reduced && !outside_range(pr, c).is_empty() {
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

/// The DEM loads (N, ascending) of a design to confirm: the confirmation loads plus its own
/// superlubric load (`superlubric_to`, the load its answer would name), so the claimed limit
/// itself is run, not only the confirmation loads around it. `confirm_loads` and `loads` (the
/// design's loads, one of which the superlubric load is) in N.
pub fn loads_to_confirm(c: &Candidate, confirm_loads: &[f64], loads: &[f64]) -> Vec<f64> {
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

/// The confirmation runs (top [`ConfirmParams::designs`] designs × confirmation loads,
/// and the corners of each one's tolerance box, `corner_jobs`), with what each one is; the runs
/// of borderline designs and of recipes outside the validated range
/// ([`outside_range`]: the DEM decides them) first, else in ranking order. `limit`: the
/// design's shared knobs (its loads, contact line and tolerance box).
pub fn confirm_jobs(
    patterns: &[PatternResult],
    cp: &ConfirmParams,
    limit: &LimitKnobs,
) -> (Vec<SlideJob>, Vec<ConfirmEntry>) {
    // (not first, job, entry): DEM runs go first to borderline designs and to recipes the
    // DEM decides
    let mut all: Vec<(bool, SlideJob, ConfirmEntry)> = Vec::new();
    for pr in patterns {
        for (k, c) in pr.ranking.iter().take(cp.designs).enumerate() {
            let borderline = c.score.verdict == crate::study::verdict::Verdict::Borderline
                || !outside_range(pr, c).is_empty();
            for w in loads_to_confirm(c, &cp.loads, &limit.loads) {
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
                        params: design_dem_params(
                            (pr, c),
                            (cp, limit.line),
                            (c.alpha_deg, w),
                            DemProtocol::Design,
                        ),
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
            for (job, entry) in corner_jobs((pr, c), k + 1, cp, limit) {
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
fn corner_jobs(
    (pr, c): (&PatternResult, &Candidate),
    rank: usize,
    cp: &ConfirmParams,
    limit: &LimitKnobs,
) -> Vec<(SlideJob, ConfirmEntry)> {
    let mut out = Vec::new();
    if c.score.superlubric_to_mn <= 0.0 {
        return out;
    }
    let Some(k) = limit
        .loads
        .position(LoadKey::of_mn(c.score.superlubric_to_mn))
    else {
        return out;
    };
    let loads = &limit.loads[k..(k + 2).min(limit.loads.len())];
    let corners = limit.tolerance_box().corners();
    for &w in loads {
        for &(dt, dd) in &corners {
            let theta = label(c.theta_deg + dt);
            let scene = pr.scene.scene.with_theta(deg_to_rad(theta));
            let line = crate::study::friction::line_at(&scene, deg_to_rad(theta), limit.line);
            let alpha = label(c.direction_deg + dd - rad_to_deg(line.angle));
            out.push((
                SlideJob {
                    name: run_name(&pr.scene.name, theta, alpha, w, DemProtocol::Design),
                    scene,
                    params: design_dem_params(
                        (pr, c),
                        (cp, limit.line),
                        (alpha, w),
                        DemProtocol::Design,
                    ),
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

/// The DEM entries of the runs `outcomes` made for `entries`, in order.
pub fn to_entries(entries: &[ConfirmEntry], outcomes: &[SlideOutcome]) -> Vec<DemEntry> {
    entries
        .iter()
        .cloned()
        .zip(outcomes.iter().cloned())
        .map(|(run, outcome)| DemEntry { run, outcome })
        .collect()
}
