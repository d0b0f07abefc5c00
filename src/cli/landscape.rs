//! `superlube landscape`: equilibrium-height landscape Δz(x, y) over the substrate repeat cell.

use super::SceneArgs;
use crate::output::{csv_text, write_or_stdout};
use crate::plot::{contact_map, heat_map, ContactMapData, HeatMap};
use anyhow::{bail, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use std::path::{Path, PathBuf};
use surrogate::map::{compute_landscape, Landscape, MapParams};
use surrogate::solver::{Equilibrium, Model, Pose, Solver};
use surrogate::units::{deg_to_rad, m_to_nm, m_to_um, mn_to_n, n_to_mn, pa_to_gpa, rad_to_deg};

/// Options of `superlube landscape`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Slider rotation θ in degrees (relative to the substrate lattice).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    theta: f64,
    /// Normal load W in mN.
    #[arg(long = "load-mn", default_value_t = 1.4)]
    load_mn: f64,
    /// Grid points N per side of the repeat cell (N×N solves; both cell edges included).
    #[arg(long, default_value_t = 51)]
    grid: usize,
    /// CSV output `x_um,y_um,dz_nm` (shift of the slider centre from its default placement, and
    /// Δz = z − min z); stdout if omitted.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// Heat-map PNG of Δz over the cell.
    #[arg(long, value_name = "FILE.png")]
    plot: Option<PathBuf>,
    /// Also draw the contact map (contacts coloured by p0) at the default placement (zero shift).
    #[arg(long, value_name = "FILE.png")]
    contact_map: Option<PathBuf>,
}

/// One CSV row of a landscape.
#[derive(Serialize)]
struct Row {
    x_um: f64,
    y_um: f64,
    dz_nm: f64,
}

