//! Tier 3 DEM: the time step (fraction of the stable step), the model (reduced, full,
//! full-explicit), the tangential history, the length of the friction window and the active set
//! (speed only). The reference is the full model at a quarter of the default step, shown
//! converged by one more halving (its row at 1/32 of the stable step); errors in μ, the window's
//! max P_max and its mean contacts, with the window's standard error (ten block means) as the
//! noise. On a small slider (30 µm, loaded per sphere as the study's), where the reference is
//! affordable; the study scenes compare the reduced and the full model at the default step.

use super::cost::measure;
use super::row::{compare, Measured, Setting, Values};
use super::{scenes, Knob, StudyScene, Tier, WorkPrecisionRow};
use crate::runs::progress::{Progress, Silent};
use crate::study::dem_run::{DemParams, ModelSpec};
use crate::study::slide::slide;
use crate::study::verdict::Verdict;
use anyhow::Result;
use dem::params::Tangential;
use dem::protocol::{RunIo, Sample};
use dem::{ModelRequest, SimParams, Start};
use std::collections::HashMap;
use surrogate::units::{gpa_to_pa, us_to_s};

/// μ below which a DEM run is superlubric (the study's).
const MU_SL: f64 = 0.02;

/// One DEM setting: every knob the tier varies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DemSetting {
    /// Fraction of the estimated stable step (default 0.25).
    pub dt_fraction: f64,
    /// Which model.
    pub model: ModelRequest,
    /// Tangential history.
    pub tangential: Tangential,
    /// Sliding time (s); friction over its last 2/3.
    pub slide_time: f64,
    /// Active set on.
    pub active_set: bool,
}

impl DemSetting {
    fn key(&self) -> String {
        format!("{self:?}")
    }
}

/// The protocol of a set: (equilibrate, relax, default slide) times (s), support speed (m/s),
/// sampling interval (s).
#[derive(Debug, Clone, Copy)]
pub struct Protocol {
    /// Equilibration (s).
    pub equilibrate: f64,
    /// Relaxation (s).
    pub relax: f64,
    /// Default sliding time (s).
    pub slide: f64,
    /// Support speed (m/s).
    pub speed: f64,
    /// Sampling interval (s).
    pub sample: f64,
}

/// The study protocol (10 + 10 + 300 µs at 0.1 m/s, sampled every 0.1 µs) or the quick one
/// (1 + 1 + 40 µs at 0.1 m/s, every 0.02 µs: a 10 µm slider, ~100× lighter than the study's,
/// swings on the pulling spring ~10× faster, so 40 µs hold as many swings as the study's 300).
pub fn protocol(quick: bool) -> Protocol {
    if quick {
        Protocol {
            equilibrate: us_to_s(1.0),
            relax: us_to_s(1.0),
            slide: us_to_s(40.0),
            speed: 0.1,
            sample: us_to_s(0.02),
        }
    } else {
        Protocol {
            equilibrate: us_to_s(10.0),
            relax: us_to_s(10.0),
            slide: us_to_s(300.0),
            speed: 0.1,
            sample: us_to_s(0.1),
        }
    }
}

/// Mean and standard error of `x` from ten block means (`NaN` with fewer than ten values): the
/// noise of a window average of a correlated time series.
pub fn block_mean_se(x: &[f64]) -> [f64; 2] {
    let blocks = 10usize;
    if x.len() < blocks {
        return [f64::NAN, f64::NAN];
    }
    let means: Vec<f64> = (0..blocks)
        .map(|b| {
            let (a, z) = (b * x.len() / blocks, (b + 1) * x.len() / blocks);
            x[a..z].iter().sum::<f64>() / (z - a) as f64
        })
        .collect();
    let m = means.iter().sum::<f64>() / blocks as f64;
    let var = means.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (blocks - 1) as f64;
    [m, (var / blocks as f64).sqrt()]
}

/// Mean and standard error of the spring force (mN) and of the contacts over the window of the
/// last 2/3 of the slide, from ten block means ([`block_mean_se`]).
pub fn window_stats(samples: &[Sample], t0_us: f64, t1_us: f64) -> ([f64; 2], [f64; 2]) {
    let w: Vec<&Sample> = samples
        .iter()
        .filter(|s| s.t_us >= t0_us - 1e-9 && s.t_us <= t1_us + 1e-9)
        .collect();
    let f: Vec<f64> = w.iter().map(|s| s.spring_force_mn).collect();
    let c: Vec<f64> = w.iter().map(|s| s.contacts as f64).collect();
    (block_mean_se(&f), block_mean_se(&c))
}

/// The engine's parameters of one setting `d` on scene `s` under protocol `pr` (the pulling
/// direction is `s.direction`, set by the caller).
pub fn sim_params(s: &StudyScene, pr: &Protocol, d: &DemSetting) -> SimParams {
    SimParams {
        protocol: dem::ProtocolParams {
            load: s.load,
            equilibrate_time: pr.equilibrate,
            relax_time: pr.relax,
            slide_time: d.slide_time,
            support_speed: pr.speed,
            sample_interval: pr.sample,
            ..Default::default()
        },
        contact: dem::ContactParams {
            tangential: d.tangential,
            ..Default::default()
        },
        numerics: dem::NumericsParams {
            dt_safety: d.dt_fraction,
            ..Default::default()
        },
        ..SimParams::default()
    }
}

