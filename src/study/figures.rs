//! The figures workflow: the data of every figure of the screening study (orientation sweeps,
//! contact maps, Δz landscapes, corrugation versus α), one [`Figure`] at a time through a
//! callback, so the caller draws and stores each one as soon as it is computed. Each figure is
//! made by the same workflow function a command uses (screen, contacts, landscape, corrugation).

use super::contacts::{contacts, ContactsParams};
use super::corrugation::{corrugation, CorrugationParams, Method};
use super::landscape::{landscape, LandscapeParams, LandscapeStats};
use super::record;
use super::rows::{CorrugationRow, LandscapeRow, ScreenRow};
use super::screen::{screen, ScreenParams};
use crate::runs::budget::Estimate;
use crate::runs::meta::{scene_file, Inputs};
use crate::runs::progress::Progress;
use anyhow::Result;
use surrogate::solver::{Equilibrium, Model, SearchKind};
use surrogate::units::{deg_to_rad, mn_to_n};
use surrogate::Scene;

/// Loads of the orientation sweeps (mN).
pub const SWEEP_LOADS_MN: [f64; 4] = [0.35, 1.4, 2.1, 3.86];
/// Patterns of the orientation sweeps.
pub const SWEEP_PATTERNS: [&str; 2] = ["tri-tri", "square-tri"];
/// Contact-map configurations (pattern, θ in degrees) at [`MAP_LOAD_MN`].
pub const CONTACT_MAPS: [(&str, f64); 6] = [
    ("tri-tri", 0.0),
    ("tri-tri", 21.8),
    ("tri-tri", 30.0),
    ("square-tri", 0.0),
    ("square-tri", 10.2),
    ("square-tri", 15.0),
];
/// Load of the contact maps and landscapes (mN).
pub const MAP_LOAD_MN: f64 = 1.4;
/// Orientations of the square-tri landscapes (degrees).
pub const LANDSCAPE_THETAS: [f64; 2] = [0.0, 10.2];
/// Orientations (degrees) × loads (mN) of the corrugation figure (square-tri).
pub const CORRUGATION_CASES: ([f64; 3], [f64; 2]) = ([0.0, 10.2, 12.4], [0.35, 1.4]);

/// Which figure groups to make.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Group {
    /// Contacts and P_max versus θ (tri-tri, square-tri).
    Sweep,
    /// Contact maps at 1.4 mN.
    Contacts,
    /// Δz landscapes of square-tri at 0° and 10.2°.
    Landscapes,
    /// Corrugation versus α for square-tri.
    Corrugation,
}

/// Parameters of the figures (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct FiguresParams {
    /// θ values of the orientation sweeps (rad), e.g. 0:30:0.1°.
    pub sweep_thetas: Vec<f64>,
    /// Corrugation figure: pulling angles α (rad), path length and step (m), method, grid.
    pub corrugation: CorrugationParams,
    /// Landscape grid points per side.
    pub grid: usize,
    /// Groups to make (all if empty).
    pub groups: Vec<Group>,
}

impl FiguresParams {
    fn want(&self, g: Group) -> bool {
        self.groups.is_empty() || self.groups.contains(&g)
    }

    /// Cost estimate of everything asked (solves summed over the groups, on the study scene).
    pub fn estimate(&self) -> Estimate {
        let scene = Scene::preset("square-tri").expect("preset");
        let mut solves = 0u64;
        if self.want(Group::Sweep) {
            solves += 2 * self.sweep_thetas.len() as u64 * SWEEP_LOADS_MN.len() as u64;
        }
        if self.want(Group::Contacts) {
            solves += CONTACT_MAPS.len() as u64;
        }
        if self.want(Group::Landscapes) {
            solves += 2 * (self.grid * self.grid) as u64;
        }
        if self.want(Group::Corrugation) {
            let c = &self.corrugation;
            let per = match c.method {
                Method::Direct => c.alphas.len() as u64 * c.samples_per_path(),
                Method::Landscape => (c.grid * c.grid) as u64,
            };
            solves += 6 * per;
        }
        Estimate::solves(
            &format!(
                "{}, {}, {} × ({} / {})",
                crate::study::input::Input::ThetaStepDeg,
                crate::study::input::Input::Grid,
                crate::study::input::Input::Alpha,
                crate::study::input::Input::DistanceUm,
                crate::study::input::Input::StepUm
            ),
            solves,
            scene.slider_sites_local().len(),
            scene.substrate_spheres().len(),
            8.0 * (self.grid * self.grid) as f64,
            0.0,
        )
    }
}

