//! `superlube design`: flags → pattern scenes + [`DesignParams`] → [`crate::study::design::design`]
//! (which writes everything under `--out-dir`).

use super::dem_args::ModelArg;
use super::friction_args::FrictionKnobArgs;
use super::tolerance_args::ToleranceArgs;
use super::{checks, parse_list_or_range, SceneArgs, SceneOverrides};
use crate::runs::{output::check_outputs, progress::Reporter};
use crate::study::campaign::STUDY_LOADS_MN;
use crate::study::dem_run::{DemParams, ModelSpec};
use crate::study::design::store::Store;
use crate::study::design::{cut, design, DesignParams, DesignScene};
use anyhow::{bail, Result};
use dem::protocol::RunIo;
use dem::{SimParams, Start};
use std::path::PathBuf;
use std::sync::LazyLock;
use surrogate::units::{mn_to_n, um_to_m, us_to_s};

/// The study's load list (mN) as clap's default string (`0.35,0.7,…,3.5,3.86`), formatted from
/// its one definition [`STUDY_LOADS_MN`].
pub static STUDY_LOADS: LazyLock<String> = LazyLock::new(|| {
    let loads: Vec<String> = STUDY_LOADS_MN.iter().map(|w| w.to_string()).collect();
    loads.join(",")
});

/// The default θ list (degrees) of `--theta`, before the symmetry cut (the study's).
pub const DEFAULT_THETA: &str = "0:30:0.1";

