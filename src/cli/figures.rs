//! `superlube figures`: flags → [`crate::study::figures::figures`] → each figure's PNG and the
//! CSV behind it (and their sidecars) as soon as it is computed.

use super::campaign::CampaignArgs;
use super::checks;
use super::point_args::{self, default, help, Alphas, ALPHA};
use crate::plot::figures::{contact_map_png, corrugation_figure_png, landscape_png, sweep_png};
use crate::runs::sink::csv_bytes;
use crate::runs::{meta::Inputs, output::check_outputs, output::Outputs, progress::Reporter};
use crate::study::corrugation::{CorrugationParams, Method};
use crate::study::figures::{figures, Figure, FiguresParams, Group};
use crate::study::rows::ContactRow;
use anyhow::{bail, Result};
use std::path::{Path, PathBuf};

/// Options of `superlube figures`.
#[derive(clap::Args, Debug)]
#[command(
    mut_args(help(
        ALPHA,
        "Pulling angles α in degrees of the corrugation figure (list or start:stop:step)"
    )),
    mut_args(default(ALPHA, "-90:90:2"))
)]
pub struct Args {
    /// Output directory for the PNGs, the CSVs behind them and their sidecars (created if
    /// missing) [default: figures; with --friction: figures/friction].
    #[arg(long = "out-dir", value_name = "DIR")]
    out_dir: Option<PathBuf>,
    /// θ step in degrees of the orientation sweeps from 0 to 30° (study: 0.1).
    #[arg(
        long = "theta-step-deg",
        alias = "theta-step",
        value_name = "DEG",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    theta_step: f64,
    /// `--alpha-deg`: α, a list or range (degrees).
    #[command(flatten)]
    alpha: Alphas,
    /// Sliding distance of each corrugation path in µm.
    #[arg(
        long = "distance-um",
        value_name = "UM",
        default_value_t = 30.0,
        allow_hyphen_values = true
    )]
    distance_um: f64,
    /// Sampling step along corrugation paths in µm.
    #[arg(
        long = "step-um",
        value_name = "UM",
        default_value_t = 0.05,
        allow_hyphen_values = true
    )]
    step_um: f64,
    /// How the corrugation figure's heights are computed (as `corrugation --method`): direct (a
    /// solve per path sample) or landscape (interpolated, fast).
    #[arg(
        long = "method",
        alias = "corrugation-method",
        value_name = "METHOD",
        value_enum,
        default_value_t = Method::Direct
    )]
    corrugation_method: Method,
    /// Landscape grid points per side (≥ 2).
    #[arg(long, value_name = "N", default_value_t = 51)]
    grid: usize,
    /// Only these figure groups (comma-separated); all if omitted.
    #[arg(long, value_enum, value_delimiter = ',', conflicts_with = "friction")]
    only: Vec<Group>,
    /// Run above the size limit (2·10⁶ solves) anyway; without it such a run is refused with
    /// its estimated time, memory and output size.
    #[arg(long)]
    force: bool,
    #[command(flatten)]
    campaign: CampaignArgs,
    #[command(flatten)]
    work_precision: super::work_precision::WorkPrecisionArgs,
}

/// `base` + `.ext` (unlike `Path::with_extension`, keeps a dotted number such as `1.4mN`).
fn with_ext(base: &Path, ext: &str) -> PathBuf {
    let mut s = base.as_os_str().to_owned();
    s.push(".");
    s.push(ext);
    PathBuf::from(s)
}

/// Runs `superlube figures`.
pub fn run(a: Args) -> Result<()> {
    if a.campaign.friction {
        let dir = a
            .out_dir
            .clone()
            .unwrap_or_else(|| PathBuf::from("figures/friction"));
        return super::campaign::run(&dir, &a.campaign);
    }
    if a.work_precision.work_precision {
        let dir = a
            .out_dir
            .clone()
            .unwrap_or_else(|| PathBuf::from("figures/work_precision"));
        return super::work_precision::run(&dir, &a.work_precision);
    }
    let out_dir = a
        .out_dir
        .clone()
        .unwrap_or_else(|| PathBuf::from("figures"));
    let params = figures_params(&a)?;
    check_outputs(&[("--out-dir", Some(&out_dir.join("x.csv")))])?;
    params.estimate().check(a.force)?;
    let rep = Reporter::stderr();
    let out = &out_dir;
    let mut outs = Outputs::new(
        Inputs {
            workflow: "figures".into(),
            scene: None,
            params: serde_json::Value::Null,
        },
        vec![],
    );
    figures(&params, &rep, &mut |fig, inputs| {
        outs.set_inputs(inputs);
        write_figure(&mut outs, &out.join(fig.name()), &fig);
        Ok(())
    })?;
    outs.finish()
}

/// The figures' parameters from the flags, checked.
fn figures_params(a: &Args) -> Result<FiguresParams> {
    if !(a.theta_step.is_finite() && a.theta_step > 0.0 && a.theta_step <= 30.0) {
        bail!(
            "`--theta-step-deg`: {} must be in (0, 30] degrees",
            a.theta_step
        );
    }
    let (distance, step) = checks::path(a.distance_um, a.step_um)?;
    Ok(FiguresParams {
        sweep_thetas: point_args::thetas(&format!("0:30:{}", a.theta_step))
            .map_err(|e| anyhow::anyhow!("`--theta-step-deg`: {e}"))?,
        corrugation: CorrugationParams {
            load: 0.0,
            alphas: a.alpha.radians()?,
            line: None,
            distance,
            step,
            method: a.corrugation_method,
            grid: checks::grid(a.grid)?,
        },
        grid: a.grid,
        groups: a.only.clone(),
    })
}

/// Writes figure `fig` as `base.csv` and `base.png`, recorded in `outs`.
fn write_figure(outs: &mut Outputs, base: &Path, fig: &Figure) {
    let (csv, png) = (with_ext(base, "csv"), with_ext(base, "png"));
    match fig {
        Figure::Sweep { scene, rows, .. } => {
            outs.write(
                "--out-dir",
                Some(&csv),
                csv_bytes(rows),
                Some(rows.len() as u64),
            );
            outs.attempt("--out-dir", &png, || sweep_png(&png, scene, rows));
        }
        Figure::ContactMap {
            scene, load, eq, ..
        } => {
            let rows = ContactRow::all(eq);
            outs.write(
                "--out-dir",
                Some(&csv),
                csv_bytes(&rows),
                Some(rows.len() as u64),
            );
            outs.attempt("--out-dir", &png, || {
                contact_map_png(&png, scene, *load, eq)
            });
        }
        Figure::Landscape {
            scene,
            load,
            stats,
            rows,
            ..
        } => {
            outs.write(
                "--out-dir",
                Some(&csv),
                csv_bytes(rows),
                Some(rows.len() as u64),
            );
            let dz: Vec<f64> = rows.iter().map(|r| r.dz_nm).collect();
            outs.attempt("--out-dir", &png, || {
                landscape_png(&png, scene, *load, stats, &dz)
            });
        }
        Figure::Corrugation { rows, distance, .. } => {
            outs.write(
                "--out-dir",
                Some(&csv),
                csv_bytes(rows),
                Some(rows.len() as u64),
            );
            outs.attempt("--out-dir", &png, || {
                corrugation_figure_png(&png, rows, *distance)
            });
        }
    }
}
