//! `superlube landscape`: flags → [`crate::study::landscape::landscape`] → CSV (streamed),
//! heat map, contact map, each with its sidecar.

use super::{checks, SceneArgs};
use crate::plot::figures::{contact_map_png, landscape_png};
use crate::study::contacts::{contacts, ContactsParams};
use crate::study::landscape::{estimate, landscape, spill_path, LandscapeParams};
use crate::study::rows::{ContactRow, LandscapeRow};
use crate::study::sink::{csv_bytes, RowSink, Tee};
use crate::study::{check_outputs, meta::scene_file, record, Inputs, Outputs, Progress, Reporter};
use anyhow::Result;
use std::path::PathBuf;
use surrogate::solver::{Model, SearchKind};
use surrogate::units::{m_to_nm, m_to_um};

/// Options of `superlube landscape`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Slider rotation θ in degrees relative to the substrate lattice [default: the scene
    /// file's theta_deg, else 0].
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
    /// Grid points N per side of the repeat cell: N×N solves, both cell edges included (≥ 2).
    #[arg(long, value_name = "N", default_value_t = 51)]
    grid: usize,
    /// CSV output `x_um,y_um,dz_nm` (shift of the slider centre from its default placement in
    /// µm, and Δz = z − min z in nm), row-major with x fastest; streamed through
    /// FILE.csv.partial, with a sidecar FILE.csv.meta.json. Stdout if absent.
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
}

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
    let sc = a.scene.resolve(a.theta)?;
    let params = LandscapeParams {
        load: checks::load(a.load_mn)?,
        grid: checks::grid(a.grid)?,
    };
    check_outputs(&[
        ("--out", a.out.as_deref()),
        ("--plot", a.plot.as_deref()),
        ("--contact-map", a.contact_map.as_deref()),
        ("--contacts-out", a.contacts_out.as_deref()),
    ])?;
    estimate(&sc.scene, &params, a.plot.is_some()).check(a.force)?;
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
    // Δz is kept in memory only for the heat map.
    let mut dz = DzOnly(Vec::new());
    let keep = a.plot.is_some();
    let spill = a.out.as_deref().map(spill_path);
    let stats = outs.stream("--out", a.out.as_deref(), |csv| {
        if keep {
            landscape(
                &sc.scene,
                &params,
                spill.as_deref(),
                &mut Tee(csv, &mut dz),
                &rep,
            )
        } else {
            landscape(&sc.scene, &params, spill.as_deref(), csv, &rep)
        }
    })?;
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
