//! `superlube yield`: flags → [`crate::study::fab_yield::fab_yield`] → `DIR/yield.csv`,
//! `DIR/summary.json` and `DIR/yield.png`, each with its sidecar (the DEM runs in `DIR/dem/`).

use super::design_dem_args::DesignDemArgs;
use super::friction_args::FrictionKnobArgs;
use super::point_args::{help, Direction, StudyLoads, Theta, LOAD, NOMINAL_THETA_HELP, THETA};
use super::scene_args::Resolved;
use super::tolerance_args::ToleranceArgs;
use super::verdict_args::VerdictArgs;
use super::{checks, SceneArgs};
use crate::plot::yield_curve::yield_png;
use crate::present::yield_words;
use crate::runs::sink::csv_bytes;
use crate::runs::{
    meta::scene_file, meta::Inputs, output::check_outputs, output::Outputs, progress::Progress,
    progress::Reporter,
};
use crate::study::fab_yield::monte_carlo::dem_monte_carlo;
use crate::study::fab_yield::{
    bound_samples, fab_yield, BadKnob, FabricationModel, OffsetLaw, YieldDem, YieldParams,
    YieldSummary, DEFAULT_MAX_RUNS, DEFAULT_RESOLUTION,
};
use crate::study::record;
use crate::study::rows::label;
use crate::study::tolerance::LimitParams;
use anyhow::{bail, Result};
use serde_json::json;
use std::path::PathBuf;
use surrogate::units::{gpa_to_pa, n_to_mn, pa_to_gpa, rad_to_deg};

