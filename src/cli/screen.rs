//! `superlube screen`: flags → [`crate::study::screen::screen`] → CSV (streamed) + sidecar.

use super::point_args::{self, Loads, Thetas, STUDY_THETAS};
use super::sweep_args::SweepArgs;
use super::SceneArgs;
use crate::runs::sink::csv_bytes;
use crate::runs::{
    meta::scene_file, meta::Inputs, output::check_outputs, output::Outputs, progress::Reporter,
    sweep::Sweep,
};
use crate::study::contacts::{contacts, ContactsParams};
use crate::study::record;
use crate::study::rows::ContactRow;
use crate::study::screen::{estimate, screen, ScreenParams};
use anyhow::{bail, Result};
use std::path::PathBuf;
use surrogate::solver::{Model, SearchKind};

/// Options of `superlube screen`. Without `--pattern` or `--scene` it screens the study's
/// square-on-triangle pair over θ = 0:30:0.1° at 0.35, 1.4, 2.1 and 3.86 mN.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// `--theta-deg`: θ, a list or range (degrees).
    #[command(flatten)]
    theta: Thetas,
    /// `--load-mn`: loads, a list or range (mN).
    #[command(flatten)]
    load: Loads,
    /// Output CSV file, streamed row by row (θ outer, load inner) through FILE.csv.partial and
    /// renamed when complete; a sidecar FILE.csv.meta.json records the scene, the parameters
    /// and the command line. Stdout if absent.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// Load-sharing model: auto (the cheapest model exact for the slider mount and the pose:
    /// rigid-z when the mount is locked or the contact moment of the rigid-z answer vanishes,
    /// e.g. a perfect lattice centred on a site; rigid-tilt with the mount's moment balance
    /// otherwise — σ_h > 0, an in-plane offset, the substrate edge; the `model` column says
    /// which), rigid-z (no tilt), rigid-tilt (tilts against the mount; refused for a locked
    /// mount) or compliant (also per-sphere vertical springs k_z = 1e6 N/m).
    #[arg(
        long = "solver",
        alias = "model",
        value_name = "SOLVER",
        default_value = "auto"
    )]
    model: String,
    /// Candidate pair search: grid (uniform bucket grid, fastest) or bvh (parry3d
    /// bounding-volume hierarchy). Both give identical pairs.
    #[arg(long, value_name = "SEARCH", default_value = "grid")]
    search: String,
    /// Also write the per-contact list of the configuration to this CSV (needs exactly one θ
    /// and one load): slider_index, substrate_index, contact point x/y/z in µm, overlap in nm,
    /// normal force in µN, p0 in GPa, failed.
    #[arg(long, value_name = "FILE.csv")]
    contacts_out: Option<PathBuf>,
    /// Run a sweep above the size limit (2·10⁶ solves) anyway; without it such a sweep is
    /// refused with its estimated time, memory and output size.
    #[arg(long)]
    force: bool,
    #[command(flatten)]
    sweep: SweepArgs,
}

/// A checked `superlube screen`, ready to run.
pub type Prepared = super::prepared::Prepared<Args, ScreenParams>;

/// Runs `superlube screen`.
pub fn run(a: Args) -> Result<()> {
    execute(prepare(a)?)
}

/// Every check of `superlube screen`, before any work: flags, scene, outputs, size.
pub fn prepare(a: Args) -> Result<Prepared> {
    let sc = a.scene.resolve(None)?;
    let thetas = match (a.theta.radians()?, a.scene.scene_file()?.slider.theta_deg) {
        (Some(t), _) => t,
        (None, Some(_)) => vec![sc.scene.slider.theta],
        (None, None) => point_args::thetas(STUDY_THETAS)?,
    };
    let params = ScreenParams {
        thetas,
        loads: a.load.newtons()?,
        model: Model::parse(&a.model).map_err(|e| anyhow::anyhow!("`--model`: {e}"))?,
        search: match a.search.as_str() {
            "grid" => SearchKind::Grid,
            "bvh" => SearchKind::Bvh,
            s => bail!("`--search`: unknown candidate search `{s}` (expected grid, bvh)"),
        },
    };
    if a.contacts_out.is_some() && (params.thetas.len() != 1 || params.loads.len() != 1) {
        bail!(
            "`--contacts-out` needs exactly one `--theta-deg` and one `--load-mn` value (got {} and {})",
            params.thetas.len(),
            params.loads.len()
        );
    }
    let run = a.sweep.run(
        Sweep {
            items: params.thetas.len(),
            rows_per_item: params.loads.len(),
            unit: "θ",
            schema: "screen",
        },
        a.out.as_deref(),
        &a.contacts_out
            .as_ref()
            .map_or(vec![], |_| vec!["--contacts-out"]),
    )?;
    check_outputs(&[
        ("--out", a.out.as_deref()),
        ("--contacts-out", a.contacts_out.as_deref()),
    ])?;
    let estimate = estimate(&sc.scene, &params).part(run.range().len(), params.thetas.len());
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
    // θ is swept: the recorded scene keeps the scene file's θ only if it is the sweep.
    let mut recorded = scene_file(&sc.scene);
    recorded.slider.theta_deg = None;
    let mut outs = Outputs::new(
        Inputs {
            workflow: "screen".into(),
            scene: Some(recorded),
            params: record::screen(&params),
        },
        sc.warnings.clone(),
    );
    let stats = outs.stream_sweep("--out", a.out.as_deref(), &run, &rep, |items, csv| {
        let part = ScreenParams {
            thetas: params.thetas[items].to_vec(),
            ..params.clone()
        };
        screen(&sc.scene, &part, csv, &rep)
    })?;
    if let Some(path) = &a.contacts_out {
        let cp = ContactsParams {
            theta: params.thetas[0],
            load: params.loads[0],
            model: params.model,
            search: params.search,
        };
        let mut scene = sc.scene.clone();
        scene.slider.theta = cp.theta;
        let rows = contacts(&scene, &cp).map(|eq| ContactRow::all(&eq));
        let n = rows.as_ref().map_or(None, |r| Some(r.len() as u64));
        let bytes = rows
            .map_err(|e| anyhow::anyhow!("no equilibrium to list: {e}"))
            .and_then(|r| csv_bytes(&r));
        outs.write("--contacts-out", Some(path), bytes, n);
    }
    outs.finish()?;
    // Only a run that computed every row of the sweep can say that none has an equilibrium.
    if let Some(stats) = stats {
        if run.is_whole() && stats.rows == run.rows() && stats.failures == stats.rows {
            bail!("no configuration has an equilibrium");
        }
    }
    Ok(())
}