/// One computed figure: its file name (without extension), the data behind it and the inputs
/// that made it.
pub enum Figure {
    /// Contacts and P_max versus θ at the sweep loads.
    Sweep {
        /// File base name, e.g. `sweep_tri-tri`.
        name: String,
        /// The scene (preset).
        scene: Scene,
        /// The screen rows (θ outer, W inner).
        rows: Vec<ScreenRow>,
    },
    /// The contact map of one configuration.
    ContactMap {
        /// File base name.
        name: String,
        /// The scene (θ set).
        scene: Scene,
        /// Load (N).
        load: f64,
        /// The equilibrium with its contacts.
        eq: Equilibrium,
    },
    /// A Δz landscape.
    Landscape {
        /// File base name.
        name: String,
        /// The scene (θ set).
        scene: Scene,
        /// Load (N).
        load: f64,
        /// Cell, range, periodicity.
        stats: LandscapeStats,
        /// The rows (row-major, x fastest).
        rows: Vec<LandscapeRow>,
    },
    /// Corrugation and barrier versus α for several (θ, W).
    Corrugation {
        /// File base name.
        name: String,
        /// Rows: θ outer, W, then α.
        rows: Vec<CorrugationRow>,
        /// Path length (m), for the title.
        distance: f64,
    },
}

impl Figure {
    /// The file base name.
    pub fn name(&self) -> &str {
        match self {
            Figure::Sweep { name, .. }
            | Figure::ContactMap { name, .. }
            | Figure::Landscape { name, .. }
            | Figure::Corrugation { name, .. } => name,
        }
    }
}

