//! `superlube tolerance`: flags → [`crate::study::tolerance::map`] → `DIR/map.csv` and
//! `DIR/map.png`, each with its sidecar.

use super::friction_args::FrictionKnobArgs;
use super::point_args::{direction_deg, help, Pull, StudyLoads, Theta, NOMINAL_THETA_HELP, THETA};
use super::scene_args::Resolved;
use super::tolerance_args::ToleranceArgs;
use super::verdict_args::VerdictArgs;
use super::{checks, point_args, SceneArgs};
use crate::plot::tolerance::tolerance_png;
use crate::runs::sink::csv_bytes;
use crate::runs::{
    meta::scene_file, meta::Inputs, output::check_outputs, output::Outputs, progress::Progress,
    progress::Reporter,
};
use crate::study::record;
use crate::study::rows::label;
use crate::study::tolerance::{map, LimitParams, MapParams, ToleranceRow};
use anyhow::{bail, Result};
use serde_json::json;
use std::path::PathBuf;
use surrogate::solver::Solver;
use surrogate::units::{n_to_mn, rad_to_deg};

/// Options of `superlube tolerance`: the superlubric limit load (friction estimate) of one
/// design over θ ± range × pulling direction ± range. A misaligned slider keeps the nominal
/// pulling direction in the substrate frame (the tribometer's axis does not turn with the
/// slider), so the map's y axis is the direction from the substrate's x axis.
#[derive(clap::Args, Debug)]
#[command(mut_args(help(THETA, NOMINAL_THETA_HELP)))]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// `--theta-deg`: one θ (degrees).
    #[command(flatten)]
    theta: Theta,
    /// `--alpha-deg` or `--direction-deg`: the nominal pulling direction (degrees).
    #[command(flatten)]
    pull: Pull,
    /// Half-width in degrees of the map in θ around the nominal (≥ 0).
    #[arg(
        long = "theta-range-deg",
        alias = "theta-range",
        value_name = "DEG",
        default_value_t = 0.2,
        allow_hyphen_values = true
    )]
    theta_range: f64,
    /// Points of the map along θ (odd keeps the nominal on the grid; 1 with range 0).
    #[arg(long = "theta-points", value_name = "N", default_value_t = 41)]
    theta_points: usize,
    /// Half-width in degrees of the map in pulling direction around the nominal (≥ 0).
    #[arg(
        long = "direction-range-deg",
        alias = "direction-range",
        value_name = "DEG",
        default_value_t = 1.0,
        allow_hyphen_values = true
    )]
    direction_range: f64,
    /// Points of the map along the direction.
    #[arg(long = "direction-points", value_name = "N", default_value_t = 21)]
    direction_points: usize,
    #[command(flatten)]
    tol: ToleranceArgs,
    /// `--load-mn`: the load ladder, a list or range (mN).
    #[command(flatten)]
    load: StudyLoads,
    #[command(flatten)]
    verdict: VerdictArgs,
    /// Contact-line angle in degrees from the substrate x axis that α is measured from
    /// [default: the moiré estimate at each θ].
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    line_deg: Option<f64>,
    #[command(flatten)]
    knobs: FrictionKnobArgs,
    /// Output folder: map.csv (one row per point, direction outer, θ inner: theta_deg,
    /// direction_deg, offsets, superlubric_to_mN, confident_to_mN, limited_by, …) and map.png
    /// (heat map of superlubric_to_mN with the nominal point and the tolerance box), each with a
    /// .meta.json sidecar.
    #[arg(long = "out-dir", alias = "out", value_name = "DIR")]
    out: PathBuf,
}

/// Grid of `n` points over ±`range` (degrees): `[0]` for one point.
fn grid(range: f64, n: usize, flag_range: &str, flag_points: &str) -> Result<Vec<f64>> {
    checks::non_negative(range, flag_range)?;
    match (n, range > 0.0) {
        (0, _) => bail!("`{flag_points}`: 0 points; give at least 1"),
        (1, true) => {
            bail!("`{flag_points}`: 1 point cannot span ±{range}°; give ≥ 2 or `{flag_range} 0`")
        }
        (1, false) => Ok(vec![0.0]),
        _ if n > 2001 => bail!("`{flag_points}`: {n} points is more than 2001"),
        _ => Ok((0..n)
            .map(|k| label(-range + 2.0 * range * k as f64 / (n - 1) as f64))
            .collect()),
    }
}

