//! `superlube corrugation`: corrugation and static-friction barrier along pulling directions α.

use super::landscape::{landscape_with_progress, progress, theta_load};
use super::{parse_list_or_range, SceneArgs};
use crate::output::{csv_text, write_or_stdout};
use anyhow::{bail, Result};
use serde::Serialize;
use std::path::PathBuf;
use surrogate::map::{
    contact_line_direction, corrugation_direct, corrugation_from_landscape, CorrugationPoint,
    MapParams,
};
use surrogate::solver::Solver;
use surrogate::units::{deg_to_rad, m_to_nm, n_to_mn, rad_to_deg, um_to_m};

/// How the heights along a path are obtained.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// A solver call at every sample along the path (exact up to the sampling step).
    Direct,
    /// Bicubic interpolation of one periodic landscape (fast; flat substrates only; the lateral
    /// force is the rigid-limit W·dz/ds).
    Landscape,
}

/// Options of `superlube corrugation`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Slider rotation θ in degrees.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    theta: f64,
    /// Normal load W in mN.
    #[arg(long = "load-mn", default_value_t = 1.4)]
    load_mn: f64,
    /// Pulling angles α in degrees from the contact line, |α| ≤ 180: a list `0,45,90` or a range
    /// `start:stop:step` (inclusive).
    #[arg(long, default_value = "0:90:5", allow_hyphen_values = true)]
    alpha: String,
    /// Contact-line angle in degrees from the substrate x axis. Default: the moiré estimate, lines
    /// perpendicular to the shortest beat vector q = G_slider(θ) − G_substrate of the first
    /// reciprocal shells (square-tri at θ = 0: along x); the substrate row a1 when commensurate.
    #[arg(long = "line-deg", allow_hyphen_values = true)]
    line_deg: Option<f64>,
    /// Sliding distance of each path in µm.
    #[arg(long = "distance-um", default_value_t = 30.0)]
    distance_um: f64,
    /// Sampling step along the path in µm.
    #[arg(long = "step-um", default_value_t = 0.05)]
    step_um: f64,
    /// How heights along the path are computed.
    #[arg(long, value_enum, default_value_t = Method::Direct)]
    method: Method,
    /// Landscape grid points per side for `--method landscape`.
    #[arg(long, default_value_t = 51)]
    grid: usize,
    /// CSV output `alpha_deg,direction_deg,corrugation_nm,max_lateral_force_mN`; stdout if omitted.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// Line plot PNG of corrugation (nm) versus α.
    #[arg(long, value_name = "FILE.png")]
    plot: Option<PathBuf>,
}

/// One CSV row of a corrugation sweep.
#[derive(Serialize)]
pub(crate) struct Row {
    pub alpha_deg: f64,
    pub direction_deg: f64,
    pub corrugation_nm: f64,
    #[serde(rename = "max_lateral_force_mN")]
    pub max_lateral_force_mn: f64,
}

impl Row {
    pub(crate) fn from_point(p: &CorrugationPoint) -> Row {
        Row {
            alpha_deg: crate::output::clean(rad_to_deg(p.alpha)),
            direction_deg: crate::output::clean(rad_to_deg(p.direction)),
            corrugation_nm: m_to_nm(p.corrugation),
            max_lateral_force_mn: n_to_mn(p.max_lateral_force),
        }
    }
}

/// Validates one pulling angle α (degrees from the contact line, finite, |α| ≤ 180) and returns
/// it in radians.
pub(crate) fn check_alpha(v: f64) -> Result<f64> {
    if !(v.is_finite() && v.abs() <= 180.0) {
        bail!("`--alpha`: {v}° is outside [-180, 180] degrees");
    }
    Ok(deg_to_rad(v))
}

/// Validates `--line-deg` (degrees from the substrate x axis, finite) and returns it in radians.
pub(crate) fn check_line_deg(line_deg: Option<f64>) -> Result<Option<f64>> {
    match line_deg {
        Some(l) if !l.is_finite() => bail!("`--line-deg`: {l} is not a finite angle"),
        l => Ok(l.map(deg_to_rad)),
    }
}