/// Options of `superlube design`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Pattern pairs to design, comma-separated: tri-tri, square-tri, square-square, tri-square
    /// (the study's geometry) [default: square-tri,tri-tri unless --scene is given].
    #[arg(long, value_name = "P1,P2")]
    pattern: Option<String>,
    /// A scene file (TOML, user units; README "Scenes") to design, repeatable (`--scene a.toml
    /// --scene b.toml`); named after the file stem in the outputs. The override flags below
    /// apply to every pattern and scene.
    #[arg(long, value_name = "FILE.toml")]
    scene: Vec<PathBuf>,
    /// An index.csv of `superlube patterns`: designs every candidate's scene file (named by its
    /// pattern_id), as if each were given with --scene; the ranking spans all of them.
    #[arg(long, value_name = "INDEX.csv", conflicts_with = "family")]
    patterns: Option<PathBuf>,
    /// A lattice family (as `superlube patterns --family`: `directional`, `presets[:s=…]`,
    /// `rectangular:a=…,b=…`, `oblique:a=…,b=…,gamma_deg=…`): its candidates over the substrate
    /// of the one --pattern or --scene given (default square-tri) are written to
    /// OUT/patterns/ (equal slider area unless --normalize spheres, p, q ≤ 3, orders ≤ 4; run
    /// `superlube patterns` for other knobs) and designed as with --patterns
    /// OUT/patterns/index.csv.
    #[arg(long, value_name = "SPEC")]
    family: Option<String>,
    /// With --family: what the candidates share, as `superlube patterns --normalize`: `area`
    /// (the base scene's slider outline, default) or `spheres` (each outline scaled to hold
    /// the base slider's sphere count); the report states the rule.
    #[arg(long, value_enum, value_name = "RULE", requires = "family")]
    normalize: Option<crate::study::patterns::Normalize>,
    /// Scene override flags, applied to every pattern and scene.
    #[command(flatten)]
    overrides: SceneOverrides,
    /// Recipe flags (`--vary`, `--fair`, `--skip-invalid`): scene fields as design variables.
    #[command(flatten)]
    recipe: super::recipe_args::RecipeArgs,
    /// Orientations θ in degrees (list or range start:stop:step), cut to each pattern's
    /// fundamental domain (square-tri 0–15°, tri-tri 0–30°: docs/commands/design.md); a list
    /// that does not span a domain is named in the log and the report [default: 0:30:0.1, and
    /// for a pattern whose domain it does not span (no derived symmetry, or a domain wider
    /// than 30°) the whole domain at 0.1°, or 0.25° when wider than 60°].
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    theta: Option<String>,
    /// Screen θ as given, without the symmetry cut (for scenes whose symmetry is broken, e.g.
    /// by --offset-um).
    #[arg(long = "no-symmetry-cut")]
    no_symmetry_cut: bool,
    /// Normal loads W in mN, strictly increasing (list or range) [default: the study's
    /// 0.35, 0.70, …, 3.50, 3.86].
    #[arg(long = "load-mn", value_name = "MN", default_value = STUDY_LOADS.as_str(), allow_hyphen_values = true)]
    load_mn: String,
    /// Friction coefficient below which a design counts as superlubric.
    #[arg(
        long = "mu-superlubric",
        value_name = "MU",
        default_value_t = 0.02,
        allow_hyphen_values = true
    )]
    mu_superlubric: f64,
    /// Orientations kept per lower load level of the shortlist (those with the lowest P_max).
    /// How the default was chosen: docs/commands/design.md "The shortlist rule".
    #[arg(long = "per-level", value_name = "N", default_value_t = 6)]
    per_level: usize,
    /// Most orientations kept from the top level (those surviving the highest load).
    #[arg(long = "max-top", value_name = "N", default_value_t = 40)]
    max_top: usize,
    /// Coarse step in degrees of the α scan over one α period (square-tri: 180°, tri-tri: 60°).
    #[arg(
        long = "alpha-step-deg",
        value_name = "DEG",
        default_value_t = 15.0,
        allow_hyphen_values = true
    )]
    alpha_step_deg: f64,
    /// Successive finer α steps in degrees, each scanned over ± half the previous step around
    /// the best α so far (comma list, decreasing; `none` for no refinement).
    #[arg(
        long = "alpha-refine-deg",
        value_name = "DEG,DEG",
        default_value = "2.5,0.5",
        allow_hyphen_values = true
    )]
    alpha_refine_deg: String,
    /// Contact-line angle in degrees from the substrate x axis for every θ [default: the moiré
    /// estimate at each θ, as in `corrugation` and `slide`].
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    line_deg: Option<f64>,
    /// Length in µm of each α-scan path.
    #[arg(
        long = "scan-distance-um",
        alias = "scan-um",
        value_name = "UM",
        default_value_t = 6.0,
        allow_hyphen_values = true
    )]
    scan_um: f64,
    /// Sample spacing in µm along the α-scan paths.
    #[arg(
        long = "scan-step-um",
        value_name = "UM",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    scan_step_um: f64,
    /// Pulling angles per orientation whose friction is estimated (the lowest-corrugation
    /// minima of the α scan, at least one coarse step apart).
    #[arg(long = "best-alphas", value_name = "N", default_value_t = 1)]
    alphas_per_theta: usize,
    #[command(flatten)]
    friction: FrictionKnobArgs,
    #[command(flatten)]
    tol: ToleranceArgs,
    /// Largest sampling step in degrees of the θ tolerance: the first sample off the nominal is
    /// at most this far, so a window narrower than the tolerance cannot pass.
    #[arg(
        long = "theta-tol-step-deg",
        alias = "theta-tol-step",
        value_name = "DEG",
        default_value_t = 0.02,
        allow_hyphen_values = true
    )]
    theta_tol_step: f64,
    /// Largest sampling step in degrees of the direction tolerance.
    #[arg(
        long = "direction-tol-step-deg",
        alias = "direction-tol-step",
        value_name = "DEG",
        default_value_t = 0.25,
        allow_hyphen_values = true
    )]
    direction_tol_step: f64,
    /// Further substrate seeds (comma list) whose height realisations the robust limit must
    /// also hold on (σ_h > 0 only): the worst case counts.
    #[arg(long, value_name = "S1,S2")]
    seeds: Option<String>,
    /// Designs per pattern confirmed with DEM `slide` runs (the top of the ranking; ≥ 1 unless
    /// --no-dem).
    #[arg(long, value_name = "K", default_value_t = 3)]
    confirm: usize,
    /// Loads in mN of the DEM confirmation, each one of --load-mn [default: the lowest, the
    /// middle and the highest load].
    #[arg(
        long = "confirm-loads-mn",
        alias = "confirm-loads",
        value_name = "MN",
        allow_hyphen_values = true
    )]
    confirm_loads: Option<String>,
    /// Stop before the DEM confirmation (surrogate tiers only).
    #[arg(long = "no-dem")]
    no_dem: bool,
    /// DEM runs side by side, one thread each [default: the number of CPU cores].
    #[arg(long, value_name = "N")]
    jobs: Option<usize>,
    /// Compute only shard I of N (zero-based) of the DEM confirmation runs, e.g. on N machines
    /// or Slurm tasks, into `--out-dir`/dem/, and stop before the report; then run the same
    /// command without `--shard` on one `--out-dir` holding every shard's `dem/` runs: it reuses
    /// them and writes the report.
    #[arg(long, value_name = "I/N")]
    shard: Option<String>,
    /// Equilibration in µs of each confirmation run (study: 10).
    #[arg(
        long = "dem-equilibrate-us",
        value_name = "US",
        default_value_t = 2.0,
        allow_hyphen_values = true
    )]
    dem_equilibrate_us: f64,
    /// Relaxation in µs with the pulling spring attached (study: 10).
    #[arg(
        long = "dem-relax-us",
        value_name = "US",
        default_value_t = 2.0,
        allow_hyphen_values = true
    )]
    dem_relax_us: f64,
    /// Sliding time in µs of each confirmation run; friction over its last two thirds (study:
    /// 300).
    #[arg(
        long = "dem-slide-us",
        value_name = "US",
        default_value_t = 60.0,
        allow_hyphen_values = true
    )]
    dem_slide_us: f64,
    /// Support speed in m/s (study: 0.1).
    #[arg(
        long = "dem-speed-m-s",
        value_name = "M_S",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    dem_speed_m_s: f64,
    /// DEM time step in µs [default: 0.25 × the stable-step estimate].
    #[arg(long = "dem-dt-us", value_name = "US", allow_hyphen_values = true)]
    dem_dt_us: Option<f64>,
    /// DEM model of the confirmation runs (as `slide --model`): `reduced` (rigid-z, default;
    /// its accuracy: docs/validation/dem-engine.md "Model choice"), `auto` (the full model near
    /// coating failure and where stick-slip is expected; its cost:
    /// docs/validation/dem-integrator.md) or `full`. Pruning and the active set (exact) are on
    /// in every model.
    #[arg(long = "dem-model", value_enum, default_value_t = ModelArg::Reduced)]
    dem_model: ModelArg,
    /// Do not run the best design once more with the study's protocol (10 + 10 + 300 µs) to
    /// measure the shorter protocol's friction difference.
    #[arg(long = "no-protocol-check")]
    no_protocol_check: bool,
    /// Output directory: report.md, ranking.csv, the CSVs and PNGs behind them, dem/ (the DEM
    /// runs) and stages/ (finished stages, reused by a re-run with the same inputs).
    #[arg(
        long = "out-dir",
        alias = "out",
        value_name = "DIR",
        default_value = "design"
    )]
    out: PathBuf,
}

