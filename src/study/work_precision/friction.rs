//! The friction estimate: path step, path length, transverse search and the inertial model's
//! starts, each against its finest setting (μ_est, the path's P_max, the mean contacts, and the
//! verdict); the search segment is a speed-only knob (its rows show that μ_est does not move).

use super::cost::measure;
use super::row::{compare, um, Measured, Setting, Values};
use super::{scenes, Knob, StudyScene, Tier, WorkPrecisionRow};
use crate::runs::progress::Progress;
use crate::study::verdict::Verdict;
use anyhow::Result;
use surrogate::friction::{estimate_friction_loads, FrictionParams};
use surrogate::solver::Solver;
use surrogate::units::um_to_m;

/// μ below which a row can be superlubric (the study's).
const MU_SL: f64 = 0.02;

/// One knob's plan: the knob, settings (knob's unit), default, reference, and how a setting
/// changes the estimate's parameters.
struct KnobPlan {
    knob: Knob,
    settings: Vec<f64>,
    default: f64,
    reference: f64,
    set: fn(&mut FrictionParams, f64),
}

fn knobs(quick: bool) -> Vec<KnobPlan> {
    let d = FrictionParams::default();
    let (steps, lengths, starts, segments) = if quick {
        (
            vec![0.2, 0.1, 0.05, 0.025],
            vec![6.0, 12.0, 24.0, 48.0],
            vec![1.0, 4.0, 8.0, 32.0],
            vec![0.25, 0.5, 2.0],
        )
    } else {
        (
            vec![0.2, 0.1, 0.05, 0.025, 0.0125],
            vec![6.0, 12.0, 24.0, 48.0],
            vec![1.0, 2.0, 4.0, 8.0, 32.0],
            vec![0.25, 0.5, 1.0, 2.0],
        )
    };
    let last = |v: &Vec<f64>| *v.last().expect("settings");
    vec![
        KnobPlan {
            knob: Knob::StepUm,
            reference: last(&steps),
            settings: steps,
            default: um(d.step),
            set: |f, v| f.step = um_to_m(v),
        },
        KnobPlan {
            knob: Knob::LengthUm,
            reference: last(&lengths),
            settings: lengths,
            default: um(d.length),
            set: |f, v| {
                f.length = um_to_m(v);
                f.transient = f.transient.min(0.5 * um_to_m(v));
            },
        },
        KnobPlan {
            knob: Knob::TransverseUm,
            settings: vec![0.0, um(d.transverse)],
            default: um(d.transverse),
            reference: um(d.transverse),
            set: |f, v| f.transverse = um_to_m(v),
        },
        KnobPlan {
            knob: Knob::Starts,
            reference: last(&starts),
            settings: starts,
            default: d.starts as f64,
            set: |f, v| f.starts = v as usize,
        },
        KnobPlan {
            knob: Knob::SegmentUm,
            settings: segments,
            default: um(d.segment),
            reference: um(d.segment),
            set: |f, v| f.segment = um_to_m(v),
        },
    ]
}

/// The estimate of `s` with `knobs` as one measured setting (μ_est with its spread/√starts,
/// the path's largest P_max, the mean contacts, the band rule's verdict).
pub fn one(solver: &Solver, s: &StudyScene, knobs: &FrictionParams, setting: Setting) -> Measured {
    let (r, cost) = measure(|| {
        estimate_friction_loads(solver, s.scene.slider.theta, s.direction, &[s.load], knobs)
    });
    let values = match r
        .map_err(anyhow::Error::from)
        .and_then(|mut v| v.pop().expect("one load").map_err(anyhow::Error::from))
    {
        Ok(e) => Values {
            mu: Some(e.mu_est),
            mu_se: e.mu_est_spread / (knobs.starts as f64).sqrt(),
            p_max: Some(e.p_max_max),
            contacts: Some(e.contacts_mean),
            verdict: Some(Verdict::of(
                Some(e.mu_est),
                Some(e.p_max_max),
                MU_SL,
                s.scene.coating.p_crit,
            )),
            note: if e.periodic {
                format!(
                    "periodic path: one lattice period ({:.3} µm) whatever length_um",
                    um(e.length)
                )
            } else if e.eta <= 1.0 {
                "steady sliding (η ≤ 1): the inertial starts do not change μ_est".into()
            } else {
                String::new()
            },
            ..Values::default()
        },
        Err(e) => Values {
            note: format!("{e:#}"),
            ..Values::default()
        },
    };
    Measured {
        setting,
        cost,
        values,
    }
}

/// Runs the tier (see the module docs).
pub fn run(quick: bool, progress: &dyn Progress) -> Result<Vec<WorkPrecisionRow>> {
    let mut ss = scenes(quick.then_some((10.0, 140.0)))?;
    // the three pull along substrate lattice directions (the path is one period, whatever
    // its length): a fourth pulls at 10° from the substrate x axis, quasi-periodic
    let mut qp = ss[0].clone();
    qp.name = qp.name.replace("superlubric", "quasi-periodic-10deg");
    qp.direction = surrogate::units::deg_to_rad(10.0);
    ss.push(qp);
    if !quick {
        // a larger flat substrate (the same periodic landscape) so that the 48 µm path fits
        for s in &mut ss {
            s.scene.substrate.size = [um_to_m(500.0), um_to_m(400.0)];
        }
    }
    let ks = knobs(quick);
    let mut rows = Vec::new();
    progress.stage(
        "work-precision: friction estimate",
        (ss.len() * ks.len()) as u64,
        "knobs",
    );
    for s in &ss {
        let solver = Solver::new(&s.scene)?;
        for k in &ks {
            let ms: Vec<Measured> = k
                .settings
                .iter()
                .map(|&v| {
                    let mut f = FrictionParams::default();
                    (k.set)(&mut f, v);
                    let mut setting = Setting::num(v, k.default, k.reference);
                    if k.knob == Knob::TransverseUm {
                        setting.text = if v > 0.0 { "on (1.5)" } else { "off (0)" }.into();
                    }
                    one(&solver, s, &f, setting)
                })
                .collect();
            let mut rs = compare(Tier::Friction, &s.name, k.knob, &ms);
            if k.knob == Knob::LengthUm {
                // a quasi-periodic path's average converges like a finite sample, not
                // monotonically: its noise is taken as the change between the two longest
                // paths (the reference and the next)
                let n = rs.len();
                let noise = if n >= 2 { rs[n - 2].error_rel } else { 0.0 };
                for r in &mut rs {
                    r.noise_rel = r.noise_rel.max(noise);
                }
            }
            rows.extend(rs);
            progress.advance(1);
        }
    }
    progress.finish();
    Ok(rows)
}
