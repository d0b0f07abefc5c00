//! `superlube friction`: flags → [`crate::study::friction::friction`] → CSV (streamed) + sidecar.

use super::friction_args::FrictionKnobArgs;
use super::point_args::{help, Alphas, Loads, Thetas, ALPHA, LOAD, THETA};
use super::sweep_args::SweepArgs;
use super::verdict_args::VerdictArgs;
use super::{checks, SceneArgs};
use crate::runs::{
    meta::scene_file, meta::Inputs, output::check_outputs, output::Outputs, progress::Reporter,
    sweep::Sweep,
};
use crate::study::friction::{check, estimate, friction, resonance_note, FrictionSweepParams};
use crate::study::record;
use anyhow::{bail, Result};
use std::path::PathBuf;

/// Options of `superlube friction`: the surrogate friction estimate μ_est (coating term +
/// Prandtl–Tomlinson corrugation term from the quasi-static path; where the path sticks and
/// slips, the slider's centre of mass run along it with the DEM's mass, damping and speed) for
/// every θ × α × W.
#[derive(clap::Args, Debug)]
#[command(
    mut_args(help(
        THETA,
        "Slider orientations θ in degrees: a list `0,10.2` or an inclusive range \
         `start:stop:step` [default: the scene file's theta_deg, else 0]"
    )),
    mut_args(help(
        ALPHA,
        "Pulling angles α in degrees from the slider's contact line (as in `corrugation` and \
         `slide`; 90 = perpendicular to the lines), |α| ≤ 180: a list `0,90` or a range"
    )),
    mut_args(help(
        LOAD,
        "Normal loads W in mN: a list `0.35,1.4` or a range `0.35:3.5:0.35` (each > 0). The \
         loads of one (θ, α) share one path's pair searches"
    ))
)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// `--theta-deg`: θ, a list or range (degrees).
    #[command(flatten)]
    theta: Thetas,
    /// `--alpha-deg`: α, a list or range (degrees).
    #[command(flatten)]
    alpha: Alphas,
    /// `--load-mn`: loads, a list or range (mN).
    #[command(flatten)]
    load: Loads,
    /// Contact-line angle in degrees from the substrate x axis, used for every θ. Default: the
    /// moiré estimate at each θ (as in `corrugation`); the substrate row a1 when commensurate.
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    line_deg: Option<f64>,
    #[command(flatten)]
    knobs: FrictionKnobArgs,
    #[command(flatten)]
    verdict: VerdictArgs,
    /// Output CSV, one row per (θ, α, W), θ outer: `pattern,theta_deg,alpha_deg,load_mN,mu_est,
    /// p_max_GPa,failed_fraction,…,verdict,error` (units in the names; docs/commands/friction.md), streamed
    /// through FILE.csv.partial, with a sidecar FILE.csv.meta.json. Stdout if absent. Rows with
    /// mount_resonance = true (contacts fail and the `--tilt springs` mount's tilt mode is tuned
    /// to the stuck contact pairs' lateral mode, on a smooth substrate; the run prints the band
    /// and the measured drop when it applies) may have mu_est as an upper bound;
    /// docs/validation/friction.md, "The mount's resonance".
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// Run a sweep above the size limit (2·10⁶ solves) anyway; without it such a sweep is
    /// refused with its estimated time, memory and output size.
    #[arg(long)]
    force: bool,
    #[command(flatten)]
    sweep: SweepArgs,
}

/// A checked `superlube friction`, ready to run.
pub type Prepared = super::prepared::Prepared<Args, FrictionSweepParams>;

/// Runs `superlube friction`.
pub fn run(a: Args) -> Result<()> {
    execute(prepare(a)?)
}

/// Every check of `superlube friction`, before any work: flags, scene, every path, outputs,
/// size.
pub fn prepare(a: Args) -> Result<Prepared> {
    let alphas = a.alpha.radians()?;
    let loads = a.load.newtons()?;
    let line = checks::line_deg(a.line_deg)?;
    let knobs = a.knobs.params()?;
    let mu_superlubric = a.verdict.mu_superlubric()?;
    let sc = a.scene.resolve(None)?;
    checks::line_for(&sc.scene, line)?;
    let thetas = (a.theta.radians()?).unwrap_or_else(|| vec![sc.scene.slider.theta]);
    let params = FrictionSweepParams {
        thetas,
        alphas,
        loads,
        line,
        knobs,
        mu_superlubric,
    };
    let run = a.sweep.run(
        Sweep {
            items: params.items(),
            rows_per_item: params.loads.len(),
            unit: "(θ, α)",
            schema: "friction",
        },
        a.out.as_deref(),
        &[],
    )?;
    check_outputs(&[("--out", a.out.as_deref())])?;
    if let Err(e) = check(&sc.scene, &params) {
        sc.log(&Reporter::stderr()); // the edge warning explains a refusal
        return Err(e);
    }
    let estimate = estimate(&sc.scene, &params).part(run.range().len(), params.items());
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
    // θ is swept: the recorded scene does not keep a θ of its own.
    let mut recorded = scene_file(&sc.scene);
    recorded.slider.theta_deg = None;
    let mut outs = Outputs::new(
        Inputs {
            workflow: "friction".into(),
            scene: Some(recorded),
            params: record::friction(&params, sc.scene.coating.p_crit),
        },
        sc.warnings.clone(),
    );
    let t0 = std::time::Instant::now();
    let stats = outs.stream_sweep("--out", a.out.as_deref(), &run, &rep, |items, csv| {
        friction(&sc.scene, &params, items, csv, &rep)
    })?;
    if let Some(s) = stats {
        crate::runs::progress::Progress::note(
            &rep,
            &format!(
                "friction: {} estimates in {:.2} s ({:.1} ms per (θ, α, W))",
                s.rows,
                t0.elapsed().as_secs_f64(),
                surrogate::units::s_to_ms(t0.elapsed().as_secs_f64()) / s.rows.max(1) as f64
            ),
        );
    }
    // the note only where it applies: some row's mount_resonance is true
    if let (Some(note), Some(s)) = (resonance_note(&sc.scene, &params.knobs), stats) {
        if s.resonant > 0 {
            crate::runs::progress::Progress::note(
                &rep,
                &format!(
                    "note: {note}; it applies to {} of {} rows",
                    s.resonant, s.rows
                ),
            );
        }
    }
    outs.finish()?;
    if let Some(s) = stats {
        if run.is_whole() && !run.resume && s.rows == run.rows() && s.failures == s.rows {
            bail!("no configuration has an estimate");
        }
    }
    Ok(())
}
