//! `superlube screen`: orientation × load screen of a pattern pair with the quasi-static
//! surrogate (contacts, P_max, height, coating failure), parallel over θ with rayon.

use super::{parse_list_or_range, SceneArgs};
use crate::output::{csv_text, write_or_stdout};
use anyhow::{bail, Context, Result};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;
use std::path::PathBuf;
use surrogate::solver::{Equilibrium, Model, Pose, SearchKind, Solver};
use surrogate::units::{deg_to_rad, m_to_nm, m_to_um, mn_to_n, pa_to_gpa};

/// The study's orientation sweep (degrees).
pub const DEFAULT_THETA: &str = "0:30:0.1";
/// The study's orientation-sweep loads (mN).
pub const DEFAULT_LOADS: &str = "0.35,1.4,2.1,3.86";

/// Options of `superlube screen`. Without `--pattern` or `--scene` it screens the study's
/// square-on-triangle pair over θ = 0:30:0.1° at 0.35, 1.4, 2.1 and 3.86 mN.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Slider orientations θ in degrees: a list `0,21.8,30` or an inclusive range
    /// `start:stop:step` [default: the scene file's theta_deg if set, else 0:30:0.1].
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    theta: Option<String>,
    /// Normal loads W in mN: a list `0.35,1.4` or a range `0.35:3.5:0.35` (each > 0).
    #[arg(long = "load-mn", value_name = "MN", default_value = DEFAULT_LOADS, allow_hyphen_values = true)]
    load_mn: String,
    /// Output CSV file (written atomically); stdout if absent.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// Load-sharing model: auto (rigid-z on flat substrates, rigid-tilt with σ_h > 0),
    /// rigid-z, rigid-tilt or compliant (per-sphere vertical springs k_z = 1e6 N/m).
    #[arg(long, default_value = "auto")]
    model: String,
    /// Candidate search: grid (uniform bucket grid, fastest) or bvh (parry3d bounding-volume
    /// hierarchy). Both give identical pairs.
    #[arg(long, default_value = "grid")]
    search: String,
    /// Also write the per-contact list of the configuration to this CSV (requires exactly one
    /// θ and one load): slider_index, substrate_index, contact point x/y/z in µm, overlap in
    /// nm, force in µN, p0 in GPa, failed.
    #[arg(long, value_name = "FILE.csv")]
    contacts_out: Option<PathBuf>,
}

/// One screen row (CSV). The leading seven columns are fixed by the issue; units in the names.
#[derive(Debug, Serialize)]
#[allow(non_snake_case)]
pub struct Row {
    /// Pattern pair name.
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Normal load W (mN).
    pub load_mN: f64,
    /// Contact number (pairs with overlap > 0).
    pub contacts: Option<usize>,
    /// Largest Hertz pressure p0 (GPa).
    pub p_max_GPa: Option<f64>,
    /// Slider sphere-centre plane height at the disc centre (µm), 3 µm at first on-top touch.
    pub z_um: Option<f64>,
    /// Whether P_max exceeds P_crit.
    pub coating_failed: Option<bool>,
    /// Number of contacts with p0 > P_crit.
    pub failed_contacts: Option<usize>,
    /// Tilt about x (µrad).
    pub tilt_x_urad: Option<f64>,
    /// Tilt about y (µrad).
    pub tilt_y_urad: Option<f64>,
    /// Model used.
    pub model: String,
    /// |ΣF_z − W| / W.
    pub residual_rel: Option<f64>,
    /// Solver iterations.
    pub iterations: Option<usize>,
    /// Empty, or why this configuration has no equilibrium.
    pub error: String,
}

#[derive(Debug, Serialize)]
#[allow(non_snake_case)]
struct ContactRow {
    slider_index: u32,
    substrate_index: u32,
    x_um: f64,
    y_um: f64,
    z_um: f64,
    overlap_nm: f64,
    force_uN: f64,
    p0_GPa: f64,
    failed: bool,
}

fn row(
    pattern: &str,
    theta_deg: f64,
    load_mn: f64,
    r: &Result<Equilibrium, surrogate::SceneError>,
    model: Model,
) -> Row {
    match r {
        Ok(e) => Row {
            pattern: pattern.to_string(),
            theta_deg,
            load_mN: load_mn,
            contacts: Some(e.contact_count()),
            p_max_GPa: Some(pa_to_gpa(e.p_max)),
            z_um: Some(m_to_um(e.z)),
            coating_failed: Some(e.coating_failed()),
            failed_contacts: Some(e.failed_count()),
            tilt_x_urad: Some(e.tilt[0] * 1e6),
            tilt_y_urad: Some(e.tilt[1] * 1e6),
            model: e.model.name().to_string(),
            residual_rel: Some(e.residual_rel()),
            iterations: Some(e.iterations),
            error: String::new(),
        },
        Err(err) => Row {
            pattern: pattern.to_string(),
            theta_deg,
            load_mN: load_mn,
            contacts: None,
            p_max_GPa: None,
            z_um: None,
            coating_failed: None,
            failed_contacts: None,
            tilt_x_urad: None,
            tilt_y_urad: None,
            model: model.name().to_string(),
            residual_rel: None,
            iterations: None,
            error: err.to_string(),
        },
    }
}

