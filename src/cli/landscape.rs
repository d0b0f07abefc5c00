//! `superlube landscape`: flags → [`crate::study::landscape::landscape`] → CSV (streamed),
//! heat map, contact map, each with its sidecar.

use super::point_args::{help, Load, Theta, THETA};
use super::scene_args::Resolved;
use super::sweep_args::SweepArgs;
use super::{checks, SceneArgs};
use crate::plot::figures::{contact_map_png, landscape_png};
use crate::runs::meta::sidecar_path;
use crate::runs::resume::is_complete;
use crate::runs::sink::{csv_bytes, RowSink, Tee};
use crate::runs::{
    meta::scene_file, meta::Inputs, output::check_outputs, output::Outputs, output::SweepRun,
    progress::Progress, progress::Reporter, shard::Shard,
};
use crate::study::contacts::{contacts, ContactsParams};
use crate::study::landscape::{
    self as workflow, estimate, finish, heights, landscape, spill_path, LandscapeParams,
    LandscapeStats,
};
use crate::study::record;
use crate::study::rows::{ContactRow, LandscapeRow};
use anyhow::Result;
use std::path::{Path, PathBuf};
use surrogate::solver::{Model, SearchKind};
use surrogate::units::{m_to_nm, m_to_um};

/// Options of `superlube landscape`.
#[derive(clap::Args, Debug)]
#[command(mut_args(help(
    THETA,
    "Slider rotation θ in degrees relative to the substrate lattice [default: the scene \
     file's theta_deg, else 0]"
)))]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// `--theta-deg`: one θ (degrees).
    #[command(flatten)]
    theta: Theta,
    /// `--load-mn`: one load (mN).
    #[command(flatten)]
    load: Load,
    /// Grid points N per side of the repeat cell: N×N solves, both cell edges included (≥ 2).
    #[arg(long, value_name = "N", default_value_t = 51)]
    grid: usize,
    /// CSV output `x_um,y_um,dz_nm` (shift of the slider centre from its default placement in
    /// µm, and Δz = z − min z in nm), row-major with x fastest; streamed through
    /// FILE.csv.partial, with a sidecar FILE.csv.meta.json. Stdout if absent. The heights are
    /// kept in FILE.csv.z until Δz can be computed. With `--shard`: that shard's rows
    /// `x_um,y_um,z_um` (the exact height z in µm), which `superlube merge` turns into Δz.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// Heat-map PNG of Δz (nm) over the cell (axes in µm).
    #[arg(long, value_name = "FILE.png")]
    plot: Option<PathBuf>,
    /// Also draw the contact map (contacts coloured by p0 in GPa) at the default placement
    /// (zero shift).
    #[arg(long, value_name = "FILE.png")]
    contact_map: Option<PathBuf>,
    /// Also write the per-contact list at the default placement (the contact-map data; same
    /// columns as `screen --contacts-out`).
    #[arg(long, value_name = "FILE.csv")]
    contacts_out: Option<PathBuf>,
    /// Run a grid above the size limit (2·10⁶ solves) anyway; without it such a grid is refused
    /// with its estimated time, memory and output size.
    #[arg(long)]
    force: bool,
    #[command(flatten)]
    sweep: SweepArgs,
}

/// A checked `superlube landscape`, ready to run.
pub type Prepared = super::prepared::Prepared<Args, LandscapeParams>;

/// Keeps only Δz (nm) of each row, for the heat map.
struct DzOnly(Vec<f64>);

impl RowSink<LandscapeRow> for DzOnly {
    fn push(&mut self, r: &LandscapeRow) -> Result<()> {
        self.0.push(r.dz_nm);
        Ok(())
    }
}

/// Runs `superlube landscape`.
pub fn run(a: Args) -> Result<()> {
    execute(prepare(a)?)
}

/// Every check of `superlube landscape`, before any work: flags, scene, outputs, size.
pub fn prepare(a: Args) -> Result<Prepared> {
    let mut sc = a.scene.resolve(a.theta.deg)?;
    let params = LandscapeParams {
        load: a.load.newtons()?,
        grid: checks::grid(a.grid)?,
    };
    sc.warnings
        .extend(checks::grid_warning(&sc.scene, params.grid));
    let extras: Vec<&str> = [
        ("--plot", a.plot.is_some()),
        ("--contact-map", a.contact_map.is_some()),
        ("--contacts-out", a.contacts_out.is_some()),
    ]
    .iter()
    .filter(|(_, given)| *given)
    .map(|(flag, _)| *flag)
    .collect();
    let run = a
        .sweep
        .run(workflow::sweep(&params), a.out.as_deref(), &extras)?;
    check_outputs(&[
        ("--out", a.out.as_deref()),
        ("--plot", a.plot.as_deref()),
        ("--contact-map", a.contact_map.as_deref()),
        ("--contacts-out", a.contacts_out.as_deref()),
    ])?;
    let estimate =
        estimate(&sc.scene, &params, a.plot.is_some()).part(run.range().len(), run.sweep.items);
    estimate.check(a.force)?;
    Ok(Prepared {
        a,
        sc,
        params,
        run,
        estimate,
    })
}