/// Runs the slide of `s` with `d` and measures it.
pub fn run_one(s: &StudyScene, pr: &Protocol, d: &DemSetting, setting: Setting) -> Measured {
    let sim = sim_params(s, pr, d);
    let p = DemParams {
        sim,
        alpha: s.direction,
        line: Some(0.0),
        start: Start::Surrogate,
        friction: None,
        io: RunIo::default(),
        resume: None,
        model: ModelSpec {
            request: d.model,
            force_rigid_z: false,
            active_set: d.active_set,
        },
    };
    let (out, cost) = measure(|| slide(&s.scene, &p, &Silent));
    let values = match out {
        Ok((out, Some(rep))) => {
            let t0 = crate::study::rows::label(surrogate::units::s_to_us(
                pr.equilibrate + pr.relax + d.slide_time / 3.0,
            ));
            let t1 = surrogate::units::s_to_us(pr.equilibrate + pr.relax + d.slide_time);
            let (f, c) = window_stats(&out.samples, t0, t1);
            let w_mn = surrogate::units::n_to_mn(s.load);
            let r = &rep.result;
            let superlubric = !r.locked_in
                && gpa_to_pa(r.max_p_max_gpa) <= s.scene.coating.p_crit
                && r.mu < MU_SL;
            Values {
                mu: Some(r.mu),
                mu_se: f[1] / w_mn,
                p_max: Some(gpa_to_pa(r.max_p_max_gpa)),
                contacts: Some(r.mean_contacts),
                contacts_se: c[1],
                verdict: Some(if superlubric {
                    Verdict::Superlubric
                } else {
                    Verdict::Not
                }),
                note: format!(
                    "{} steps of {:.3e} µs, model {}{}",
                    r.steps,
                    out.info.dt_us,
                    out.info.model,
                    if r.locked_in { "; locked in" } else { "" }
                ),
                ..Values::default()
            }
        }
        Ok((out, None)) => Values {
            note: format!(
                "run failed: {}",
                out.error.map_or("?".into(), |e| e.to_string())
            ),
            ..Values::default()
        },
        Err(e) => Values {
            note: format!("refused: {e:#}"),
            ..Values::default()
        },
    };
    Measured {
        setting,
        cost,
        values,
    }
}

/// The settings of one knob: (knob, settings with their text, value, default and reference
/// flags).
type KnobPlan = (Knob, Vec<(DemSetting, Setting)>);

/// The code's default DEM setting under protocol `pr`: the full model at the default step
/// fraction, Mindlin history, the protocol's slide, active set on.
pub fn default_setting(pr: &Protocol) -> DemSetting {
    DemSetting {
        dt_fraction: SimParams::default().numerics.dt_safety,
        model: ModelRequest::Full,
        tangential: Tangential::Mindlin,
        slide_time: pr.slide,
        active_set: true,
    }
}

/// The reference of the DEM tier (and the best reference of the tiers diagram): the default
/// setting at a quarter of its step.
pub fn reference_setting(pr: &Protocol) -> DemSetting {
    let d = default_setting(pr);
    DemSetting {
        dt_fraction: d.dt_fraction / 4.0,
        ..d
    }
}

/// The small slider of the DEM tier (and the tiers diagram): (radius, substrate side) in µm.
pub fn small_slider(quick: bool) -> (f64, f64) {
    if quick {
        (10.0, 60.0)
    } else {
        (30.0, 200.0)
    }
}

/// The DEM runs of a set, by scene and setting: a run shared by several knobs, or by the DEM
/// tier and the tiers diagram, runs once (its cost is reported on every row that uses it).
#[derive(Debug, Default)]
pub struct DemRuns {
    runs: HashMap<String, Measured>,
}

impl DemRuns {
    /// The run of setting `d` on scene `s` under `pr`, run now unless it already ran; the copy
    /// returned is labelled `setting`.
    pub fn get(
        &mut self,
        s: &StudyScene,
        pr: &Protocol,
        d: &DemSetting,
        setting: Setting,
    ) -> Measured {
        let key = format!("{}|{}", s.name, d.key());
        let m = self
            .runs
            .entry(key)
            .or_insert_with(|| run_one(s, pr, d, setting.clone()));
        Measured {
            setting,
            ..m.clone()
        }
    }
}

/// The default setting and, per knob, its settings with their DEM settings (`quick`: fewer
/// and shorter).
fn plan(quick: bool, pr: &Protocol) -> (DemSetting, Vec<KnobPlan>) {
    let default = default_setting(pr);
    let reference = reference_setting(pr);
    (
        default,
        vec![
            (Knob::DtFraction, dt_settings(quick, default, reference)),
            (Knob::Model, model_settings(quick, default, reference)),
            (Knob::Tangential, tangential_settings(default, reference)),
            (Knob::SlideUs, window_settings(quick, default, pr)),
            (Knob::ActiveSet, active_settings(default)),
        ],
    )
}