/// The scene flags shared by every pattern, as given (for the reproduction commands).
fn scene_args(a: &Args, pattern: Option<String>, scene: Option<PathBuf>) -> SceneArgs {
    SceneArgs {
        pattern,
        scene,
        overrides: a.overrides.clone(),
    }
}

/// The pattern scenes of the command line (errors name `--pattern` / `--scene`).
fn scenes(a: &Args) -> Result<Vec<DesignScene>> {
    let mut out: Vec<DesignScene> = Vec::new();
    let mut files = a.scene.clone();
    let mut facts = Vec::new();
    let mut pattern = a.pattern.clone();
    let generated = match &a.family {
        Some(spec) => {
            if a.scene.len() > 1 || pattern.as_deref().is_some_and(|p| p.contains(',')) {
                bail!("`--family`: give at most one --pattern or --scene (the base of the candidates)");
            }
            let base = scene_args(a, pattern.take(), files.pop()).resolve(None)?;
            let params = super::patterns::check(
                spec,
                super::patterns::DEFAULT_MAX_PQ,
                super::patterns::DEFAULT_MAX_ORDER,
            )?;
            Some(super::patterns::generate(
                &base,
                &params,
                a.normalize.unwrap_or_default(),
                &a.out.join("patterns"),
                Some("--family"),
            )?)
        }
        None => None,
    };
    if let Some(index) = a.patterns.as_ref().or(generated.as_ref()) {
        facts = crate::study::patterns::index_facts(index)?;
        // the contact-type pre-screen orders the surrogate's work
        files.extend(crate::study::patterns::prescreen_order(
            crate::study::patterns::index_scenes(index)?,
            &facts,
        ));
    }
    let patterns: Vec<String> = match (&pattern, files.is_empty()) {
        (Some(p), _) => p.split(',').map(|s| s.trim().to_string()).collect(),
        (None, true) => vec!["square-tri".into(), "tri-tri".into()],
        (None, false) => vec![],
    };
    let extra = a.overrides.flags();
    for p in patterns {
        if !surrogate::scene::PATTERNS.contains(&p.as_str()) {
            bail!(
                "`--pattern`: unknown pattern `{p}` (expected a comma list of {})",
                surrogate::scene::PATTERNS.join(", ")
            );
        }
        let r = scene_args(a, Some(p.clone()), None).resolve(Some(0.0))?;
        let mut flags = vec!["--pattern".to_string(), p.clone()];
        flags.extend(extra.iter().cloned());
        out.push(DesignScene {
            name: p,
            scene: r.scene,
            flags,
            warnings: r.warnings,
            facts: None,
        });
    }
    for f in &files {
        let name = f
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        if name.is_empty()
            || !name
                .chars()
                .all(|c| c.is_alphanumeric() || "-_.".contains(c))
        {
            bail!(
                "`--scene`: {}: the file stem names the outputs and must be letters, digits, `-`, `_`, `.`",
                f.display()
            );
        }
        let r = scene_args(a, None, Some(f.clone())).resolve(Some(0.0))?;
        let mut flags = vec!["--scene".to_string(), f.display().to_string()];
        flags.extend(extra.iter().cloned());
        let facts = facts
            .iter()
            .find(|(id, _)| *id == name)
            .map(|(_, f)| f.clone());
        out.push(DesignScene {
            name,
            scene: r.scene,
            flags,
            warnings: r.warnings,
            facts,
        });
    }
    for (k, s) in out.iter().enumerate() {
        if out[..k].iter().any(|t| t.name == s.name) {
            bail!(
                "`--pattern`/`--scene`: `{}` is given twice (patterns and scene-file stems name the outputs)",
                s.name
            );
        }
    }
    a.recipe.expand(out, &a.out)
}