/// Options of `superlube yield`: the fraction of fabricated devices of one design (θ, pull
/// direction) that stay superlubric at a load, the load that a fraction q of them hold, and
/// its one-sided confidence bound; the DEM locates the critical loads of the devices that set
/// them.
#[derive(clap::Args, Debug)]
#[command(
    mut_args(help(THETA, NOMINAL_THETA_HELP)),
    mut_args(help(
        LOAD,
        "The load ladder in mN, strictly increasing: each device's critical load is found \
         between two of them [default: the study's 0.35 … 3.86]"
    ))
)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// `--theta-deg`: one θ (degrees).
    #[command(flatten)]
    theta: Theta,
    /// `--direction-deg`: the pulling direction (degrees from x).
    #[command(flatten)]
    direction: Direction,
    #[command(flatten)]
    tol: ToleranceArgs,
    /// σ in degrees of a normal θ offset (truncated at ±3σ) instead of the uniform one over
    /// ±--theta-tol-deg.
    #[arg(
        long = "theta-sigma-deg",
        value_name = "DEG",
        allow_hyphen_values = true,
        conflicts_with = "theta_tol"
    )]
    theta_sigma_deg: Option<f64>,
    /// σ in degrees of a normal pull-direction offset (truncated at ±3σ) instead of the
    /// uniform one over ±--direction-tol-deg.
    #[arg(
        long = "direction-sigma-deg",
        value_name = "DEG",
        allow_hyphen_values = true,
        conflicts_with = "direction_tol"
    )]
    direction_sigma_deg: Option<f64>,
    /// Coefficient of variation of each slider sphere's diameter (normal, truncated at ±3σ; 0:
    /// every sphere the scene's). Needs room between the spheres: refused where a sphere 3σ
    /// large would overlap its neighbour.
    #[arg(
        long = "sphere-diameter-cv",
        value_name = "CV",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    sphere_diameter_cv: f64,
    /// σ in GPa of the coating strength P_crit around the scene's (normal, truncated at ±3σ;
    /// 0: no spread).
    #[arg(
        long = "p-crit-sigma-gpa",
        value_name = "GPA",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    p_crit_sigma_gpa: f64,
    /// Devices drawn (≥ 1). 59 gives the one-sided 95 %/95 % bound (Wilks).
    #[arg(long, value_name = "N", default_value_t = bound_samples())]
    samples: usize,
    /// q in (0, 1): the fraction of devices the quoted load must hold.
    #[arg(
        long,
        value_name = "Q",
        default_value_t = 0.95,
        allow_hyphen_values = true
    )]
    quantile: f64,
    /// γ in (0, 1): confidence of the yield's interval and of the quoted load's bound.
    #[arg(
        long,
        value_name = "G",
        default_value_t = 0.95,
        allow_hyphen_values = true
    )]
    confidence: f64,
    /// Resolution of each device's critical load, as a fraction of the load (bisection
    /// between two loads of --load-mn; 0 < r ≤ 0.5).
    #[arg(
        long,
        value_name = "R",
        default_value_t = DEFAULT_RESOLUTION,
        allow_hyphen_values = true
    )]
    resolution: f64,
    /// Seed of the devices' draws (each device its own stream: the same seed gives the same
    /// devices).
    #[arg(long = "sample-seed", value_name = "SEED", default_value_t = 1)]
    sample_seed: u64,
    /// Substrate seeds the design searched (its --seeds), never drawn for a device besides
    /// the scene's own --seed (comma list of non-negative integers).
    #[arg(long = "searched-seeds", value_name = "S1,S2")]
    searched_seeds: Option<String>,
    /// `--load-mn`: the load ladder, a list or range (mN).
    #[command(flatten)]
    load: StudyLoads,
    #[command(flatten)]
    verdict: VerdictArgs,
    /// Contact-line angle in degrees from the substrate x axis (for α in the DEM runs' names)
    /// [default: the moiré estimate at each θ].
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    line_deg: Option<f64>,
    #[command(flatten)]
    knobs: FrictionKnobArgs,
    /// Fresh devices run with the DEM at the estimate's quote, first, as a check and to
    /// calibrate the estimate on random devices, then pooled into the yield; the quote is
    /// lowered until the check agrees with it (0: none).
    #[arg(
        long = "dem-check",
        value_name = "N",
        default_value_t = 10,
        conflicts_with = "no_dem"
    )]
    dem_check: usize,
    /// Load in mN of the DEM check [default: the estimate's quote]: compares the yield at another
    /// load with the DEM's.
    #[arg(
        long = "dem-check-load-mn",
        value_name = "MN",
        allow_hyphen_values = true,
        conflicts_with = "no_dem"
    )]
    dem_check_load_mn: Option<f64>,
    /// Most DEM runs of the yield, the check's included: the devices still undecided when they
    /// are spent count at the lower end of what is known of them (safe, less sharp). Where the
    /// estimate ranks the devices poorly (rough substrates) a sharp bound needs about one run
    /// per device plus a few per located one.
    #[arg(
        long = "dem-max-runs",
        value_name = "N",
        default_value_t = DEFAULT_MAX_RUNS,
        conflicts_with = "no_dem"
    )]
    dem_max_runs: usize,
    /// Validation: after the yield, N fresh devices each get their own critical load from the
    /// DEM alone (located to --resolution), written to DIR/dem_monte_carlo.csv, and
    /// DIR/monte_carlo.json sets the quote and its bound against that distribution (its 5th
    /// percentile, the devices holding each). Costs about 3–6 DEM runs per device.
    #[arg(long = "dem-monte-carlo", value_name = "N", conflicts_with = "no_dem")]
    dem_monte_carlo: Option<usize>,
    /// Estimate only: no DEM runs and no DEM check (the quote is the estimate's).
    #[arg(long = "no-dem")]
    no_dem: bool,
    #[command(flatten)]
    dem: DesignDemArgs,
    /// Output folder: yield.csv (one row per device), summary.json (the quoted load, its
    /// bound, the DEM check, the fabrication model), yield.png, each with a .meta.json
    /// sidecar, and dem/ (the DEM runs, reused by a re-run).
    #[arg(long = "out-dir", alias = "out", value_name = "DIR")]
    out: PathBuf,
}