/// Parses and checks `--load-mn` (every value finite and > 0).
fn loads_mn(text: &str) -> Result<Vec<f64>> {
    let v = parse_list_or_range(text, "--load-mn")?;
    for &w in &v {
        if !(w.is_finite() && w > 0.0) {
            bail!("`--load-mn`: load {w} mN must be a positive number");
        }
    }
    Ok(v)
}

/// Runs `superlube screen`.
pub fn run(args: Args) -> Result<()> {
    let file = args.scene.scene_file()?;
    let scene = args.scene.scene()?;
    let thetas = match (&args.theta, file.slider.theta_deg) {
        (Some(t), _) => parse_list_or_range(t, "--theta")?,
        (None, Some(t)) => vec![t],
        (None, None) => parse_list_or_range(DEFAULT_THETA, "--theta")?,
    };
    let loads = loads_mn(&args.load_mn)?;
    let model = Model::parse(&args.model).context("`--model`")?;
    let mut solver = Solver::new(&scene)?;
    solver.search = match args.search.as_str() {
        "grid" => SearchKind::Grid,
        "bvh" => SearchKind::Bvh,
        s => bail!("`--search`: unknown candidate search `{s}` (expected grid, bvh)"),
    };
    if args.contacts_out.is_some() && (thetas.len() != 1 || loads.len() != 1) {
        bail!(
            "`--contacts-out` needs exactly one `--theta` and one `--load-mn` value (got {} and {})",
            thetas.len(),
            loads.len()
        );
    }
    let loads_n: Vec<f64> = loads.iter().map(|&w| mn_to_n(w)).collect();
    let pb = ProgressBar::with_draw_target(Some(thetas.len() as u64), ProgressDrawTarget::stderr());
    pb.set_style(
        ProgressStyle::with_template("screen {bar:40} {pos}/{len} θ [{elapsed_precise}]")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let per_theta: Vec<Vec<Result<Equilibrium, surrogate::SceneError>>> = thetas
        .par_iter()
        .map(|&t| {
            let pose = Pose {
                theta: deg_to_rad(t),
                shift: [0.0, 0.0],
            };
            let r = solver.solve_loads(pose, &loads_n, model);
            pb.inc(1);
            r
        })
        .collect();
    pb.finish_and_clear();
    let mut rows = Vec::with_capacity(thetas.len() * loads.len());
    let mut failures = 0;
    for (t, rs) in thetas.iter().zip(&per_theta) {
        for (w, r) in loads.iter().zip(rs) {
            failures += r.is_err() as usize;
            // Ranges are computed as start + k·step: round off the binary noise (1e-9 deg, mN).
            let clean = crate::output::clean;
            rows.push(row(&scene.pattern, clean(*t), clean(*w), r, model));
        }
    }
    if let Some(path) = &args.contacts_out {
        match &per_theta[0][0] {
            Ok(eq) => {
                let crow: Vec<ContactRow> = eq
                    .contacts
                    .iter()
                    .map(|c| ContactRow {
                        slider_index: c.slider,
                        substrate_index: c.substrate,
                        x_um: m_to_um(c.point[0]),
                        y_um: m_to_um(c.point[1]),
                        z_um: m_to_um(c.point[2]),
                        overlap_nm: m_to_nm(c.overlap),
                        force_uN: c.force_n / surrogate::units::UN,
                        p0_GPa: pa_to_gpa(c.p0),
                        failed: c.failed,
                    })
                    .collect();
                write_or_stdout(Some(path), &csv_text(&crow)?)?;
            }
            Err(e) => bail!("`--contacts-out`: no equilibrium to list: {e}"),
        }
    }
    write_or_stdout(args.out.as_deref(), &csv_text(&rows)?)?;
    if failures > 0 {
        eprintln!(
            "warning: {failures} of {} configurations have no equilibrium (see the `error` column)",
            rows.len()
        );
        if failures == rows.len() {
            bail!("no configuration has an equilibrium");
        }
    }
    Ok(())
}