/// A progress bar on stderr with `len` steps and a message.
pub(crate) fn progress(len: u64, msg: &str) -> ProgressBar {
    let pb = ProgressBar::new(len);
    pb.set_style(
        ProgressStyle::with_template("{msg} [{elapsed_precise}] {bar:40} {pos}/{len} ({eta})")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    pb.set_message(msg.to_string());
    pb
}

/// Validates the common θ / load flags and converts them to SI (rad, N).
pub(crate) fn theta_load(theta_deg: f64, load_mn: f64) -> Result<(f64, f64)> {
    if !theta_deg.is_finite() {
        bail!("`--theta`: {theta_deg} is not a finite angle in degrees");
    }
    if !(load_mn.is_finite() && load_mn > 0.0) {
        bail!("`--load-mn`: {load_mn} must be a positive load in mN");
    }
    Ok((deg_to_rad(theta_deg), mn_to_n(load_mn)))
}

/// Computes a landscape with a progress bar.
pub(crate) fn landscape_with_progress(
    solver: &Solver,
    theta: f64,
    load: f64,
    grid: usize,
) -> Result<Landscape> {
    if grid < 2 {
        bail!("`--grid`: {grid} must be at least 2 (both cell edges are included)");
    }
    let params = MapParams {
        grid,
        ..MapParams::default()
    };
    let pb = progress((grid * grid) as u64, "landscape");
    let l = compute_landscape(solver, theta, load, &params, &|| pb.inc(1))?;
    pb.finish_and_clear();
    Ok(l)
}

/// CSV text `x_um,y_um,dz_nm` of a landscape (row-major, x fastest).
pub(crate) fn landscape_csv(l: &Landscape) -> Result<String> {
    let mut rows = Vec::with_capacity(l.n * l.n);
    for j in 0..l.n {
        for i in 0..l.n {
            let s = l.shift(i, j);
            rows.push(Row {
                x_um: crate::output::clean(m_to_um(s[0])),
                y_um: crate::output::clean(m_to_um(s[1])),
                dz_nm: m_to_nm(l.dz_at(i, j)),
            });
        }
    }
    csv_text(&rows)
}

/// Heat map of Δz (nm) over the cell, axes in µm.
pub(crate) fn landscape_png(path: &Path, l: &Landscape, pattern: &str) -> Result<()> {
    let d = (l.n - 1) as f64;
    let dz: Vec<f64> = (0..l.n * l.n)
        .map(|k| m_to_nm(l.dz_at(k % l.n, k / l.n)))
        .collect();
    let title = format!(
        "Δz landscape, {pattern}, θ = {}°, W = {} mN (range {:.3} nm)",
        fmt_num(rad_to_deg(l.theta)),
        fmt_num(n_to_mn(l.load)),
        m_to_nm(l.range())
    );
    heat_map(
        path,
        &HeatMap {
            title,
            x_label: "slider shift x (µm)".into(),
            y_label: "slider shift y (µm)".into(),
            value_label: "Δz = z − min z (nm)".into(),
            n: l.n,
            da: [m_to_um(l.cell.a[0]) / d, m_to_um(l.cell.a[1]) / d],
            db: [m_to_um(l.cell.b[0]) / d, m_to_um(l.cell.b[1]) / d],
            values: &dz,
        },
    )
}

/// Formats a number without trailing zeros (for titles and file names).
pub(crate) fn fmt_num(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// One CSV row of a contact map.
#[derive(Serialize)]
#[allow(non_snake_case)]
struct ContactRow {
    slider_index: u32,
    substrate_index: u32,
    x_um: f64,
    y_um: f64,
    overlap_nm: f64,
    force_mN: f64,
    p0_GPa: f64,
    failed: bool,
}

/// Solves the slider at rotation `theta` (rad), zero shift, load `load` (N), draws its contact
/// map to `png` and writes the contacts as CSV to `csv` (if given). Returns the equilibrium.
pub(crate) fn contact_map_files(
    solver: &Solver,
    theta: f64,
    load: f64,
    png: &Path,
    csv: Option<&Path>,
) -> Result<Equilibrium> {
    let scene = solver.scene();
    let pose = Pose {
        theta,
        shift: [0.0, 0.0],
    };
    let eq = solver.solve(pose, load, Model::Auto)?;
    let slider = scene.slider_sites_at(theta, pose.shift);
    let um = |p: [f64; 2]| [m_to_um(p[0]), m_to_um(p[1])];
    let data = ContactMapData {
        title: format!(
            "{}, θ = {}°, W = {} mN: {} contacts, P_max = {:.2} GPa, {} failed",
            scene.pattern,
            fmt_num(rad_to_deg(theta)),
            fmt_num(n_to_mn(load)),
            eq.contact_count(),
            pa_to_gpa(eq.p_max),
            eq.failed_count()
        ),
        sphere_radius_um: m_to_um(scene.sphere_radius),
        slider_um: slider.iter().map(|&p| um(p)).collect(),
        substrate_um: solver
            .substrate()
            .iter()
            .map(|p| um([p[0], p[1]]))
            .collect(),
        contacts: eq
            .contacts
            .iter()
            .map(|c| (um([c.point[0], c.point[1]]), pa_to_gpa(c.p0), c.failed))
            .collect(),
        p_crit_gpa: pa_to_gpa(scene.coating.p_crit),
    };
    contact_map(png, &data).with_context(|| format!("drawing {}", png.display()))?;
    if let Some(csv) = csv {
        let rows: Vec<ContactRow> = eq
            .contacts
            .iter()
            .map(|c| ContactRow {
                slider_index: c.slider,
                substrate_index: c.substrate,
                x_um: m_to_um(c.point[0]),
                y_um: m_to_um(c.point[1]),
                overlap_nm: m_to_nm(c.overlap),
                force_mN: n_to_mn(c.force_n),
                p0_GPa: pa_to_gpa(c.p0),
                failed: c.failed,
            })
            .collect();
        crate::output::write_atomic(csv, csv_text(&rows)?.as_bytes())?;
    }
    Ok(eq)
}

/// Runs `superlube landscape`.
pub fn run(args: Args) -> Result<()> {
    let scene = args.scene.scene()?;
    let (theta, load) = theta_load(args.theta, args.load_mn)?;
    if args.grid < 2 {
        bail!(
            "`--grid`: {} must be at least 2 (both cell edges are included)",
            args.grid
        );
    }
    let solver = Solver::new(&scene)?;
    let t0 = std::time::Instant::now();
    let l = landscape_with_progress(&solver, theta, load, args.grid)?;
    eprintln!(
        "landscape: {}x{} grid over the {} cell {:.4}x{:.4} µm, Δz range {:.4} nm, edge mismatch {:.2e} nm, {:.2} s",
        l.n,
        l.n,
        if l.cell.rectangular { "rectangular" } else { "primitive (oblique)" },
        m_to_um(l.cell.a[0].hypot(l.cell.a[1])),
        m_to_um(l.cell.b[0].hypot(l.cell.b[1])),
        m_to_nm(l.range()),
        m_to_nm(l.edge_mismatch()),
        t0.elapsed().as_secs_f64()
    );
    write_or_stdout(args.out.as_deref(), &landscape_csv(&l)?)?;
    if let Some(p) = &args.plot {
        landscape_png(p, &l, &scene.pattern)?;
    }
    if let Some(p) = &args.contact_map {
        contact_map_files(&solver, theta, load, p, None)?;
    }
    Ok(())
}
