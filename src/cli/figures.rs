//! `superlube figures`: regenerates the screening study's figures (PNG) and the data behind each
//! (CSV next to it) into an output directory.

use super::corrugation::{parse_alphas, path_params};
use super::landscape::{
    contact_map_files, fmt_num, landscape_csv, landscape_png, landscape_with_progress, progress,
};
use crate::output::{csv_text, write_atomic};
use crate::plot::{stacked_line_plots, LinePlot, Series};
use anyhow::{bail, Result};
use rayon::prelude::*;
use serde::Serialize;
use std::path::{Path, PathBuf};
use surrogate::map::{contact_line_direction, corrugation_direct, corrugation_from_landscape};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::units::{deg_to_rad, m_to_nm, m_to_um, mn_to_n, n_to_mn, pa_to_gpa};
use surrogate::Scene;

/// Loads of the orientation sweeps (mN).
const SWEEP_LOADS_MN: [f64; 4] = [0.35, 1.4, 2.1, 3.86];
/// Contact-map configurations (pattern, θ in degrees) at 1.4 mN.
const CONTACT_MAPS: [(&str, f64); 6] = [
    ("tri-tri", 0.0),
    ("tri-tri", 21.8),
    ("tri-tri", 30.0),
    ("square-tri", 0.0),
    ("square-tri", 10.2),
    ("square-tri", 15.0),
];

/// Which figure groups to make.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    /// Contacts and P_max versus θ (tri-tri, square-tri).
    Sweep,
    /// Contact maps at 1.4 mN.
    Contacts,
    /// Δz landscapes of square-tri at 0° and 10.2°.
    Landscapes,
    /// Corrugation versus α for square-tri.
    Corrugation,
}

/// How the corrugation figure's heights are computed.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CorrMethod {
    /// Solver call at every path sample.
    Direct,
    /// Interpolated landscape (fast).
    Landscape,
}

/// Options of `superlube figures`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Output directory for the PNGs and the CSVs behind them.
    #[arg(long = "out-dir", default_value = "figures")]
    out_dir: PathBuf,
    /// θ step in degrees of the orientation sweeps (0 to 30°; study: 0.1).
    #[arg(long = "theta-step", default_value_t = 0.1)]
    theta_step: f64,
    /// Pulling angles α in degrees of the corrugation figure (list or start:stop:step).
    #[arg(long, default_value = "-90:90:2", allow_hyphen_values = true)]
    alpha: String,
    /// Sliding distance of each corrugation path in µm.
    #[arg(long = "distance-um", default_value_t = 30.0)]
    distance_um: f64,
    /// Sampling step along corrugation paths in µm.
    #[arg(long = "step-um", default_value_t = 0.05)]
    step_um: f64,
    /// How the corrugation figure's heights are computed.
    #[arg(long = "corrugation-method", value_enum, default_value_t = CorrMethod::Direct)]
    corrugation_method: CorrMethod,
    /// Landscape grid points per side.
    #[arg(long, default_value_t = 51)]
    grid: usize,
    /// Only these figure groups (comma-separated); all if omitted.
    #[arg(long, value_enum, value_delimiter = ',')]
    only: Vec<Group>,
}

#[derive(Serialize)]
struct SweepRow {
    pattern: String,
    theta_deg: f64,
    #[serde(rename = "load_mN")]
    load_mn: f64,
    contacts: usize,
    failed_contacts: usize,
    #[serde(rename = "p_max_GPa")]
    p_max_gpa: f64,
    z_um: f64,
}

#[derive(Serialize)]
struct CorrRow {
    theta_deg: f64,
    #[serde(rename = "load_mN")]
    load_mn: f64,
    line_deg: f64,
    alpha_deg: f64,
    direction_deg: f64,
    corrugation_nm: f64,
    #[serde(rename = "max_lateral_force_mN")]
    max_lateral_force_mn: f64,
}