/// Runs `superlube tolerance`.
pub fn run(a: Args) -> Result<()> {
    // every check before any work
    let loads = a.load.newtons()?;
    if loads.windows(2).any(|w| w[1] <= w[0]) {
        bail!("`--load-mn`: loads must be strictly increasing");
    }
    let (thetas, dirs, (theta_tol, direction_tol)) = offsets(&a)?;
    a.verdict.mu_superlubric()?;
    let line = checks::line_deg(a.line_deg)?;
    let knobs = a.knobs.params()?;
    knobs.validate()?;
    let sc = a.scene.resolve(a.theta.deg)?;
    let theta_deg = label(rad_to_deg(sc.scene.slider.theta));
    let direction_deg = nominal_direction(&a, &sc, line)?;
    let csv = a.out.join("map.csv");
    let png = a.out.join("map.png");
    std::fs::create_dir_all(&a.out)
        .map_err(|e| anyhow::anyhow!("`--out-dir`: cannot create {}: {e}", a.out.display()))?;
    check_outputs(&[("--out-dir", Some(&csv)), ("--out-dir", Some(&png))])?;
    let mut scene0 = sc.scene.clone();
    scene0.slider.theta = 0.0;
    let solver = Solver::new(&scene0)?;
    let params = MapParams {
        theta_deg,
        direction_deg,
        theta_offsets_deg: thetas,
        direction_offsets_deg: dirs,
        limit: LimitParams {
            loads,
            mu_superlubric: a.verdict.mu_superlubric,
            line,
            friction: knobs,
        },
    };
    let rep = Reporter::stderr();
    sc.log(&rep);
    let n = params.theta_offsets_deg.len() * params.direction_offsets_deg.len();
    rep.stage("tolerance map", n as u64, "points");
    let t0 = std::time::Instant::now();
    let rows = map(&solver, &params, &|| rep.advance(1))?;
    rep.finish();
    let paths: usize = rows.iter().map(|r| r.loads_estimated).sum();
    rep.note(&format!(
        "tolerance: {n} points ({paths} load estimates) in {:.1} s",
        t0.elapsed().as_secs_f64()
    ));
    let mut outs = Outputs::new(
        record_inputs(
            &sc,
            &params,
            (theta_tol, direction_tol),
            a.verdict.mu_superlubric,
        ),
        sc.warnings.clone(),
    );
    outs.write(
        "--out-dir",
        Some(&csv),
        csv_bytes(&rows),
        Some(rows.len() as u64),
    );
    let nominal = rows
        .iter()
        .find(|r| r.theta_offset_deg == 0.0 && r.direction_offset_deg == 0.0);
    let (title, box_min) = title(
        &sc,
        &rows,
        (theta_deg, direction_deg),
        (theta_tol, direction_tol),
    );
    outs.attempt("--out-dir", &png, || {
        tolerance_png(
            &png,
            &title,
            &rows,
            params.theta_offsets_deg.len(),
            (theta_deg, direction_deg),
            (theta_tol, direction_tol),
            (
                surrogate::units::pa_to_gpa(solver.scene().coating.p_crit),
                params.limit.mu_superlubric,
            ),
        )
    });
    if let Some(r) = nominal {
        rep.note(&format!(
            "nominal θ = {theta_deg}°, direction {direction_deg}°: superlubric up to {} mN; over the box ±{}° × ±{}°: {} mN",
            r.superlubric_to_mN, theta_tol, direction_tol, box_min
        ));
    }
    outs.finish()
}

