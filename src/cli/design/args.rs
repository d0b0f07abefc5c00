//! The flags of `superlube design` ([`Args`]) and their shared defaults.

use super::yield_args;
use crate::cli::dem_args::ModelArg;
use crate::cli::friction_args::FrictionKnobArgs;
use crate::cli::point_args::{help, StudyLoads, Thetas, LOAD, THETA};
use crate::cli::tolerance_args::ToleranceArgs;
use crate::cli::verdict_args::VerdictArgs;
use crate::cli::SceneOverrides;
use std::path::PathBuf;

/// Options of `superlube design`.
#[derive(clap::Args, Debug)]
#[command(
    mut_args(help(
        THETA,
        "Orientations θ in degrees (list or range start:stop:step), cut to each pattern's \
         fundamental domain (square-tri 0–15°, tri-tri 0–30°: docs/commands/design.md); a \
         list that does not span a domain is named in the log and the report [default: \
         0:30:0.1, and for a pattern whose domain it does not span (no derived symmetry, or a \
         domain wider than 30°) the whole domain at 0.1°, or 0.25° when wider than 60°]"
    )),
    mut_args(help(
        LOAD,
        "Normal loads W in mN, strictly increasing (list or range) [default: the study's \
         0.35, 0.70, …, 3.50, 3.86]"
    ))
)]
pub struct Args {
    /// Pattern pairs to design, comma-separated: tri-tri, square-tri, square-square, tri-square
    /// (the study's geometry) [default: square-tri,tri-tri unless --scene is given].
    #[arg(long, value_name = "P1,P2")]
    pub(super) pattern: Option<String>,
    /// A scene file (TOML, user units; README "Scenes") to design, repeatable (`--scene a.toml
    /// --scene b.toml`); named after the file stem in the outputs. The override flags below
    /// apply to every pattern and scene.
    #[arg(long, value_name = "FILE.toml")]
    pub(super) scene: Vec<PathBuf>,
    /// An index.csv of `superlube patterns`: designs every candidate's scene file (named by its
    /// pattern_id), as if each were given with --scene; the ranking spans all of them.
    #[arg(long, value_name = "INDEX.csv", conflicts_with = "family")]
    pub(super) patterns: Option<PathBuf>,
    /// A lattice family (as `superlube patterns --family`: `directional`, `presets[:s=…]`,
    /// `rectangular:a=…,b=…`, `oblique:a=…,b=…,gamma_deg=…`): its candidates over the substrate
    /// of the one --pattern or --scene given (default square-tri) are written to
    /// OUT/patterns/ (equal slider area unless --fair count, p, q ≤ 3, orders ≤ 4; run
    /// `superlube patterns` for other knobs) and designed as with --patterns
    /// OUT/patterns/index.csv.
    #[arg(long, value_name = "SPEC")]
    pub(super) family: Option<String>,
    /// Scene override flags, applied to every pattern and scene.
    #[command(flatten)]
    pub(super) overrides: SceneOverrides,
    /// Recipe flags (`--vary`, `--fair`, `--skip-invalid`): scene fields as design variables.
    #[command(flatten)]
    pub(super) recipe: crate::cli::recipe_args::RecipeArgs,
    /// `--theta-deg`: θ, a list or range (degrees).
    #[command(flatten)]
    pub(super) theta: Thetas,
    /// Screen θ as given, without the symmetry cut (for scenes whose symmetry is broken, e.g.
    /// by --offset-um).
    #[arg(long = "no-symmetry-cut")]
    pub(super) no_symmetry_cut: bool,
    /// `--load-mn`: the load ladder, a list or range (mN).
    #[command(flatten)]
    pub(super) load: StudyLoads,
    #[command(flatten)]
    pub(super) verdict: VerdictArgs,
    /// Orientations kept per lower load level of the shortlist (those with the lowest P_max).
    /// How the default was chosen: docs/commands/design.md "The shortlist rule".
    #[arg(long = "per-level", value_name = "N", default_value_t = 6)]
    pub(super) per_level: usize,
    /// Most orientations kept from the top level (those surviving the highest load).
    #[arg(long = "max-top", value_name = "N", default_value_t = 40)]
    pub(super) max_top: usize,
    /// Coarse step in degrees of the α scan over one α period (square-tri: 180°, tri-tri: 60°).
    #[arg(
        long = "alpha-step-deg",
        value_name = "DEG",
        default_value_t = 15.0,
        allow_hyphen_values = true
    )]
    pub(super) alpha_step_deg: f64,
    /// Successive finer α steps in degrees, each scanned over ± half the previous step around
    /// the best α so far (comma list, decreasing; `none` for no refinement).
    #[arg(
        long = "alpha-refine-deg",
        value_name = "DEG,DEG",
        default_value = "2.5,0.5",
        allow_hyphen_values = true
    )]
    pub(super) alpha_refine_deg: String,
    /// Contact-line angle in degrees from the substrate x axis for every θ [default: the moiré
    /// estimate at each θ, as in `corrugation` and `slide`].
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    pub(super) line_deg: Option<f64>,
    /// Length in µm of each α-scan path.
    #[arg(
        long = "scan-distance-um",
        alias = "scan-um",
        value_name = "UM",
        default_value_t = 6.0,
        allow_hyphen_values = true
    )]
    pub(super) scan_um: f64,
    /// Sample spacing in µm along the α-scan paths.
    #[arg(
        long = "scan-step-um",
        value_name = "UM",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    pub(super) scan_step_um: f64,
    /// Pulling angles per orientation whose friction is estimated (the lowest-corrugation
    /// minima of the α scan, at least one coarse step apart).
    #[arg(long = "best-alphas", value_name = "N", default_value_t = 1)]
    pub(super) alphas_per_theta: usize,
    #[command(flatten)]
    pub(super) friction: FrictionKnobArgs,
    #[command(flatten)]
    pub(super) tol: ToleranceArgs,
    /// Largest sampling step in degrees of the θ tolerance: the first sample off the nominal is
    /// at most this far, so a window narrower than the tolerance cannot pass.
    #[arg(
        long = "theta-tol-step-deg",
        alias = "theta-tol-step",
        value_name = "DEG",
        default_value_t = 0.02,
        allow_hyphen_values = true
    )]
    pub(super) theta_tol_step: f64,
    /// Largest sampling step in degrees of the direction tolerance.
    #[arg(
        long = "direction-tol-step-deg",
        alias = "direction-tol-step",
        value_name = "DEG",
        default_value_t = 0.25,
        allow_hyphen_values = true
    )]
    pub(super) direction_tol_step: f64,
    /// Further substrate seeds (comma list) besides the scene's own (`--seed`), whose height
    /// realisations the robust limit must also hold on (σ_h > 0 only): the worst case counts.
    /// (`--seeds` in `slide` and `figures --friction` is the whole list, replacing `--seed`.)
    #[arg(long = "extra-seeds", alias = "seeds", value_name = "S1,S2")]
    pub(super) seeds: Option<String>,
    /// Designs per pattern confirmed with DEM `slide` runs (the top of the ranking; ≥ 1 unless
    /// --no-dem).
    #[arg(long, value_name = "K", default_value_t = 3)]
    pub(super) confirm: usize,
    /// Loads in mN of the DEM confirmation, each one of --load-mn [default: the lowest, the
    /// middle and the highest load].
    #[arg(
        long = "confirm-loads-mn",
        alias = "confirm-loads",
        value_name = "MN",
        allow_hyphen_values = true
    )]
    pub(super) confirm_loads: Option<String>,
    /// Stop before the DEM confirmation (surrogate tiers only).
    #[arg(long = "no-dem")]
    pub(super) no_dem: bool,
    /// DEM runs side by side, one thread each [default: the number of CPU cores].
    #[arg(long, value_name = "N")]
    pub(super) jobs: Option<usize>,
    /// Compute only shard I of N (zero-based) of the DEM confirmation runs, e.g. on N machines
    /// or Slurm tasks, into `--out-dir`/dem/, and stop before the report; then run the same
    /// command without `--shard` on one `--out-dir` holding every shard's `dem/` runs: it reuses
    /// them and writes the report.
    #[arg(long, value_name = "I/N")]
    pub(super) shard: Option<String>,
    /// Equilibration in µs of each confirmation run (study: 10).
    #[arg(
        long = "dem-equilibrate-us",
        value_name = "US",
        default_value_t = 2.0,
        allow_hyphen_values = true
    )]
    pub(super) dem_equilibrate_us: f64,
    /// Relaxation in µs with the pulling spring attached (study: 10).
    #[arg(
        long = "dem-relax-us",
        value_name = "US",
        default_value_t = 2.0,
        allow_hyphen_values = true
    )]
    pub(super) dem_relax_us: f64,
    /// Sliding time in µs of each confirmation run; friction over its last two thirds (study:
    /// 300).
    #[arg(
        long = "dem-slide-us",
        value_name = "US",
        default_value_t = 60.0,
        allow_hyphen_values = true
    )]
    pub(super) dem_slide_us: f64,
    /// Support speed in m/s (study: 0.1).
    #[arg(
        long = "dem-speed-m-s",
        value_name = "M_S",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    pub(super) dem_speed_m_s: f64,
    /// DEM time step in µs [default: 0.25 × the stable-step estimate].
    #[arg(long = "dem-dt-us", value_name = "US", allow_hyphen_values = true)]
    pub(super) dem_dt_us: Option<f64>,
    /// DEM model of the confirmation runs (as `slide --model`): `reduced` (rigid-z, default;
    /// its accuracy: docs/validation/dem-engine.md "Model choice"), `auto` (the full model near
    /// coating failure and where stick-slip is expected; its cost:
    /// docs/validation/dem-integrator.md) or `full`. Pruning and the active set (exact) are on
    /// in every model.
    #[arg(long = "dem-model", value_enum, default_value_t = ModelArg::Reduced)]
    pub(super) dem_model: ModelArg,
    /// Do not run the best design once more with the study's protocol (10 + 10 + 300 µs) to
    /// measure the shorter protocol's friction difference.
    #[arg(long = "no-protocol-check")]
    pub(super) no_protocol_check: bool,
    /// The yield stage (on by default; `--no-yield`).
    #[command(flatten)]
    pub(super) fab_yield: yield_args::YieldArgs,
    /// Output directory: report.md, ranking.csv, the CSVs and PNGs behind them, dem/ (the DEM
    /// runs) and stages/ (finished stages, reused by a re-run with the same inputs).
    #[arg(
        long = "out-dir",
        alias = "out",
        value_name = "DIR",
        default_value = "design"
    )]
    pub(super) out: PathBuf,
}