fn sweep(out: &Path, pattern: &str, theta_step: f64) -> Result<()> {
    let scene = Scene::preset(pattern)?;
    let solver = Solver::new(&scene)?;
    let thetas = super::parse_list_or_range(&format!("0:30:{theta_step}"), "--theta-step")?;
    let jobs: Vec<(f64, f64)> = thetas
        .iter()
        .flat_map(|&t| SWEEP_LOADS_MN.iter().map(move |&w| (t, w)))
        .collect();
    let pb = progress(jobs.len() as u64, &format!("sweep {pattern}"));
    let rows: Result<Vec<SweepRow>> = jobs
        .par_iter()
        .map(|&(t, w)| {
            let eq = solver.solve(
                Pose {
                    theta: deg_to_rad(t),
                    shift: [0.0, 0.0],
                },
                mn_to_n(w),
                Model::Auto,
            )?;
            pb.inc(1);
            Ok(SweepRow {
                pattern: pattern.into(),
                theta_deg: t,
                load_mn: w,
                contacts: eq.contact_count(),
                failed_contacts: eq.failed_count(),
                p_max_gpa: pa_to_gpa(eq.p_max),
                z_um: m_to_um(eq.z),
            })
        })
        .collect();
    pb.finish_and_clear();
    let rows = rows?;
    let base = out.join(format!("sweep_{pattern}"));
    write_atomic(&with_ext(&base, "csv"), csv_text(&rows)?.as_bytes())?;
    let series = |f: &dyn Fn(&SweepRow) -> f64| -> Vec<Series> {
        SWEEP_LOADS_MN
            .iter()
            .map(|&w| Series {
                name: format!("W = {} mN", fmt_num(w)),
                points: rows
                    .iter()
                    .filter(|r| r.load_mn == w)
                    .map(|r| (r.theta_deg, f(r)))
                    .collect(),
            })
            .collect()
    };
    let contacts = LinePlot {
        title: format!("{pattern}: contact number versus orientation θ"),
        x_label: "slider rotation θ (°)".into(),
        y_label: "contacts (log scale)".into(),
        series: series(&|r| r.contacts as f64),
        hlines: vec![],
        log_y: true,
    };
    let pmax = LinePlot {
        title: format!("{pattern}: maximum Hertz pressure versus θ"),
        x_label: "slider rotation θ (°)".into(),
        y_label: "P_max (GPa)".into(),
        series: series(&|r| r.p_max_gpa),
        hlines: vec![(
            pa_to_gpa(scene.coating.p_crit),
            "P_crit (coating fails above)".into(),
        )],
        log_y: false,
    };
    stacked_line_plots(&with_ext(&base, "png"), (1100, 1150), &[&contacts, &pmax])
}

fn corrugation(
    out: &Path,
    alphas_text: &str,
    distance_um: f64,
    step_um: f64,
    grid: usize,
    method: CorrMethod,
) -> Result<()> {
    let scene = Scene::preset("square-tri")?;
    let solver = Solver::new(&scene)?;
    let alphas = parse_alphas(alphas_text)?;
    let params = path_params(distance_um, step_um, grid)?;
    let mut rows = Vec::new();
    let mut corr = Vec::new();
    let mut force = Vec::new();
    for theta_deg in [0.0, 10.2, 12.4] {
        for load_mn in [0.35, 1.4] {
            let theta = deg_to_rad(theta_deg);
            let load = mn_to_n(load_mn);
            let line = contact_line_direction(&scene, theta, &params);
            let pts = match method {
                CorrMethod::Direct => {
                    let per = (params.distance / params.step - 1e-9).ceil().max(1.0) as u64 + 1;
                    let pb = progress(
                        per * alphas.len() as u64,
                        &format!("corrugation θ={theta_deg}° W={load_mn} mN"),
                    );
                    let r = corrugation_direct(
                        &solver,
                        theta,
                        load,
                        line.angle,
                        &alphas,
                        &params,
                        &|| pb.inc(1),
                    )?;
                    pb.finish_and_clear();
                    r
                }
                CorrMethod::Landscape => {
                    let l = landscape_with_progress(&solver, theta, load, grid)?;
                    corrugation_from_landscape(&l, line.angle, &alphas, &params)?
                }
            };
            let name = format!("θ = {}°, W = {} mN", fmt_num(theta_deg), fmt_num(load_mn));
            corr.push(Series {
                name: name.clone(),
                points: pts
                    .iter()
                    .map(|p| (p.alpha.to_degrees(), m_to_nm(p.corrugation)))
                    .collect(),
            });
            force.push(Series {
                name,
                points: pts
                    .iter()
                    .map(|p| (p.alpha.to_degrees(), n_to_mn(p.max_lateral_force) * 1e3))
                    .collect(),
            });
            for p in &pts {
                rows.push(CorrRow {
                    theta_deg,
                    load_mn,
                    line_deg: line.angle.to_degrees(),
                    alpha_deg: crate::output::clean(p.alpha.to_degrees()),
                    direction_deg: crate::output::clean(p.direction.to_degrees()),
                    corrugation_nm: m_to_nm(p.corrugation),
                    max_lateral_force_mn: n_to_mn(p.max_lateral_force),
                });
            }
        }
    }
    let base = out.join("corrugation_square-tri");
    write_atomic(&with_ext(&base, "csv"), csv_text(&rows)?.as_bytes())?;
    let c = LinePlot {
        title: format!(
            "square-tri: corrugation along pulling angle α ({} µm paths)",
            fmt_num(distance_um)
        ),
        x_label: "pulling angle α from the contact line (°)".into(),
        y_label: "corrugation, peak-to-peak z (nm)".into(),
        series: corr,
        hlines: vec![],
        log_y: false,
    };
    let f = LinePlot {
        title: "square-tri: static-friction barrier along α".into(),
        x_label: "pulling angle α from the contact line (°)".into(),
        y_label: "max lateral force (µN)".into(),
        series: force,
        hlines: vec![],
        log_y: false,
    };
    stacked_line_plots(&with_ext(&base, "png"), (1100, 1150), &[&c, &f])
}

