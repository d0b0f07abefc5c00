//! Tier 1 screen and Tier 2 maps: the load-sharing model at the placement (rigid-z,
//! rigid-tilt against the compliant model), the landscape grid (against 101 points per side)
//! and the corrugation path step (against a quarter of the default step).

use super::cost::{measure, measure_repeated};
use super::row::{compare, um, Measured, Setting, Values};
use super::{scenes, Knob, StudyScene, Tier, WorkPrecisionRow};
use crate::runs::progress::Progress;
use crate::study::verdict::Verdict;
use anyhow::Result;
use surrogate::map::{compute_landscape, path_profile, MapParams};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::units::um_to_m;

/// Settings of the screen/map tier: landscape grids (points per side, last = reference),
/// corrugation steps (µm, last = reference), corrugation distance (µm), and the scenes' small
/// slider (radius, substrate side in µm) or `None` for the study's.
struct Plan {
    grids: Vec<usize>,
    steps_um: Vec<f64>,
    distance_um: f64,
    small: Option<(f64, f64)>,
}

fn plan(quick: bool) -> Plan {
    if quick {
        Plan {
            grids: vec![6, 26, 51, 101],
            steps_um: vec![0.2, 0.1, 0.05, 0.025],
            distance_um: 6.0,
            small: Some((10.0, 60.0)),
        }
    } else {
        Plan {
            grids: vec![6, 11, 26, 51, 101],
            steps_um: vec![0.4, 0.2, 0.1, 0.05, 0.025],
            distance_um: 30.0,
            small: None,
        }
    }
}

/// The screen's verdict on the coating at one P_max (Pa): the estimate's band rule on P_max
/// alone (μ taken as 0).
fn coating_verdict(p_max: f64, s: &StudyScene) -> Verdict {
    Verdict::of(Some(0.0), Some(p_max), 0.02, s.scene.coating.p_crit)
}

/// Runs the tier (see the module docs).
pub fn run(quick: bool, progress: &dyn Progress) -> Result<Vec<WorkPrecisionRow>> {
    let pl = plan(quick);
    let mut rows = Vec::new();
    let ss = scenes(pl.small)?;
    progress.stage("work-precision: screen/map", ss.len() as u64 * 3, "knobs");
    for s in &ss {
        let solver = Solver::new(&s.scene)?;
        let pose = Pose {
            theta: s.scene.slider.theta,
            shift: [0.0, 0.0],
        };
        // 1. the load-sharing model at the placement (reference: compliant)
        let ms = models(&solver, pose, s)?;
        rows.extend(compare(Tier::ScreenMap, &s.name, Knob::Model, &ms));
        progress.advance(1);
        // 2. the landscape grid (reference: the finest)
        let ms = grids(&solver, pose, s, &pl.grids)?;
        rows.extend(compare(Tier::ScreenMap, &s.name, Knob::GridPoints, &ms));
        progress.advance(1);
        // 3. the corrugation path step (reference: the finest)
        let ms = steps(&solver, pose, s, &pl)?;
        rows.extend(compare(
            Tier::ScreenMap,
            &s.name,
            Knob::CorrugationStepUm,
            &ms,
        ));
        progress.advance(1);
    }
    progress.finish();
    Ok(rows)
}

/// Each load-sharing model the solver takes at the placement `pose`, measured.
fn models(solver: &Solver, pose: Pose, s: &StudyScene) -> Result<Vec<Measured>> {
    let auto = solver.solve(pose, s.load, Model::Auto)?.model;
    let mut ms = Vec::new();
    for m in [Model::RigidZ, Model::RigidTilt, Model::Compliant] {
        let setting = Setting::cat(m.name(), m == auto, m == Model::Compliant);
        if solver.check_model(m).is_err() {
            continue;
        }
        let (eq, cost) = measure_repeated(0.05, || solver.solve(pose, s.load, m));
        let values = match eq {
            Ok(eq) => Values {
                p_max: Some(eq.p_max),
                contacts: Some(eq.contact_count() as f64),
                verdict: Some(coating_verdict(eq.p_max, s)),
                ..Values::default()
            },
            Err(e) => Values {
                note: e.to_string(),
                ..Values::default()
            },
        };
        ms.push(Measured {
            setting,
            cost,
            values,
        });
    }
    Ok(ms)
}

/// Each landscape grid of `grids`, measured (reference: the finest, the last).
fn grids(solver: &Solver, pose: Pose, s: &StudyScene, grids: &[usize]) -> Result<Vec<Measured>> {
    let reference = *grids.last().expect("grids");
    let mut ms = Vec::new();
    for &n in grids {
        let mp = MapParams {
            grid: n,
            ..MapParams::default()
        };
        let (ls, cost) = measure(|| compute_landscape(solver, pose.theta, s.load, &mp, &|| {}));
        let ls = ls?;
        let p_max = ls.p_max.iter().copied().fold(0.0, f64::max);
        let contacts =
            ls.contacts.iter().map(|&c| c as f64).sum::<f64>() / ls.contacts.len() as f64;
        ms.push(Measured {
            setting: Setting::num(n as f64, MapParams::default().grid as f64, reference as f64),
            cost,
            values: Values {
                p_max: Some(p_max),
                contacts: Some(contacts),
                landscape_range: Some(ls.range()),
                verdict: Some(coating_verdict(p_max, s)),
                ..Values::default()
            },
        });
    }
    Ok(ms)
}

/// Each corrugation path step of the plan `pl`, measured (reference: the finest, the last).
fn steps(solver: &Solver, pose: Pose, s: &StudyScene, pl: &Plan) -> Result<Vec<Measured>> {
    let reference = *pl.steps_um.last().expect("steps");
    let mut ms = Vec::new();
    for &st in &pl.steps_um {
        let mp = MapParams {
            step: um_to_m(st),
            distance: um_to_m(pl.distance_um),
            ..MapParams::default()
        };
        let (prof, cost) =
            measure(|| path_profile(solver, pose.theta, s.load, s.direction, &mp, &|| {}));
        let prof = prof?;
        let contacts =
            prof.contacts.iter().map(|&c| c as f64).sum::<f64>() / prof.contacts.len() as f64;
        ms.push(Measured {
            setting: Setting::num(st, um(MapParams::default().step), reference),
            cost,
            values: Values {
                contacts: Some(contacts),
                corrugation: Some(prof.corrugation()),
                max_pull: Some(prof.max_pull()),
                ..Values::default()
            },
        });
    }
    Ok(ms)
}
