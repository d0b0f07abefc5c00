//! `superlube export-lammps`: the Tier 3 (DEM) model of one (θ, α, W) as a LAMMPS data file and input
//! deck (engine: `dem::export`), to run with MPI LAMMPS on a cluster.

use super::checks::{line_deg as check_line_deg, non_negative, positive};
use super::point_args::{help, Alpha, Load, Theta, LOAD};
use super::protocol_args::ProtocolArgs;
use super::SceneArgs;
use anyhow::{bail, Context, Result};
use dem::export::{export_lammps, files, ExportOptions};
use dem::SimParams;
use std::path::PathBuf;
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::units::{deg_to_rad, mn_to_n, us_to_s};

/// Options of `superlube export-lammps`.
#[derive(clap::Args, Debug)]
#[command(mut_args(help(LOAD, "Normal load W in mN, applied to the control layer")))]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// `--theta-deg`: one θ (degrees).
    #[command(flatten)]
    theta: Theta,
    /// `--load-mn`: one load (mN).
    #[command(flatten)]
    load: Load,
    /// `--alpha-deg`: one α (degrees).
    #[command(flatten)]
    alpha: Alpha,
    /// Contact-line angle in degrees from the substrate x axis [default: the moiré estimate].
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    line_deg: Option<f64>,
    /// Equilibration time under load in µs.
    #[arg(
        long = "equilibrate-us",
        value_name = "US",
        default_value_t = 10.0,
        allow_hyphen_values = true
    )]
    equilibrate_us: f64,
    #[command(flatten)]
    protocol: ProtocolArgs,
    /// Time step in µs [default: 0.25 × the Rust engine's stable-step estimate, as `slide`].
    #[arg(long = "dt-us", value_name = "US", allow_hyphen_values = true)]
    dt_us: Option<f64>,
    /// Time-series interval in µs.
    #[arg(
        long = "sample-us",
        value_name = "US",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    sample_us: f64,
    /// Contact-dump interval in µs (for `superlube lammps-check`); 0 = no dump.
    #[arg(
        long = "dump-us",
        value_name = "US",
        default_value_t = 1.0,
        allow_hyphen_values = true
    )]
    dump_us: f64,
    /// Constant friction coefficient of every contact [default: the coating's μ1]. LAMMPS cannot
    /// switch μ at P_crit; `superlube lammps-check` shows where that matters.
    #[arg(long, value_name = "MU", allow_hyphen_values = true)]
    mu: Option<f64>,
    /// Leave out substrate spheres the slider can never touch along its path (as `slide --prune`).
    #[arg(long)]
    prune: bool,
    /// Output directory (created if missing): scene.data, in.superlube.lmp, README.md, export.json.
    #[arg(long = "out-dir", alias = "out", value_name = "DIR")]
    out: PathBuf,
}

/// Runs `superlube export-lammps`.
pub fn run(a: Args) -> Result<()> {
    if a.out.exists() && !a.out.is_dir() {
        bail!(
            "`--out-dir`: {} exists and is not a directory",
            a.out.display()
        );
    }
    positive(a.load.mn, "--load-mn")?;
    positive(a.equilibrate_us, "--equilibrate-us")?;
    a.protocol.check(false)?;
    positive(a.sample_us, "--sample-us")?;
    non_negative(a.dump_us, "--dump-us")?;
    if let Some(dt) = a.dt_us {
        positive(dt, "--dt-us")?;
    }
    if let Some(mu) = a.mu {
        non_negative(mu, "--mu")?;
    }
    let alpha = a.alpha.radians()?;
    let line_given = check_line_deg(a.line_deg)?;
    let file = a.scene.scene_file()?;
    let mut scene = file.into_scene()?;
    let theta = match a.theta.checked()? {
        Some(t) => t,
        None => file.slider.theta_deg.unwrap_or(0.0),
    };
    scene.slider.theta = deg_to_rad(theta);
    scene.validate()?;
    super::checks::line_for(&scene, line_given)?;
    if let Some(w) = scene.edge_warning() {
        eprintln!("warning: {w}");
    }
    let line = match line_given {
        Some(l) => l,
        None => contact_line_direction(&scene, scene.slider.theta, &MapParams::default()).angle,
    };
    let params = sim_params(&a, line + alpha);
    let opts = ExportOptions {
        mu: a.mu.unwrap_or(scene.coating.mu1),
        dump_interval: us_to_s(a.dump_us),
        command: std::env::args().collect::<Vec<_>>().join(" "),
        alpha_and_line: Some((alpha, line)),
        ..ExportOptions::default()
    };
    // Make sure the output directory can be made before the work; remove it again (if this run
    // made it and it is still empty) when the export fails.
    let created = !a.out.exists();
    std::fs::create_dir_all(&a.out).with_context(|| {
        format!(
            "`--out-dir`: cannot create the directory {}",
            a.out.display()
        )
    })?;
    let ex = match export_lammps(&scene, &params, &opts) {
        Ok(ex) => ex,
        Err(e) => {
            if created {
                let _ = std::fs::remove_dir(&a.out);
            }
            return Err(e.into());
        }
    };
    ex.write(&a.out)
        .with_context(|| format!("`--out-dir`: writing into {}", a.out.display()))?;
    let m = &ex.meta;
    eprintln!(
        "export-lammps: {} LAMMPS atoms, dt = {:.4e} µs, {} steps (equilibrate {}, relax {}, slide {}), constant μ = {} → {}",
        m.atoms,
        m.dt_us,
        m.steps.total(),
        m.steps.equilibrate,
        m.steps.relax,
        m.steps.slide,
        m.mu,
        a.out.display()
    );
    eprintln!(
        "run: cd {} && lmp -in {} (MPI: mpirun -np N lmp -in {}); check the deck: lmp -in {} -var nsteps 0",
        a.out.display(),
        files::DECK,
        files::DECK,
        files::DECK
    );
    Ok(())
}

/// The exported run's knobs from the flags (checked by the caller), pulling `direction` (rad
/// from x): the study's defaults but the load, the protocol, dt, the sample interval, `--prune`.
fn sim_params(a: &Args, direction: f64) -> SimParams {
    let mut params = SimParams {
        protocol: dem::ProtocolParams {
            load: mn_to_n(a.load.mn),
            alpha: direction,
            equilibrate_time: us_to_s(a.equilibrate_us),
            sample_interval: us_to_s(a.sample_us),
            ..Default::default()
        },
        numerics: dem::NumericsParams {
            dt: a.dt_us.map(us_to_s),
            ..Default::default()
        },
        active: dem::ActiveSetParams {
            prune_substrate: a.prune,
            ..Default::default()
        },
        ..SimParams::default()
    };
    a.protocol.apply(&mut params.protocol);
    params
}
