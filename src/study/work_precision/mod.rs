//! # Work-precision diagrams: what each accuracy knob costs and how wrong it is
//!
//! For every tier (screen/map, friction estimate, tolerance search, DEM) and every accuracy knob
//! of it, each setting is run on the study's scenes ([`scenes`]) and its CPU cost
//! ([`cost`]: process CPU time, not wall) is put beside its error against the knob's
//! reference setting on the same scene (the finest setting, or the richest model): the
//! work-precision diagram of numerical ODE benchmarking (log cost against log error, one line
//! per knob, each point a setting). One tier per file: [`screen`], [`friction`], [`tolerance`],
//! [`dem`]; [`tiers`] puts the tiers themselves on one diagram against the best reference (with
//! [`lammps`]'s point where LAMMPS is installed); their rows are [`WorkPrecisionRow`]s ([`row::compare`] makes them). [`check`] holds
//! the convergence checks of the quick set (each knob's error falls as it is refined, within
//! noise; the DEM's default step is below the window's noise; no default has a coarser
//! neighbour of the same error) — asserted in CI by `tests/work_precision_cli.rs`.
//!
//! The full set (`superlube figures --work-precision`) runs the study scenes (DEM: a 30 µm
//! slider, scaled to the study's load per sphere, and the study scenes at the default step
//! only); the quick set ([`WorkPrecisionParams::quick`]) a 10 µm slider with shorter paths and
//! a 1 + 1 + 40 µs DEM protocol. Results and recommendations:
//! docs/validation/work-precision.md.

pub mod check;
pub mod cost;
pub mod dem;
pub mod friction;
pub mod lammps;
pub mod row;
pub mod screen;
pub mod tiers;
pub mod tolerance;

pub use row::{Measured, Setting, Values, WorkPrecisionRow};

use crate::runs::progress::Progress;
use crate::study::corrugation::contact_line;
use anyhow::Result;
use serde::{Deserialize, Serialize};
use surrogate::units::{deg_to_rad, mn_to_n, um_to_m};
use surrogate::Scene;

/// The tiers of the diagrams, in run order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Tier {
    /// Tier 1 screen and Tier 2 maps: solver model, landscape grid, corrugation path step.
    ScreenMap,
    /// The friction estimate: path step, length, transverse search, inertial starts; the
    /// search segment as a speed-only knob.
    Friction,
    /// The tolerance search: θ and direction sampling steps.
    Tolerance,
    /// Tier 3 DEM: time step, model, tangential history, friction window, active set.
    Dem,
    /// The tiers on one diagram: screen, estimate, DEM (reduced, full), LAMMPS, against the
    /// best reference (the full DEM at a quarter of the default step).
    Tiers,
}

impl Tier {
    /// Every tier, in run order.
    pub const ALL: [Tier; 5] = [
        Tier::ScreenMap,
        Tier::Friction,
        Tier::Tolerance,
        Tier::Dem,
        Tier::Tiers,
    ];

    /// The kebab-case name (file names `work_precision_<name>.csv`).
    pub fn name(self) -> &'static str {
        match self {
            Tier::ScreenMap => "screen-map",
            Tier::Friction => "friction",
            Tier::Tolerance => "tolerance",
            Tier::Dem => "dem",
            Tier::Tiers => "tiers",
        }
    }

    /// The file stem of its CSV and PNG (`work_precision_screen_map`).
    pub fn stem(self) -> String {
        format!("work_precision_{}", self.name().replace('-', "_"))
    }
}

/// What to run (settings are fixed per set; see the tier files).
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPrecisionParams {
    /// The quick set (CI): small scenes, few settings.
    pub quick: bool,
    /// The tiers to run, in order.
    pub tiers: Vec<Tier>,
    /// Whether the tiers diagram runs LAMMPS where it is found ([`lammps::find_lmp`]).
    pub lammps: bool,
}