/// The offset law of one axis: normal with `sigma` (degrees) when given, else uniform over
/// ±`tol`.
fn law(tol: f64, sigma: Option<f64>, flag: &str) -> Result<OffsetLaw> {
    Ok(match sigma {
        Some(s) => OffsetLaw::Normal {
            sigma_deg: checks::non_negative(s, flag)?,
        },
        None => OffsetLaw::Uniform {
            half_width_deg: tol,
        },
    })
}

/// The refusal of an out-of-range knob of `superlube yield` (`values`: samples, quantile,
/// confidence, resolution as given).
fn bad_knob_words(bad: BadKnob, values: [f64; 4]) -> String {
    match bad {
        BadKnob::Samples => format!(
            "`--samples`: 0 devices; give at least 1 ({} for a 95 %/95 % bound)",
            bound_samples()
        ),
        BadKnob::Quantile => format!(
            "`--quantile`: {} must lie strictly between 0 and 1",
            values[1]
        ),
        BadKnob::Confidence => format!(
            "`--confidence`: {} must lie strictly between 0 and 1",
            values[2]
        ),
        BadKnob::Resolution => format!(
            "`--resolution`: {} must lie in (0, 0.5] (a fraction of the load)",
            values[3]
        ),
    }
}

/// The fabrication model of `a` on `scene`: the offset laws, the scatters (refused where a
/// ±3σ draw leaves no room) and the seeds never drawn.
fn fabrication(a: &Args, scene: &surrogate::Scene) -> Result<FabricationModel> {
    let (theta_tol, direction_tol) = a.tol.checked()?;
    let theta = law(theta_tol, a.theta_sigma_deg, "--theta-sigma-deg")?;
    let direction = law(
        direction_tol,
        a.direction_sigma_deg,
        "--direction-sigma-deg",
    )?;
    let cv = checks::non_negative(a.sphere_diameter_cv, "--sphere-diameter-cv")?;
    let p_sigma = gpa_to_pa(checks::non_negative(
        a.p_crit_sigma_gpa,
        "--p-crit-sigma-gpa",
    )?);
    let searched = a
        .searched_seeds
        .as_deref()
        .map_or(Ok(Vec::new()), |t| checks::seed_list(t, "--searched-seeds"))?;
    let three = crate::study::fab_yield::fabrication::TRUNCATE_SIGMA;
    if p_sigma > 0.0 && scene.coating.p_crit - three * p_sigma <= 0.0 {
        bail!(
            "`--p-crit-sigma-gpa`: {} GPa reaches P_crit ≤ 0 within ±{three}σ of the scene's {} GPa; give less than {} GPa",
            a.p_crit_sigma_gpa,
            pa_to_gpa(scene.coating.p_crit),
            pa_to_gpa(scene.coating.p_crit) / three
        );
    }
    if cv > 0.0 {
        if three * cv >= 1.0 {
            bail!("`--sphere-diameter-cv`: {cv} reaches a diameter ≤ 0 within ±{three}σ; give less than {}", 1.0 / three);
        }
        // the largest sphere a draw can give, on every site: must not overlap a neighbour
        let mut widest = scene.clone();
        let r = scene.slider_sphere_radius() * (1.0 + three * cv);
        let sites = scene.slider_sites_local();
        widest.geometry.slider_sites = Some(surrogate::scene::SiteList {
            path: "largest drawn spheres".into(),
            radii: Some(vec![r; sites.len()]),
            sites,
            diameter: None,
            cells: Vec::new(),
            lines: Vec::new(),
        });
        if let Err(e) = widest.validate() {
            bail!("`--sphere-diameter-cv`: {cv}: a slider sphere drawn {three}σ large would overlap its neighbour ({e}); give a smaller CV, or a slider whose spacing exceeds its sphere diameter");
        }
    }
    let mut excluded = vec![scene.substrate.seed];
    excluded.extend(&searched);
    Ok(FabricationModel {
        theta,
        direction,
        sphere_diameter_cv: cv,
        p_crit_sigma: p_sigma,
        seed: a.sample_seed,
        excluded_seeds: excluded,
    })
}

