//! The tiers on one diagram ("speed against error", the README's tier table): for the same
//! (θ, α, W) — the DEM tier's three scenes on its small slider, loaded per sphere as the
//! study's — the Tier 1 screen's P_max at the placement, the Tier 2 estimate's μ_est and path
//! P_max, the Tier 3 DEM's μ and window P_max (reduced and full model at the default step) and
//! LAMMPS's (the exported deck, where `lmp` is found and not turned off), each at its CPU cost,
//! against the best reference: the full DEM at a quarter of the default step (the DEM tier's
//! reference, reused with the default and reduced runs when the set ran the DEM tier).
//!
//! Errors are of μ and of P_max, the latter against the reference's largest P_max over the
//! friction window (the coating criterion of a slide): the screen sees one placement, the
//! estimate one quasi-static path, so their P_max errors include what those models leave out.
//! The contacts are not judged (the screen's are at one placement, the others' a mean).

use super::dem::{
    default_setting, protocol, reference_setting, small_slider, DemRuns, DemSetting, Protocol,
};
use super::friction::one as estimate_one;
use super::row::{compare, Measured, Setting, Values};
use super::{lammps, scenes, Knob, StudyScene, Tier, WorkPrecisionRow};
use crate::runs::progress::Progress;
use crate::study::verdict::Verdict;
use anyhow::Result;
use dem::ModelRequest;
use serde::{Deserialize, Serialize};
use surrogate::friction::FrictionParams;
use surrogate::solver::{Model, Pose, Solver};

/// The methods of the diagram, in the order of their cost (cheapest first).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Method {
    /// Tier 1 screen: the quasi-static solve at the placement (`Model::Auto`).
    Screen,
    /// Tier 2 estimate: μ_est and the path's P_max at the default `FrictionParams`.
    Estimate,
    /// Tier 3 DEM, reduced model, default step.
    DemReduced,
    /// Tier 3 DEM, full model, default step (the code's default DEM).
    DemFull,
    /// The exported deck in stock LAMMPS (constant μ = μ1).
    Lammps,
    /// The best reference: full DEM at a quarter of the default step.
    Reference,
}

impl Method {
    /// Every method, in cost order.
    pub const ALL: [Method; 6] = [
        Method::Screen,
        Method::Estimate,
        Method::DemReduced,
        Method::DemFull,
        Method::Lammps,
        Method::Reference,
    ];

    /// The text of the CSV's `setting` column.
    pub fn name(self) -> &'static str {
        match self {
            Method::Screen => "screen",
            Method::Estimate => "estimate",
            Method::DemReduced => "DEM reduced",
            Method::DemFull => "DEM full",
            Method::Lammps => "LAMMPS",
            Method::Reference => "DEM full, step/4 (reference)",
        }
    }

    /// The method a `setting` text names (`None`: not a method of this diagram).
    pub fn parse(text: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == text)
    }
}

/// The screen's verdict on the coating at one P_max (Pa): the band rule on P_max alone.
fn coating_verdict(p_max: f64, s: &StudyScene) -> Verdict {
    Verdict::of(Some(0.0), Some(p_max), 0.02, s.scene.coating.p_crit)
}

fn screen(s: &StudyScene) -> Result<Measured> {
    let solver = Solver::new(&s.scene)?;
    let pose = Pose {
        theta: s.scene.slider.theta,
        shift: [0.0, 0.0],
    };
    let (eq, cost) =
        super::cost::measure_repeated(0.05, || solver.solve(pose, s.load, Model::Auto));
    let values = match eq {
        Ok(eq) => Values {
            p_max: Some(eq.p_max),
            verdict: Some(coating_verdict(eq.p_max, s)),
            note: format!("solver {}", eq.model.name()),
            ..Values::default()
        },
        Err(e) => Values {
            note: e.to_string(),
            ..Values::default()
        },
    };
    Ok(Measured {
        setting: setting(Method::Screen),
        cost,
        values,
    })
}

fn setting(m: Method) -> Setting {
    Setting::cat(m.name(), false, m == Method::Reference)
}

/// Only μ and P_max are compared: a DEM run's contacts (and their noise) are dropped.
fn mu_and_p_max(mut m: Measured) -> Measured {
    m.values.contacts = None;
    m.values.contacts_se = 0.0;
    m
}

/// Runs the diagram (see the module docs); `lammps_exe`: the LAMMPS binary, or `None` to leave
/// LAMMPS out. DEM runs already in `runs` are reused.
pub fn run(
    quick: bool,
    lammps_exe: Option<&str>,
    progress: &dyn Progress,
    runs: &mut DemRuns,
) -> Result<Vec<WorkPrecisionRow>> {
    let pr: Protocol = protocol(quick);
    let ss = scenes(Some(small_slider(quick)))?;
    let per_scene = 5 + usize::from(lammps_exe.is_some());
    progress.stage(
        "work-precision: tiers",
        (ss.len() * per_scene) as u64,
        "methods",
    );
    let default = default_setting(&pr);
    let reduced = DemSetting {
        model: ModelRequest::Reduced,
        ..default
    };
    let mut rows = Vec::new();
    for s in &ss {
        let mut ms = vec![screen(s)?];
        progress.advance(1);
        let solver = Solver::new(&s.scene)?;
        let mut est = estimate_one(
            &solver,
            s,
            &FrictionParams::default(),
            setting(Method::Estimate),
        );
        est.values.contacts = None;
        ms.push(est);
        progress.advance(1);
        for (m, d) in [(Method::DemReduced, reduced), (Method::DemFull, default)] {
            ms.push(mu_and_p_max(runs.get(s, &pr, &d, setting(m))));
            progress.advance(1);
        }
        if let Some(exe) = lammps_exe {
            ms.push(lammps::run_one(
                s,
                &pr,
                &default,
                exe,
                setting(Method::Lammps),
            ));
            progress.advance(1);
        }
        let r = reference_setting(&pr);
        ms.push(mu_and_p_max(runs.get(
            s,
            &pr,
            &r,
            setting(Method::Reference),
        )));
        progress.advance(1);
        rows.extend(compare(Tier::Tiers, &s.name, Knob::Tier, &ms));
    }
    progress.finish();
    Ok(rows)
}