impl WorkPrecisionParams {
    /// Parameters as recorded in the sidecars.
    pub fn record(&self) -> serde_json::Value {
        serde_json::json!({
            "quick": self.quick,
            "tiers": self.tiers.iter().map(|t| t.name()).collect::<Vec<_>>(),
            "lammps": self.lammps,
        })
    }
}

/// One study scene of the diagrams: the scene at its θ, the pulling direction and the load.
#[derive(Debug, Clone)]
pub struct StudyScene {
    /// `superlubric`, `coating-failure`, `stick-slip` (prefixed `small-` on a small slider).
    pub name: String,
    /// The scene, slider at θ.
    pub scene: Scene,
    /// Pulling direction (rad from the substrate x axis).
    pub direction: f64,
    /// Normal load W (N), scaled to the study's load per slider sphere on a small slider.
    pub load: f64,
}

/// The three study scenes: square-tri θ = 0°, α = 90° at 1.4 mN (superlubric); tri-tri 30°
/// pulled along the substrate x axis at 2.45 mN (coating failure); square-tri 0°, α = 0° at
/// 1.4 mN (stick-slip). α is measured from the contact line (as `friction` does). With
/// `small = Some((radius_um, substrate_um))` the slider is a disc of that radius over a square
/// substrate of that side, loaded per sphere as the study's (W × N_small / N_study).
pub fn scenes(small: Option<(f64, f64)>) -> Result<Vec<StudyScene>> {
    let specs: [(&str, &str, f64, Option<f64>, f64); 3] = [
        ("superlubric", "square-tri", 0.0, Some(90.0), 1.4),
        ("coating-failure", "tri-tri", 30.0, None, 2.45),
        ("stick-slip", "square-tri", 0.0, Some(0.0), 1.4),
    ];
    specs
        .iter()
        .map(|&(name, pattern, theta_deg, alpha_deg, load_mn)| {
            let mut scene = Scene::preset(pattern)?;
            scene.slider.theta = deg_to_rad(theta_deg);
            let n_study = scene.slider_sites_local().len() as f64;
            let mut load = mn_to_n(load_mn);
            let mut name = name.to_string();
            if let Some((r, side)) = small {
                scene.slider.radius = um_to_m(r);
                scene.substrate.size = [um_to_m(side), um_to_m(side)];
                load *= scene.slider_sites_local().len() as f64 / n_study;
                name = format!("small-{name}");
            }
            scene.validate()?;
            let direction = match alpha_deg {
                Some(a) => contact_line(&scene, None).angle + deg_to_rad(a),
                None => 0.0,
            };
            Ok(StudyScene {
                name,
                scene,
                direction,
                load,
            })
        })
        .collect()
}

/// Runs the tiers of `p` one after the other (the DEM runs the tiers diagram shares with the
/// DEM tier run once) and hands each tier's rows to `emit` as soon as
/// the tier is done (the command writes its CSV and PNG then). Errors: a scene or a run that
/// cannot start; a setting that fails is a row with its reason in `note`.
pub fn work_precision(
    p: &WorkPrecisionParams,
    progress: &dyn Progress,
    emit: &mut dyn FnMut(Tier, Vec<WorkPrecisionRow>) -> Result<()>,
) -> Result<()> {
    let mut runs = dem::DemRuns::default();
    let lmp = if p.lammps && p.tiers.contains(&Tier::Tiers) {
        let found = lammps::find_lmp();
        if found.is_none() {
            progress
                .note("work-precision: LAMMPS (`lmp`) not found; the tiers diagram leaves it out");
        }
        found
    } else {
        None
    };
    for &tier in &p.tiers {
        let rows = match tier {
            Tier::ScreenMap => screen::run(p.quick, progress)?,
            Tier::Friction => friction::run(p.quick, progress)?,
            Tier::Tolerance => tolerance::run(p.quick, progress)?,
            Tier::Dem => dem::run(p.quick, progress, &mut runs)?,
            Tier::Tiers => tiers::run(p.quick, lmp.as_deref(), progress, &mut runs)?,
        };
        emit(tier, rows)?;
    }
    Ok(())
}