/// The heights of the whole grid into the spill file `OUT.z` (resumable: `--resume` continues
/// `OUT.z.partial`, or skips the pass when `OUT.z` is complete), then Δz into `OUT`.
fn whole_to_file(
    outs: &mut Outputs,
    out: &Path,
    sc: &Resolved,
    params: &LandscapeParams,
    resume: bool,
    rows: &mut dyn RowSink<LandscapeRow>,
    rep: &Reporter,
) -> Result<LandscapeStats> {
    let z = spill_path(out);
    let zrun = SweepRun::new(workflow::sweep(params), Some(Shard::ALL), resume)?;
    if resume && is_complete(&z, outs.inputs(), zrun.shard.as_ref(), zrun.rows()) {
        rep.note(&format!(
            "resuming: the heights in {} are complete; computing Δz",
            z.display()
        ));
    } else {
        outs.stream_sweep("--out", Some(&z), &zrun, rep, |items, csv| {
            heights(&sc.scene, params, items, csv, rep)
        })?;
    }
    let h = outs.stream("--out", Some(out), |csv| {
        finish(params.grid, std::slice::from_ref(&z), &mut Tee(csv, rows))
    })?;
    let _ = std::fs::remove_file(&z);
    let _ = std::fs::remove_file(sidecar_path(&z));
    Ok(workflow::stats(workflow::cell(&sc.scene), &h))
}

/// A sink that drops every row.
struct Discard;

impl RowSink<LandscapeRow> for Discard {
    fn push(&mut self, _: &LandscapeRow) -> Result<()> {
        Ok(())
    }
}

fn execute(p: Prepared) -> Result<()> {
    let Prepared {
        a, sc, params, run, ..
    } = p;
    let rep = Reporter::stderr();
    sc.log(&rep);
    let mut outs = Outputs::new(
        Inputs {
            workflow: "landscape".into(),
            scene: Some(scene_file(&sc.scene)),
            params: record::landscape(&params),
        },
        sc.warnings.clone(),
    );
    let t0 = std::time::Instant::now();
    if let (Some(shard), Some(out)) = (&run.shard, a.out.as_deref()) {
        // A shard: its block of heights, merged into Δz by `superlube merge`.
        outs.stream_sweep("--out", Some(out), &run, &rep, |items, csv| {
            heights(&sc.scene, &params, items, csv, &rep)
        })?;
        rep.note(&format!(
            "landscape shard {}: grid points {}..{} of {} (heights z; `superlube merge` of all {} shards writes Δz), {:.2} s",
            shard.label(),
            shard.item_range[0],
            shard.item_range[1],
            shard.items,
            shard.count,
            t0.elapsed().as_secs_f64()
        ));
        return outs.finish();
    }
    // Δz is kept in memory only for the heat map.
    let mut dz = DzOnly(Vec::new());
    let mut none = Discard;
    let keep: &mut dyn RowSink<LandscapeRow> = if a.plot.is_some() { &mut dz } else { &mut none };
    let stats = match a.out.as_deref() {
        Some(out) if std::fs::metadata(out).map_or(true, |m| m.is_file()) => {
            whole_to_file(&mut outs, out, &sc, &params, run.resume, keep, &rep)?
        }
        out => outs.stream("--out", out, |csv| {
            landscape(&sc.scene, &params, None, &mut Tee(csv, keep), &rep)
        })?,
    };
    let c = &stats.cell;
    rep.note(&format!(
        "landscape: {}x{} grid over the {} cell {:.4}x{:.4} µm, Δz range {:.4} nm, edge mismatch {:.2e} nm, {:.2} s",
        stats.n,
        stats.n,
        if c.rectangular { "rectangular" } else { "primitive (oblique)" },
        m_to_um(c.a[0].hypot(c.a[1])),
        m_to_um(c.b[0].hypot(c.b[1])),
        m_to_nm(stats.range),
        m_to_nm(stats.edge_mismatch),
        t0.elapsed().as_secs_f64()
    ));
    if let Some(p) = &a.plot {
        outs.attempt("--plot", p, || {
            landscape_png(p, &sc.scene, params.load, &stats, &dz.0)
        });
    }
    if a.contact_map.is_some() || a.contacts_out.is_some() {
        let cp = ContactsParams {
            theta: sc.scene.slider.theta,
            load: params.load,
            model: Model::Auto,
            search: SearchKind::Grid,
        };
        match contacts(&sc.scene, &cp) {
            Ok(eq) => {
                if let Some(p) = &a.contact_map {
                    outs.attempt("--contact-map", p, || {
                        contact_map_png(p, &sc.scene, params.load, &eq)
                    });
                }
                if let Some(p) = &a.contacts_out {
                    let rows = ContactRow::all(&eq);
                    outs.write(
                        "--contacts-out",
                        Some(p),
                        csv_bytes(&rows),
                        Some(rows.len() as u64),
                    );
                }
            }
            Err(e) => {
                for (flag, p) in [
                    ("--contact-map", &a.contact_map),
                    ("--contacts-out", &a.contacts_out),
                ] {
                    if p.is_some() {
                        outs.fail(flag, p.as_deref(), anyhow::anyhow!("{e:#}"));
                    }
                }
            }
        }
    }
    outs.finish()
}