/// `v` formatted without trailing zeros (for titles and file names): 1.4 → `1.4`, 0 → `0`.
pub fn fmt_num(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// Makes the figures asked in `p`, handing each to `emit` (with the inputs to record) as soon as
/// it is computed.
pub fn figures(
    p: &FiguresParams,
    progress: &dyn Progress,
    emit: &mut dyn FnMut(Figure, Inputs) -> Result<()>,
) -> Result<()> {
    let t0 = std::time::Instant::now();
    if p.want(Group::Sweep) {
        sweeps(p, progress, emit, t0)?;
    }
    if p.want(Group::Contacts) {
        contact_maps(progress, emit, t0)?;
    }
    if p.want(Group::Landscapes) {
        landscapes(p, progress, emit, t0)?;
    }
    if p.want(Group::Corrugation) {
        corrugation_figure(p, progress, emit, t0)?;
    }
    Ok(())
}

/// The screening sweeps of [`SWEEP_PATTERNS`]. `t0`: when the figures started (for the progress note).
fn sweeps(
    p: &FiguresParams,
    progress: &dyn Progress,
    emit: &mut dyn FnMut(Figure, Inputs) -> Result<()>,
    t0: std::time::Instant,
) -> Result<()> {
    for pattern in SWEEP_PATTERNS {
        let scene = Scene::preset(pattern)?;
        let sp = ScreenParams {
            thetas: p.sweep_thetas.clone(),
            loads: SWEEP_LOADS_MN.iter().map(|&w| mn_to_n(w)).collect(),
            model: Model::Auto,
            search: SearchKind::Grid,
        };
        let mut rows = Vec::new();
        screen(&scene, &sp, &mut rows, progress)?;
        let mut sc = scene.clone();
        sc.slider.theta = 0.0;
        let i = inputs("sweep", Some(&sc), record::screen(&sp));
        emit(
            Figure::Sweep {
                name: format!("sweep_{pattern}"),
                scene,
                rows,
            },
            i,
        )?;
    }
    progress.note(&format!(
        "sweeps done ({:.1} s)",
        t0.elapsed().as_secs_f64()
    ));
    Ok(())
}

/// The contact maps of [`CONTACT_MAPS`]. `t0`: when the figures started (for the progress note).
fn contact_maps(
    progress: &dyn Progress,
    emit: &mut dyn FnMut(Figure, Inputs) -> Result<()>,
    t0: std::time::Instant,
) -> Result<()> {
    for (pattern, t) in CONTACT_MAPS {
        let scene = Scene::preset(pattern)?.with_theta(deg_to_rad(t));
        let cp = ContactsParams {
            theta: scene.slider.theta,
            load: mn_to_n(MAP_LOAD_MN),
            model: Model::Auto,
            search: SearchKind::Grid,
        };
        let eq = contacts(&scene, &cp)?;
        let i = inputs("contacts", Some(&scene), record::contacts(&cp));
        emit(
            Figure::ContactMap {
                name: format!(
                    "contact_map_{pattern}_{}deg_{}mN",
                    fmt_num(t),
                    fmt_num(MAP_LOAD_MN)
                ),
                scene,
                load: cp.load,
                eq,
            },
            i,
        )?;
    }
    progress.note(&format!(
        "contact maps done ({:.1} s)",
        t0.elapsed().as_secs_f64()
    ));
    Ok(())
}

/// The height landscapes of square-tri at [`LANDSCAPE_THETAS`]. `t0`: when the figures started (for the progress note).
fn landscapes(
    p: &FiguresParams,
    progress: &dyn Progress,
    emit: &mut dyn FnMut(Figure, Inputs) -> Result<()>,
    t0: std::time::Instant,
) -> Result<()> {
    for t in LANDSCAPE_THETAS {
        let scene = Scene::preset("square-tri")?.with_theta(deg_to_rad(t));
        let lp = LandscapeParams {
            load: mn_to_n(MAP_LOAD_MN),
            grid: p.grid,
        };
        // the grid must resolve the moiré's second harmonic (docs/validation/maps.md)
        let need = surrogate::map::grid_need(&scene);
        if need.periods.is_some() && p.grid < need.grid {
            progress.note(&format!(
                "warning: the landscape at θ = {}° needs {} {} or more to resolve its moiré \
                 (at {} it aliases; docs/validation/maps.md)",
                fmt_num(t),
                crate::study::input::Input::Grid,
                need.grid,
                p.grid
            ));
        }
        let mut rows = Vec::new();
        let stats = landscape(&scene, &lp, None, &mut rows, progress)?;
        let i = inputs("landscape", Some(&scene), record::landscape(&lp));
        emit(
            Figure::Landscape {
                name: format!(
                    "landscape_square-tri_{}deg_{}mN",
                    fmt_num(t),
                    fmt_num(MAP_LOAD_MN)
                ),
                scene,
                load: lp.load,
                stats,
                rows,
            },
            i,
        )?;
    }
    progress.note(&format!(
        "landscapes done ({:.1} s)",
        t0.elapsed().as_secs_f64()
    ));
    Ok(())
}

/// The corrugation of square-tri over [`CORRUGATION_CASES`]. `t0`: when the figures started (for the progress note).
fn corrugation_figure(
    p: &FiguresParams,
    progress: &dyn Progress,
    emit: &mut dyn FnMut(Figure, Inputs) -> Result<()>,
    t0: std::time::Instant,
) -> Result<()> {
    let base = Scene::preset("square-tri")?;
    let mut rows = Vec::new();
    let (thetas, loads) = CORRUGATION_CASES;
    for t in thetas {
        for w in loads {
            let scene = base.with_theta(deg_to_rad(t));
            let cp = CorrugationParams {
                load: mn_to_n(w),
                line: None,
                ..p.corrugation.clone()
            };
            corrugation(&scene, &cp, &mut rows, progress)?;
        }
    }
    let mut params = record::corrugation(&p.corrugation);
    params["theta_deg"] = serde_json::json!(thetas);
    params["load_mN"] = serde_json::json!(loads);
    let i = inputs("corrugation", Some(&base), params);
    emit(
        Figure::Corrugation {
            name: "corrugation_square-tri".into(),
            rows,
            distance: p.corrugation.distance,
        },
        i,
    )?;
    progress.note(&format!(
        "corrugation done ({:.1} s)",
        t0.elapsed().as_secs_f64()
    ));
    Ok(())
}

/// The inputs to record of a figure of `workflow` (`figures/<workflow>`).
fn inputs(workflow: &str, scene: Option<&Scene>, params: serde_json::Value) -> Inputs {
    Inputs {
        workflow: format!("figures/{workflow}"),
        scene: scene.map(scene_file),
        params,
    }
}
