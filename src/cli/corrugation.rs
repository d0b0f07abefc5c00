//! `superlube corrugation`: flags → [`crate::study::corrugation::corrugation`] → CSV (streamed)
//! and line plot, each with its sidecar.

use super::{checks, SceneArgs};
use crate::plot::figures::corrugation_png;
use crate::study::corrugation::{corrugation, estimate, CorrugationParams, Method};
use crate::study::rows::CorrugationRow;
use crate::study::sink::Tee;
use crate::study::{check_outputs, meta::scene_file, record, Inputs, Outputs, Progress, Reporter};
use anyhow::{bail, Result};
use std::path::PathBuf;

/// Options of `superlube corrugation`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Slider rotation θ in degrees [default: the scene file's theta_deg, else 0].
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    theta: Option<f64>,
    /// Normal load W in mN (> 0).
    #[arg(
        long = "load-mn",
        value_name = "MN",
        default_value_t = 1.4,
        allow_hyphen_values = true
    )]
    load_mn: f64,
    /// Pulling angles α in degrees from the contact line, |α| ≤ 180: a list `0,45,90` or an
    /// inclusive range `start:stop:step`.
    #[arg(
        long,
        value_name = "DEG",
        default_value = "0:90:5",
        allow_hyphen_values = true
    )]
    alpha: String,
    /// Contact-line angle in degrees from the substrate x axis. Default: the moiré estimate, lines
    /// perpendicular to the shortest beat vector q = G_slider(θ) − G_substrate of the first
    /// reciprocal shells (square-tri at θ = 0: along x); the substrate row a1 when commensurate.
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    line_deg: Option<f64>,
    /// Sliding distance of each path in µm (> 0).
    #[arg(
        long = "distance-um",
        value_name = "UM",
        default_value_t = 30.0,
        allow_hyphen_values = true
    )]
    distance_um: f64,
    /// Sampling step along the path in µm (> 0, ≤ --distance-um).
    #[arg(
        long = "step-um",
        value_name = "UM",
        default_value_t = 0.05,
        allow_hyphen_values = true
    )]
    step_um: f64,
    /// How heights along the path are computed: direct (a solve per sample) or landscape
    /// (interpolated from one landscape; flat substrates only).
    #[arg(long, value_enum, default_value_t = Method::Direct)]
    method: Method,
    /// Landscape grid points per side for `--method landscape` (≥ 2).
    #[arg(long, value_name = "N", default_value_t = 51)]
    grid: usize,
    /// CSV output `theta_deg,load_mN,line_deg,alpha_deg,direction_deg,corrugation_nm,
    /// max_lateral_force_mN`, one row per α, streamed through FILE.csv.partial, with a sidecar
    /// FILE.csv.meta.json. Stdout if absent.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// Line plot PNG of corrugation (nm) versus α (degrees).
    #[arg(long, value_name = "FILE.png")]
    plot: Option<PathBuf>,
    /// Run a sweep above the size limit (2·10⁶ solves) anyway; without it such a sweep is
    /// refused with its estimated time, memory and output size.
    #[arg(long)]
    force: bool,
}

/// Runs `superlube corrugation`.
pub fn run(a: Args) -> Result<()> {
    let alphas = checks::alphas(&a.alpha)?;
    let load = checks::load(a.load_mn)?;
    let (distance, step) = checks::path(a.distance_um, a.step_um)?;
    let line = checks::line_deg(a.line_deg)?;
    let sc = a.scene.resolve(a.theta)?;
    if a.method == Method::Landscape {
        checks::grid(a.grid)?;
        if sc.scene.substrate.sigma_h > 0.0 {
            bail!("`--method landscape` needs a flat substrate (σ_h = 0): the landscape of a perturbed substrate is not periodic; use --method direct");
        }
    }
    let params = CorrugationParams {
        load,
        alphas,
        line,
        distance,
        step,
        method: a.method,
        grid: a.grid,
    };
    check_outputs(&[("--out", a.out.as_deref()), ("--plot", a.plot.as_deref())])?;
    estimate(&sc.scene, &params).check(a.force)?;
    let rep = Reporter::stderr();
    sc.log(&rep);
    let mut outs = Outputs::new(
        Inputs {
            workflow: "corrugation".into(),
            scene: Some(scene_file(&sc.scene)),
            params: record::corrugation(&params),
        },
        sc.warnings.clone(),
    );
    let t0 = std::time::Instant::now();
    // The rows are kept in memory only for the plot.
    let mut rows: Vec<CorrugationRow> = Vec::new();
    let keep = a.plot.is_some();
    outs.stream("--out", a.out.as_deref(), |csv| {
        if keep {
            corrugation(&sc.scene, &params, &mut Tee(csv, &mut rows), &rep)
        } else {
            corrugation(&sc.scene, &params, csv, &rep)
        }
    })?;
    rep.note(&format!(
        "corrugation: {} directions in {:.2} s",
        params.alphas.len(),
        t0.elapsed().as_secs_f64()
    ));
    if let Some(p) = &a.plot {
        outs.attempt("--plot", p, || {
            corrugation_png(p, &sc.scene, &rows, a.distance_um)
        });
    }
    outs.finish()
}