/// Parses and validates `--alpha` (degrees, |α| ≤ 180) into radians.
pub(crate) fn parse_alphas(text: &str) -> Result<Vec<f64>> {
    parse_list_or_range(text, "--alpha")?
        .into_iter()
        .map(check_alpha)
        .collect()
}

/// Path parameters from the distance and step flags (µm).
pub(crate) fn path_params(distance_um: f64, step_um: f64, grid: usize) -> Result<MapParams> {
    if !(distance_um.is_finite() && distance_um > 0.0) {
        bail!("`--distance-um`: {distance_um} must be a positive distance in µm");
    }
    if !(step_um.is_finite() && step_um > 0.0 && step_um <= distance_um) {
        bail!("`--step-um`: {step_um} must be positive and at most --distance-um");
    }
    Ok(MapParams {
        grid,
        distance: um_to_m(distance_um),
        step: um_to_m(step_um),
        ..MapParams::default()
    })
}

/// Runs `superlube corrugation`.
pub fn run(args: Args) -> Result<()> {
    let alphas = parse_alphas(&args.alpha)?;
    let (theta, load) = theta_load(args.theta, args.load_mn)?;
    let params = path_params(args.distance_um, args.step_um, args.grid)?;
    let given_line = check_line_deg(args.line_deg)?;
    let scene = args.scene.scene()?;
    let solver = Solver::new(&scene)?;
    let line = contact_line_direction(&scene, theta, &params);
    let line_angle = given_line.unwrap_or(line.angle);
    eprintln!(
        "contact line: {:.3}° from x ({}; moiré estimate {:.3}°{}, line spacing {:.2} µm)",
        rad_to_deg(line_angle),
        if args.line_deg.is_some() {
            "given by --line-deg"
        } else {
            "moiré estimate"
        },
        rad_to_deg(line.angle),
        if line.degenerate {
            ", degenerate: commensurate first shells, substrate row used"
        } else {
            ""
        },
        line.spacing * 1e6
    );
    let t0 = std::time::Instant::now();
    let points = match args.method {
        Method::Direct => {
            let per = (params.distance / params.step - 1e-9).ceil().max(1.0) as u64 + 1;
            let pb = progress(per * alphas.len() as u64, "corrugation");
            let r =
                corrugation_direct(&solver, theta, load, line_angle, &alphas, &params, &|| {
                    pb.inc(1)
                })?;
            pb.finish_and_clear();
            r
        }
        Method::Landscape => {
            if scene.substrate.sigma_h > 0.0 {
                bail!("`--method landscape` needs a flat substrate (σ_h = 0): the landscape of a perturbed substrate is not periodic; use --method direct");
            }
            let l = landscape_with_progress(&solver, theta, load, args.grid)?;
            corrugation_from_landscape(&l, line_angle, &alphas, &params)?
        }
    };
    eprintln!(
        "corrugation: {} directions in {:.2} s",
        points.len(),
        t0.elapsed().as_secs_f64()
    );
    let rows: Vec<Row> = points.iter().map(Row::from_point).collect();
    write_or_stdout(args.out.as_deref(), &csv_text(&rows)?)?;
    if let Some(p) = &args.plot {
        crate::plot::line_plot(
            p,
            (1000, 650),
            &crate::plot::LinePlot {
                title: format!(
                    "Corrugation, {}, θ = {}°, W = {} mN, {} µm paths",
                    scene.pattern,
                    super::landscape::fmt_num(args.theta),
                    super::landscape::fmt_num(args.load_mn),
                    super::landscape::fmt_num(args.distance_um)
                ),
                x_label: "pulling angle α from the contact line (°)".into(),
                y_label: "corrugation, peak-to-peak z (nm)".into(),
                series: vec![crate::plot::Series {
                    name: "corrugation".into(),
                    points: rows
                        .iter()
                        .map(|r| (r.alpha_deg, r.corrugation_nm))
                        .collect(),
                }],
                hlines: vec![],
                log_y: false,
            },
        )?;
    }
    Ok(())
}
