//! Test fixture of the stages' unit tests: a small design (a 15 µm slider of ≈ 80 spheres on a
//! 60 × 60 µm substrate, two loads, three θ) whose parameters are built here as the command
//! line builds them, and a recording observer.

use super::confirm::ConfirmParams;
use super::evaluate::AlphaScanParams;
use super::limit::ToleranceParams;
use super::model::DesignScene;
use super::observer::{Event, Observer};
use super::params::DesignParams;
use super::screen::ScreenStageParams;
use super::shortlist::ShortlistParams;
use crate::runs::progress::{Progress, Silent};
use crate::study::load::Loads;
use std::sync::Mutex;

/// The small scene of `pattern` (a preset) as a design's pattern.
pub fn small_scene(pattern: &str) -> DesignScene {
    let mut scene = surrogate::Scene::preset(pattern).unwrap();
    scene.slider.radius = 15e-6;
    scene.substrate.size = [60e-6, 60e-6];
    DesignScene {
        name: pattern.into(),
        scene,
        flags: vec![],
        warnings: vec![],
        facts: None,
        recipe: None,
    }
}

/// The parameters of a small design: θ 0:30:15, loads 0.01 and 0.03 mN, tolerance θ ± `tol`°
/// × direction ± 5·`tol`° (0: none), the DEM on (`--confirm 1` at both loads, no protocol
/// check) unless `no_dem`, no yield.
pub fn small_params(tol: f64, no_dem: bool) -> DesignParams {
    let loads = Loads::new(vec![0.01e-3, 0.03e-3]);
    DesignParams {
        loads: loads.clone(),
        mu_superlubric: 0.02,
        screen: ScreenStageParams {
            thetas_deg: vec![0.0, 15.0, 30.0],
            theta_default: false,
            symmetry_cut: true,
        },
        shortlist: ShortlistParams {
            per_level: 1,
            max_top: 2,
        },
        alpha_scan: AlphaScanParams {
            alpha_step_deg: 15.0,
            alpha_refine_deg: vec![2.5],
            line: None,
            scan_length: 6e-6,
            scan_step: 0.2e-6,
            alphas_per_theta: 1,
        },
        friction: surrogate::friction::FrictionParams::default(),
        tolerance: ToleranceParams {
            theta_tol_deg: tol,
            direction_tol_deg: 5.0 * tol,
            theta_tol_step_deg: 0.05,
            direction_tol_step_deg: 0.25,
            seeds: vec![],
        },
        confirm: ConfirmParams {
            designs: 1,
            loads: loads.to_vec(),
            no_dem,
            jobs: 1,
            dem_shard: crate::runs::shard::Shard::ALL,
            dem: dem_params(),
            dem_is_study_protocol: false,
            protocol_check: false,
        },
        fab_yield: None,
    }
}

/// A fresh, empty output folder under the temporary directory for test `name`.
pub fn out_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("superlube-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// An observer that records a short name of each event, in order.
#[derive(Default)]
pub struct Record(pub Mutex<Vec<&'static str>>);

impl Record {
    /// The names recorded so far.
    pub fn names(&self) -> Vec<&'static str> {
        self.0.lock().unwrap().clone()
    }
}

impl Observer for Record {
    fn event(&self, e: &Event<'_>) {
        let name = match e {
            Event::Symmetry { .. } => "symmetry",
            Event::Screened { .. } | Event::ScreenReused { .. } => "screen",
            Event::Level { .. } => "level",
            Event::Robust { .. } => "robust",
            Event::RobustDone { .. } => "robust-done",
            Event::Best { .. } => "best",
            Event::DemRuns { .. } => "dem",
            Event::DemNothing => "dem-nothing",
            Event::ProtocolCheck { .. } => "protocol-check",
            Event::ToleranceMap { .. } => "tolerance-map",
            Event::Yield { .. } => "yield",
            _ => "other",
        };
        self.0.lock().unwrap().push(name);
    }

    fn progress(&self) -> &dyn Progress {
        &Silent
    }
}

/// A DEM that runs nothing: every job's outcome is μ_DEM `mu` with P_max 3 GPa, not locked
/// in; every batch asked of it is recorded (its jobs' names and the threads).
pub struct Oracle {
    /// μ_DEM of every run.
    pub mu: f64,
    /// The batches asked, in order: (job names, threads).
    pub batches: Mutex<Vec<(Vec<String>, usize)>>,
}

impl Oracle {
    /// An oracle answering μ_DEM `mu`.
    pub fn new(mu: f64) -> Self {
        Oracle {
            mu,
            batches: Mutex::new(Vec::new()),
        }
    }
}

impl super::confirm::DemRunner for Oracle {
    fn run(
        &self,
        jobs: &[crate::study::batch::SlideJob],
        threads: usize,
        dir: &std::path::Path,
        _: &dyn Progress,
    ) -> anyhow::Result<Vec<crate::study::batch::SlideOutcome>> {
        let names = jobs.iter().map(|j| j.name.clone()).collect();
        self.batches.lock().unwrap().push((names, threads));
        Ok(jobs
            .iter()
            .map(|j| crate::study::batch::SlideOutcome {
                name: j.name.clone(),
                dir: dir.join(&j.name),
                result: Some(crate::study::batch::SlideResult {
                    friction_mN: 0.0,
                    friction_std_mN: 0.0,
                    mu: self.mu,
                    mean_contacts: 10.0,
                    max_p_max_GPa: 3.0,
                    mean_failed_contacts: 0.0,
                    locked_in: false,
                    advance_ratio: None,
                    steps: 1,
                    wall_s: 0.0,
                }),
                error: None,
                reused: false,
            })
            .collect())
    }
}

/// The DEM parameters of the fixtures' confirmation (the study's protocol; never run: the
/// tests' DEM is an [`Oracle`]).
pub fn dem_params() -> crate::study::dem_run::DemParams {
    crate::study::dem_run::DemParams {
        sim: dem::SimParams::default(),
        alpha: 0.0,
        line: None,
        start: dem::Start::Surrogate,
        friction: None,
        io: dem::protocol::RunIo {
            checkpoint: None,
            checkpoint_every: 50_000,
            xyz: None,
            xyz_every: 10_000,
        },
        resume: None,
        model: crate::study::dem_run::ModelSpec::default(),
    }
}