/// The ladder, μ_sl, contact line and estimate knobs of `a`, checked.
fn limit(a: &Args) -> Result<LimitParams> {
    let loads = a.load.newtons()?;
    if loads.windows(2).any(|w| w[1] <= w[0]) {
        bail!("`--load-mn`: the loads must be strictly increasing");
    }
    let knobs = a.knobs.params()?;
    knobs.validate()?;
    Ok(LimitParams {
        loads,
        mu_superlubric: a.verdict.mu_superlubric()?,
        line: checks::line_deg(a.line_deg)?,
        friction: knobs,
    })
}

/// The yield of `a`, every input checked before any work: its scene (with its warnings) and
/// its knobs.
fn prepare(a: &Args) -> Result<(Resolved, YieldParams)> {
    if let Some(bad) = YieldParams::bad_knob(a.samples, a.quantile, a.confidence, a.resolution) {
        bail!(
            "{}",
            bad_knob_words(
                bad,
                [a.samples as f64, a.quantile, a.confidence, a.resolution]
            )
        );
    }
    a.direction.checked()?;
    let limit = limit(a)?;
    let check_load = a
        .dem_check_load_mn
        .map(|w| checks::positive(w, "--dem-check-load-mn").map(surrogate::units::mn_to_n))
        .transpose()?;
    if !a.no_dem && !YieldDem::runs_hold_check(a.dem_max_runs, a.dem_check) {
        bail!(
            "`--dem-max-runs`: {} runs cannot hold the check's {} (--dem-check); give at least {}, or --no-dem",
            a.dem_max_runs,
            a.dem_check,
            a.dem_check.max(1)
        );
    }
    let dem = if a.no_dem {
        None
    } else {
        Some(a.dem.params(limit.line)?)
    };
    let sc = a.scene.resolve(a.theta.deg)?;
    let fabrication = fabrication(a, &sc.scene)?;
    let params = YieldParams {
        theta_deg: label(rad_to_deg(sc.scene.slider.theta)),
        direction_deg: a.direction.deg,
        fabrication,
        samples: a.samples,
        quantile: a.quantile,
        confidence: a.confidence,
        resolution: a.resolution,
        limit,
        dem: dem.map(|(params, jobs)| {
            let check = (a.dem_check, check_load);
            YieldDem::new(params, check, a.dem_max_runs, jobs, a.out.join("dem"))
        }),
    };
    Ok((sc, params))
}

/// The inputs `superlube yield` records in its sidecars.
fn inputs(scene: &surrogate::Scene, p: &YieldParams) -> Inputs {
    let mut recorded = scene_file(scene);
    recorded.slider.theta_deg = Some(p.theta_deg);
    let mn = |w: f64| label(n_to_mn(w));
    Inputs {
        workflow: "yield".into(),
        scene: Some(recorded),
        params: json!({
            "theta_deg": p.theta_deg,
            "direction_deg": p.direction_deg,
            "fabrication": p.fabrication.record(scene),
            "samples": p.samples,
            "quantile": p.quantile,
            "confidence": p.confidence,
            "resolution": p.resolution,
            "load_mN": p.limit.loads.iter().map(|&w| mn(w)).collect::<Vec<_>>(),
            "mu_superlubric": p.limit.mu_superlubric,
            "line_deg": p.limit.line.map(rad_to_deg),
            "friction": record::friction_knobs(&p.limit.friction),
            "dem": p.dem.as_ref().map(|d| record::dem(scene, &d.params)),
            "dem_check": p.dem.as_ref().map(|d| d.check),
            "dem_max_runs": p.dem.as_ref().map(|d| d.max_runs),
            "dem_check_load_mN": p.dem.as_ref().and_then(|d| d.check_load).map(mn),
        }),
    }
}

