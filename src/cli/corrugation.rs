//! `superlube corrugation`: flags → [`crate::study::corrugation::corrugation`] → CSV (streamed)
//! and line plot, each with its sidecar.

use super::point_args::{default, help, Alphas, Load, Theta, ALPHA, THETA};
use super::sweep_args::SweepArgs;
use super::{checks, SceneArgs};
use crate::plot::figures::corrugation_png;
use crate::runs::sink::Tee;
use crate::runs::{
    meta::scene_file, meta::Inputs, output::check_outputs, output::Outputs, progress::Progress,
    progress::Reporter, sweep::Sweep,
};
use crate::study::corrugation::{
    check_paths, contact_line, corrugation, estimate, CorrugationParams, Method,
};
use crate::study::record;
use crate::study::rows::CorrugationRow;
use anyhow::{bail, Context, Result};
use std::path::PathBuf;

/// Options of `superlube corrugation`.
#[derive(clap::Args, Debug)]
#[command(
    mut_args(help(
        THETA,
        "Slider rotation θ in degrees [default: the scene file's theta_deg, else 0]"
    )),
    mut_args(help(
        ALPHA,
        "Pulling angles α in degrees from the contact line, |α| ≤ 180: a list `0,45,90` or \
         an inclusive range `start:stop:step`"
    )),
    mut_args(default(ALPHA, "0:90:5"))
)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// `--theta-deg`: one θ (degrees).
    #[command(flatten)]
    theta: Theta,
    /// `--load-mn`: one load (mN).
    #[command(flatten)]
    load: Load,
    /// `--alpha-deg`: α, a list or range (degrees).
    #[command(flatten)]
    alpha: Alphas,
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
    #[command(flatten)]
    sweep: SweepArgs,
}

/// A checked `superlube corrugation`, ready to run.
pub type Prepared = super::prepared::Prepared<Args, CorrugationParams>;

/// Runs `superlube corrugation`.
pub fn run(a: Args) -> Result<()> {
    execute(prepare(a)?)
}

/// Every check of `superlube corrugation`, before any work: flags, scene, every path, outputs,
/// size.
pub fn prepare(a: Args) -> Result<Prepared> {
    let alphas = a.alpha.radians()?;
    let load = a.load.newtons()?;
    let (distance, step) = checks::path(a.distance_um, a.step_um)?;
    let line = checks::line_deg(a.line_deg)?;
    let mut sc = a.scene.resolve(a.theta.deg)?;
    checks::line_for(&sc.scene, line)?;
    if a.method == Method::Landscape {
        checks::grid(a.grid)?;
        sc.warnings.extend(checks::grid_warning(&sc.scene, a.grid));
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
    let run = a.sweep.run(
        Sweep {
            items: params.alphas.len(),
            rows_per_item: 1,
            unit: "α",
            schema: "corrugation",
        },
        a.out.as_deref(),
        &a.plot.as_ref().map_or(vec![], |_| vec!["--plot"]),
    )?;
    check_outputs(&[("--out", a.out.as_deref()), ("--plot", a.plot.as_deref())])?;
    // Every path of the sweep (not only this shard's) must stay over the substrate.
    if let Err(e) = check_paths(&sc.scene, &params, &contact_line(&sc.scene, params.line)) {
        sc.log(&Reporter::stderr()); // the edge warning explains the refusal
        return Err(e);
    }
    let estimate = match params.method {
        // the landscape is computed whole by every shard
        Method::Landscape => estimate(&sc.scene, &params),
        Method::Direct => estimate(&sc.scene, &params).part(run.range().len(), params.alphas.len()),
    };
    estimate.check(a.force)?;
    Ok(Prepared {
        a,
        sc,
        params,
        run,
        estimate,
    })
}

fn execute(p: Prepared) -> Result<()> {
    let Prepared {
        a, sc, params, run, ..
    } = p;
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
    // The rows are kept in memory only for the plot (a resumed run reads them back from --out).
    let mut rows: Vec<CorrugationRow> = Vec::new();
    let keep = a.plot.is_some() && !run.resume;
    let mut computed = 0;
    outs.stream_sweep("--out", a.out.as_deref(), &run, &rep, |items, csv| {
        computed = items.len();
        let part = CorrugationParams {
            alphas: params.alphas[items].to_vec(),
            ..params.clone()
        };
        if keep {
            corrugation(&sc.scene, &part, &mut Tee(csv, &mut rows), &rep)
        } else {
            corrugation(&sc.scene, &part, csv, &rep)
        }
    })?;
    rep.note(&format!(
        "corrugation: {computed} directions in {:.2} s",
        t0.elapsed().as_secs_f64()
    ));
    if let (Some(out), true, true) = (a.out.as_deref(), a.plot.is_some(), run.resume) {
        rows = csv::Reader::from_path(out)
            .and_then(|mut r| r.deserialize().collect())
            .with_context(|| format!("reading {} back for the plot", out.display()))?;
    }
    if let Some(p) = &a.plot {
        outs.attempt("--plot", p, || {
            corrugation_png(p, &sc.scene, &rows, a.distance_um)
        });
    }
    outs.finish()
}