/// Every check of `superlube design`, before any work.
pub fn prepare(a: &Args) -> Result<(Vec<DesignScene>, DesignParams)> {
    let theta_text = a.theta.clone().unwrap_or_else(|| DEFAULT_THETA.to_string());
    let thetas_deg = parse_list_or_range(&theta_text, "--theta")?;
    let loads = checks::loads(&a.load_mn)?;
    if let Some(k) = loads.windows(2).position(|w| w[1] <= w[0]) {
        bail!(
            "`--load-mn`: the loads must be strictly increasing ({} mN then {} mN): a design's superlubric load is the highest of an increasing list",
            a.load_mn.split(',').nth(k).unwrap_or("?").trim(),
            a.load_mn.split(',').nth(k + 1).unwrap_or("?").trim()
        );
    }
    if !(a.mu_superlubric.is_finite() && a.mu_superlubric > 0.0) {
        bail!(
            "`--mu-superlubric`: {} must be a positive number",
            a.mu_superlubric
        );
    }
    if a.per_level == 0 {
        bail!("`--per-level`: 0 would keep no orientation below the top level; give ≥ 1");
    }
    if a.max_top == 0 {
        bail!("`--max-top`: 0 would keep no orientation of the top level; give ≥ 1");
    }
    if a.alphas_per_theta == 0 {
        bail!("`--best-alphas`: give ≥ 1");
    }
    let step = checks::positive(a.alpha_step_deg, "--alpha-step-deg")?;
    if step > 90.0 {
        bail!("`--alpha-step-deg`: {step} must be at most 90");
    }
    let refine: Vec<f64> = if a.alpha_refine_deg.trim() == "none" {
        vec![]
    } else {
        parse_list_or_range(&a.alpha_refine_deg, "--alpha-refine-deg")?
    };
    let mut prev = step;
    for &r in &refine {
        if !(r > 0.0 && r < prev) {
            bail!("`--alpha-refine-deg`: each step must be positive and below the previous one ({r} after {prev})");
        }
        prev = r;
    }
    let line = checks::line_deg(a.line_deg)?;
    let scan_length = checks::positive(a.scan_um, "--scan-distance-um").map(um_to_m)?;
    let scan_step = checks::positive(a.scan_step_um, "--scan-step-um").map(um_to_m)?;
    if scan_step > scan_length {
        bail!(
            "`--scan-step-um`: {} must not exceed --scan-distance-um {}",
            a.scan_step_um,
            a.scan_um
        );
    }
    let friction = a.friction.params()?;
    if !a.no_dem && a.confirm == 0 {
        bail!("`--confirm`: 0 designs to confirm with the DEM on; give --confirm ≥ 1, or --no-dem to stop before the DEM");
    }
    let confirm_loads = match &a.confirm_loads {
        Some(t) => {
            let v = checks::loads(t).map_err(|e| {
                anyhow::anyhow!(
                    "{}",
                    e.to_string().replace("`--load-mn`", "`--confirm-loads-mn`")
                )
            })?;
            for &w in &v {
                if !loads.iter().any(|&l| (l - w).abs() <= 1e-12 * l) {
                    bail!(
                        "`--confirm-loads-mn`: {} mN is not one of --load-mn (the DEM is compared with the estimate at the same load)",
                        surrogate::units::n_to_mn(w)
                    );
                }
            }
            v
        }
        None => {
            let mut v = vec![loads[0], loads[loads.len() / 2], loads[loads.len() - 1]];
            v.dedup();
            v
        }
    };
    let jobs = match a.jobs {
        Some(0) => bail!("`--jobs`: give ≥ 1 DEM runs side by side"),
        Some(j) => j,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let times = [
        (a.dem_equilibrate_us, "--dem-equilibrate-us"),
        (a.dem_slide_us, "--dem-slide-us"),
        (a.dem_speed_m_s, "--dem-speed-m-s"),
    ];
    for (v, f) in times {
        checks::positive(v, f)?;
    }
    checks::non_negative(a.dem_relax_us, "--dem-relax-us")?;
    let dt = a
        .dem_dt_us
        .map(|d| checks::time_us(d, "--dem-dt-us"))
        .transpose()?;
    let study = SimParams::default();
    let sim = SimParams {
        dt,
        load: mn_to_n(1.0),
        equilibrate_time: us_to_s(a.dem_equilibrate_us),
        relax_time: us_to_s(a.dem_relax_us),
        slide_time: us_to_s(a.dem_slide_us),
        support_speed: a.dem_speed_m_s,
        ..SimParams::default()
    };
    let dem_is_study_protocol = sim.equilibrate_time == study.equilibrate_time
        && sim.relax_time == study.relax_time
        && sim.slide_time == study.slide_time
        && sim.support_speed == study.support_speed;
    let dem = DemParams {
        sim,
        alpha: 0.0,
        line,
        start: Start::Surrogate,
        friction: None,
        io: RunIo {
            checkpoint: None,
            checkpoint_every: 50_000,
            xyz: None,
            xyz_every: 10_000,
        },
        resume: None,
        model: ModelSpec {
            request: a.dem_model.request(),
            ..ModelSpec::default()
        },
    };
    let dem_shard = match &a.shard {
        Some(t) => {
            if a.no_dem {
                bail!("`--shard`: shards the DEM confirmation runs, but --no-dem skips them");
            }
            crate::runs::shard::Shard::parse(t, "--shard")?
        }
        None => crate::runs::shard::Shard::ALL,
    };
    let (theta_tol_deg, direction_tol_deg) = a.tol.checked()?;
    let theta_tol_step_deg = checks::positive(a.theta_tol_step, "--theta-tol-step-deg")?;
    let direction_tol_step_deg =
        checks::positive(a.direction_tol_step, "--direction-tol-step-deg")?;
    let seeds: Vec<u64> = match &a.seeds {
        None => Vec::new(),
        Some(t) => t
            .split(',')
            .map(|x| {
                x.trim().parse::<u64>().map_err(|_| {
                    anyhow::anyhow!(
                        "`--seeds`: `{}` is not a non-negative integer seed",
                        x.trim()
                    )
                })
            })
            .collect::<Result<_>>()?,
    };
    let params = DesignParams {
        theta_tol_deg,
        direction_tol_deg,
        theta_tol_step_deg,
        direction_tol_step_deg,
        seeds,
        thetas_deg,
        theta_text,
        theta_default: a.theta.is_none(),
        symmetry_cut: !a.no_symmetry_cut,
        loads,
        mu_superlubric: a.mu_superlubric,
        per_level: a.per_level,
        max_top: a.max_top,
        alpha_step_deg: step,
        alpha_refine_deg: refine,
        line,
        scan_length,
        scan_step,
        alphas_per_theta: a.alphas_per_theta,
        friction,
        confirm: a.confirm,
        confirm_loads,
        no_dem: a.no_dem,
        jobs,
        dem_shard,
        dem,
        dem_is_study_protocol,
        dem_flags: format!(" --model {}", a.dem_model.request().name()),
        dem_words: match a.dem_model {
            ModelArg::Reduced => "reduced model `--model reduced` (slider spheres rigid in z; unreachable substrate spheres left out and only the active set integrated, both exact)".into(),
            ModelArg::Full => "full model `--model full` (slider spheres on their z springs; pruning and the active set, both exact)".into(),
            ModelArg::FullExplicit => "full model by velocity-Verlet throughout `--model full-explicit` (slider spheres on their z springs; pruning and the active set, both exact)".into(),
            ModelArg::Auto => "`--model auto` (per run: the full model near coating failure, where stick-slip is expected or beyond the measured stiffness ratio, else rigid-z; the choice is in each run's JSON)".into(),
        },
        protocol_check: !a.no_protocol_check,
    };
    let scenes = scenes(a)?;
    for s in &scenes {
        let (_, sym) = cut(s, &params)?;
        let (lo, hi, _) = sym.domain();
        if 2.0 * params.theta_tol_deg >= hi - lo {
            bail!(
                "`--theta-tol-deg`: ±{}° spans the whole θ domain of {} ([{lo}°, {hi}°]); give a tolerance below {}°",
                params.theta_tol_deg,
                s.name,
                0.5 * (hi - lo)
            );
        }
        if !params.seeds.is_empty() && s.scene.substrate.sigma_h == 0.0 {
            bail!(
                "`--seeds`: {} has a flat substrate (σ_h = 0), so every seed gives the same one; give --sigma-h-um > 0 or leave --seeds out",
                s.name
            );
        }
    }
    check_outputs(&[("--out-dir", Some(&a.out.join("report.md")))])?;
    Ok((scenes, params))
}

/// Runs `superlube design`.
pub fn run(a: Args) -> Result<()> {
    let (scenes, params) = prepare(&a)?;
    let rep = Reporter::stderr();
    for s in &scenes {
        for w in &s.warnings {
            crate::runs::progress::Progress::note(&rep, &format!("warning: {}: {w}", s.name));
        }
    }
    if a.patterns.is_some() || a.family.is_some() {
        let mut n = [0usize; 4];
        for s in &scenes {
            let t = s.facts.as_ref().map_or("", |f| f.contact_type.as_str());
            n[crate::study::patterns::prescreen_class(t)] += 1;
        }
        crate::runs::progress::Progress::note(
            &rep,
            &format!(
                "design: {} candidates in the contact-type pre-screen's order: {} lubric (in every direction), {} directional, {} interlocked{}; index order within each",
                scenes.len(),
                n[0],
                n[1],
                n[2],
                if n[3] > 0 {
                    format!(", then {} unclassified", n[3])
                } else {
                    String::new()
                }
            ),
        );
    }
    let t0 = std::time::Instant::now();
    let store = Store::new(&a.out).labelled("--out-dir");
    let record = crate::study::design::inputs(&scenes, &params, true);
    let files = crate::present::design_report::Writer::new(&store, &record, &params);
    let o = design(&scenes, &params, &store, &rep, &|pr| files.pattern(pr))?;
    if !params.dem_shard.is_all() {
        crate::runs::progress::Progress::note(
            &rep,
            &format!(
                "design: shard {}/{} of the DEM runs done in {:.1} s (no report from a shard)",
                params.dem_shard.index,
                params.dem_shard.count,
                t0.elapsed().as_secs_f64()
            ),
        );
        return Ok(());
    }
    crate::present::design_report::publish(files, &o, &rep)?;
    let failed = o.dem.iter().filter(|d| d.outcome.error.is_some()).count();
    crate::runs::progress::Progress::note(
        &rep,
        &format!(
            "design: done in {:.1} s; the answer is in {}{}",
            t0.elapsed().as_secs_f64(),
            a.out.join("report.md").display(),
            if failed > 0 {
                format!(" ({failed} DEM run(s) failed: see the report)")
            } else {
                String::new()
            }
        ),
    );
    Ok(())
}

#[cfg(test)]
#[path = "design_tests.rs"]
mod tests;

#[cfg(test)]
#[path = "design_answer_tests.rs"]
mod answer_tests;