/// Pretty JSON with a final newline.
fn json_bytes<T: serde::Serialize>(v: &T) -> Result<Vec<u8>> {
    let mut b = serde_json::to_vec_pretty(v)?;
    b.push(b'\n');
    Ok(b)
}

/// `--dem-monte-carlo N`: the DEM's own critical loads of N fresh devices against the quote,
/// written through `outs`.
fn monte_carlo(
    (scene, p, s): (&surrogate::Scene, &YieldParams, &YieldSummary),
    count: usize,
    outs: &mut Outputs,
    (out, rep): (&std::path::Path, &Reporter),
) -> Result<()> {
    let Some(d) = &p.dem else { return Ok(()) };
    let (rows, mc) = dem_monte_carlo(scene, p, d, s, count, rep)?;
    let csv = out.join("dem_monte_carlo.csv");
    outs.write(
        "--out-dir",
        Some(&csv),
        csv_bytes(&rows),
        Some(rows.len() as u64),
    );
    outs.write(
        "--out-dir",
        Some(&out.join("monte_carlo.json")),
        json_bytes(&mc),
        None,
    );
    rep.note(&format!(
        "monte carlo: {} devices by the DEM alone ({} runs): 5th percentile {} mN; {} hold the quote, {} hold the bound",
        mc.devices,
        mc.dem_runs,
        yield_words::load(mc.p5_mN),
        mc.holding_quote,
        mc.holding_bound
    ));
    Ok(())
}

/// Runs `superlube yield`.
pub fn run(a: Args) -> Result<()> {
    let (sc, params) = prepare(&a)?;
    let scene = &sc.scene;
    let csv = a.out.join("yield.csv");
    let json_path = a.out.join("summary.json");
    let png = a.out.join("yield.png");
    std::fs::create_dir_all(&a.out)
        .map_err(|e| anyhow::anyhow!("`--out-dir`: cannot create {}: {e}", a.out.display()))?;
    check_outputs(&[
        ("--out-dir", Some(&csv)),
        ("--out-dir", Some(&json_path)),
        ("--out-dir", Some(&png)),
    ])?;
    let rep = Reporter::stderr();
    sc.log(&rep);
    if scene.substrate.sigma_h == 0.0 {
        rep.note("yield: the substrate is flat (σ_h = 0): every device's substrate is the same; only the offsets and scatters vary");
    }
    let t0 = std::time::Instant::now();
    let o = fab_yield(scene, &params, &rep)?;
    let s = &o.summary;
    rep.note(&format!(
        "yield: {} devices and {} of the check ({} load estimates), {} DEM run(s) in all, in {:.1} s",
        s.samples,
        s.dem_check_total,
        o.estimates,
        s.dem_runs,
        t0.elapsed().as_secs_f64()
    ));
    if s.dem {
        rep.note(&format!("yield: {}", yield_words::dem_work(s)));
    }
    let mut outs = Outputs::new(inputs(scene, &params), sc.warnings.clone());
    outs.write(
        "--out-dir",
        Some(&csv),
        csv_bytes(&o.rows),
        Some(o.rows.len() as u64),
    );
    outs.write("--out-dir", Some(&json_path), json_bytes(s), None);
    outs.attempt("--out-dir", &png, || yield_png(&png, s));
    rep.note(&format!("yield: {}", yield_words::fabricator(s)));
    if s.load_at_quantile_mN.is_some() && s.load_at_quantile_bound_mN.is_none() {
        rep.note("yield: more devices give a confidence bound: --samples");
    }
    if let Some(c) = yield_words::check(s) {
        rep.note(&format!("yield: {c}"));
    }
    if let Some(count) = a.dem_monte_carlo.filter(|&n| n > 0) {
        monte_carlo((scene, &params, s), count, &mut outs, (&a.out, &rep))?;
    }
    outs.finish()
}