/// A knob's settings: each one's DEM setting and its description.
type Settings = Vec<(DemSetting, Setting)>;

/// The step as fractions of the stable step.
fn dt_settings(quick: bool, default: DemSetting, reference: DemSetting) -> Settings {
    let num = |v: f64, d: f64, r: f64| Setting::num(v, d, r);
    let fractions: Vec<f64> = if quick {
        vec![0.5, 0.25, 0.125, 0.0625]
    } else {
        vec![0.5, 0.25, 0.125, 0.0625, 0.03125]
    };
    fractions
        .iter()
        .map(|&f| {
            (
                DemSetting {
                    dt_fraction: f,
                    ..default
                },
                num(f, default.dt_fraction, reference.dt_fraction),
            )
        })
        .collect()
}

/// The contact models, then the reference.
fn model_settings(quick: bool, default: DemSetting, reference: DemSetting) -> Settings {
    let mut models = vec![
        (ModelRequest::Reduced, "reduced"),
        (ModelRequest::Full, "full"),
    ];
    if !quick {
        models.push((ModelRequest::FullExplicit, "full-explicit"));
    }
    models
        .into_iter()
        .map(|(m, name)| {
            (
                DemSetting {
                    model: m,
                    ..default
                },
                Setting::cat(name, m == ModelRequest::Full, false),
            )
        })
        .chain([(
            reference,
            Setting::cat("full, step/4 (reference)", false, true),
        )])
        .collect()
}

/// The tangential laws, then the reference.
fn tangential_settings(default: DemSetting, reference: DemSetting) -> Settings {
    [
        Tangential::Mindlin,
        Tangential::MindlinForce,
        Tangential::MindlinRescale,
    ]
    .into_iter()
    .map(|t| {
        (
            DemSetting {
                tangential: t,
                ..default
            },
            Setting::cat(t.name(), t == Tangential::Mindlin, false),
        )
    })
    .chain([(
        reference,
        Setting::cat("mindlin, step/4 (reference)", false, true),
    )])
    .collect()
}

/// The friction window's slide times (µs), against the protocol's.
fn window_settings(quick: bool, default: DemSetting, pr: &Protocol) -> Settings {
    let num = |v: f64, d: f64, r: f64| Setting::num(v, d, r);
    let windows: Vec<f64> = if quick {
        vec![10.0, 20.0, 40.0, 80.0]
    } else {
        vec![100.0, 200.0, 300.0, 600.0]
    };
    let wref = *windows.last().expect("windows");
    let d_us = surrogate::units::s_to_us(pr.slide);
    windows
        .iter()
        .map(|&w| {
            (
                DemSetting {
                    slide_time: us_to_s(w),
                    ..default
                },
                num(w, d_us, wref),
            )
        })
        .collect()
}

/// The active set on and off.
fn active_settings(default: DemSetting) -> Settings {
    [true, false]
        .into_iter()
        .map(|a| {
            (
                DemSetting {
                    active_set: a,
                    ..default
                },
                Setting::cat(if a { "on" } else { "off" }, a, a),
            )
        })
        .collect()
}

/// Runs the tier (see the module docs). Runs shared by several knobs (the default, the
/// reference) run once, kept in `runs` for the tiers diagram.
pub fn run(
    quick: bool,
    progress: &dyn Progress,
    runs: &mut DemRuns,
) -> Result<Vec<WorkPrecisionRow>> {
    let pr = protocol(quick);
    let ss = scenes(Some(small_slider(quick)))?;
    let (default, knobs) = plan(quick, &pr);
    let total: usize = knobs.iter().map(|k| k.1.len()).sum::<usize>() * ss.len();
    progress.stage("work-precision: DEM", total as u64, "runs");
    let mut rows = Vec::new();
    for s in &ss {
        for (knob, settings) in &knobs {
            let ms: Vec<Measured> = settings
                .iter()
                .map(|(d, setting)| {
                    let m = runs.get(s, &pr, d, setting.clone());
                    progress.advance(1);
                    m
                })
                .collect();
            rows.extend(compare(Tier::Dem, &s.name, *knob, &ms));
        }
    }
    if !quick {
        // the study scenes: reduced against full at the default step (the reference)
        for s in &scenes(None)? {
            let ms: Vec<Measured> = [
                (ModelRequest::Reduced, "reduced"),
                (ModelRequest::Full, "full"),
            ]
            .into_iter()
            .map(|(m, name)| {
                let d = DemSetting {
                    model: m,
                    ..default
                };
                run_one(
                    s,
                    &pr,
                    &d,
                    Setting::cat(name, m == ModelRequest::Full, m == ModelRequest::Full),
                )
            })
            .collect();
            rows.extend(compare(Tier::Dem, &s.name, Knob::ModelDefaultStep, &ms));
        }
    }
    progress.finish();
    Ok(rows)
}