/// Runs `superlube figures`.
pub fn run(args: Args) -> Result<()> {
    if !(args.theta_step.is_finite() && args.theta_step > 0.0 && args.theta_step <= 30.0) {
        bail!(
            "`--theta-step`: {} must be in (0, 30] degrees",
            args.theta_step
        );
    }
    parse_alphas(&args.alpha)?;
    path_params(args.distance_um, args.step_um, args.grid)?;
    if args.grid < 2 {
        bail!("`--grid`: {} must be at least 2", args.grid);
    }
    let all = args.only.is_empty();
    let want = |g: Group| all || args.only.contains(&g);
    let out = &args.out_dir;
    let t0 = std::time::Instant::now();
    if want(Group::Sweep) {
        for p in ["tri-tri", "square-tri"] {
            sweep(out, p, args.theta_step)?;
        }
        eprintln!("sweeps done ({:.1} s)", t0.elapsed().as_secs_f64());
    }
    if want(Group::Contacts) {
        for (p, t) in CONTACT_MAPS {
            let scene = Scene::preset(p)?;
            let solver = Solver::new(&scene)?;
            let base = out.join(format!("contact_map_{p}_{}deg_1.4mN", fmt_num(t)));
            contact_map_files(
                &solver,
                deg_to_rad(t),
                mn_to_n(1.4),
                &with_ext(&base, "png"),
                Some(&with_ext(&base, "csv")),
            )?;
        }
        eprintln!("contact maps done ({:.1} s)", t0.elapsed().as_secs_f64());
    }
    if want(Group::Landscapes) {
        let scene = Scene::preset("square-tri")?;
        let solver = Solver::new(&scene)?;
        for t in [0.0, 10.2] {
            let l = landscape_with_progress(&solver, deg_to_rad(t), mn_to_n(1.4), args.grid)?;
            let base = out.join(format!("landscape_square-tri_{}deg_1.4mN", fmt_num(t)));
            write_atomic(&with_ext(&base, "csv"), landscape_csv(&l)?.as_bytes())?;
            landscape_png(&with_ext(&base, "png"), &l, "square-tri")?;
        }
        eprintln!("landscapes done ({:.1} s)", t0.elapsed().as_secs_f64());
    }
    if want(Group::Corrugation) {
        corrugation(
            out,
            &args.alpha,
            args.distance_um,
            args.step_um,
            args.grid,
            args.corrugation_method,
        )?;
        eprintln!("corrugation done ({:.1} s)", t0.elapsed().as_secs_f64());
    }
    Ok(())
}

/// `base` + `.ext` (unlike `Path::with_extension`, keeps a dotted number such as `1.4mN`).
fn with_ext(base: &Path, ext: &str) -> PathBuf {
    let mut s = base.as_os_str().to_owned();
    s.push(".");
    s.push(ext);
    PathBuf::from(s)
}