/// The map's θ and direction offsets (degrees) and the tolerance box (±θ, ±direction), checked
/// to lie on the map.
#[allow(clippy::type_complexity)]
fn offsets(a: &Args) -> Result<(Vec<f64>, Vec<f64>, (f64, f64))> {
    let thetas = grid(
        a.theta_range,
        a.theta_points,
        "--theta-range-deg",
        "--theta-points",
    )?;
    let dirs = grid(
        a.direction_range,
        a.direction_points,
        "--direction-range-deg",
        "--direction-points",
    )?;
    let (theta_tol, direction_tol) = a.tol.checked()?;
    if theta_tol > a.theta_range || direction_tol > a.direction_range {
        bail!(
            "the tolerance box (`--theta-tol-deg` {}, `--direction-tol-deg` {}) must lie on the map (`--theta-range-deg` {}, `--direction-range-deg` {})",
            theta_tol, direction_tol, a.theta_range, a.direction_range
        );
    }
    Ok((thetas, dirs, (theta_tol, direction_tol)))
}

/// The nominal pulling direction (degrees from x): `--direction-deg`, or `--alpha-deg` from the
/// contact line at the scene's θ (`line`: a fixed contact-line angle, rad).
fn nominal_direction(a: &Args, sc: &Resolved, line: Option<f64>) -> Result<f64> {
    Ok(match (a.pull.alpha_deg, a.pull.direction_deg) {
    (Some(al), None) => {
        point_args::alpha(al)?;
        checks::line_for(&sc.scene, line)?;
        let l = crate::study::friction::line_at(&sc.scene, sc.scene.slider.theta, line);
        label(rad_to_deg(l.angle) + al)
    }
    (None, Some(d)) => direction_deg(d)?,
    _ => bail!("give the nominal pulling direction: `--alpha-deg DEG` (from the contact line) or `--direction-deg DEG` (from x)"),
})
}

/// The sidecars' record of the map: the scene at its θ and the map's parameters.
fn record_inputs(
    sc: &Resolved,
    params: &MapParams,
    (theta_tol, direction_tol): (f64, f64),
    mu_superlubric: f64,
) -> Inputs {
    let (theta_deg, direction_deg, line) =
        (params.theta_deg, params.direction_deg, params.limit.line);
    let mut recorded = scene_file(&sc.scene);
    recorded.slider.theta_deg = Some(theta_deg);
    Inputs {
        workflow: "tolerance".into(),
        scene: Some(recorded),
        params: json!({
            "theta_deg": theta_deg,
            "direction_deg": direction_deg,
            "theta_offsets_deg": record::axis(&params.theta_offsets_deg),
            "direction_offsets_deg": record::axis(&params.direction_offsets_deg),
            "theta_tol_deg": theta_tol,
            "direction_tol_deg": direction_tol,
            "load_mN": params.limit.loads.iter().map(|&w| label(n_to_mn(w))).collect::<Vec<_>>(),
            "mu_superlubric": mu_superlubric,
            "line_deg": line.map(rad_to_deg),
            "friction": record::friction_knobs(&params.limit.friction),
        }),
    }
}

/// The map's title, with the least limit over the tolerance box (mN; infinite without a point
/// in it).
fn title(
    sc: &Resolved,
    rows: &[ToleranceRow],
    (theta_deg, direction_deg): (f64, f64),
    (theta_tol, direction_tol): (f64, f64),
) -> (String, f64) {
    let box_min = rows
        .iter()
        .filter(|r| {
            r.theta_offset_deg.abs() <= theta_tol + 1e-9
                && r.direction_offset_deg.abs() <= direction_tol + 1e-9
        })
        .map(|r| r.superlubric_to_mN)
        .fold(f64::INFINITY, f64::min);
    let title = format!(
        "{}: superlubric limit around θ = {}°, direction {}° (box ±{}° × ±{}°: {} mN)",
        sc.scene.pattern,
        theta_deg,
        direction_deg,
        theta_tol,
        direction_tol,
        if box_min.is_finite() {
            format!("{box_min}")
        } else {
            "–".into()
        }
    );
    (title, box_min)
}
