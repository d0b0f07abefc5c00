//! [`DesignParams`]: every knob of `superlube design`.

use crate::study::dem_run::DemParams;
use crate::study::load::Loads;
use surrogate::friction::FrictionParams;

/// One pattern pair of a design: its name (the pattern, or a scene file's stem; used in file
/// names), the validated scene (SI, θ = 0), the scene flags that reproduce it on another
/// command's command line, and the warnings to report.
#[derive(Debug, Clone)]
pub struct DesignScene {
    /// Name used in the report and the file names (`square-tri`, `my_scene`).
    pub name: String,
    /// The scene (SI); its `slider.theta` is ignored (θ is swept).
    pub scene: surrogate::Scene,
    /// Scene flags reproducing it (`--pattern square-tri --sigma-h-um 0.01`).
    pub flags: Vec<String>,
    /// Warnings about the scene (edge overhang…).
    pub warnings: Vec<String>,
    /// What `superlube patterns` recorded of it, when it comes from an `index.csv`.
    pub facts: Option<crate::study::patterns::CandidateFacts>,
    /// What the design knows of it as a recipe of `design --vary` (why it lies outside the
    /// validated range; the DEM decides such a recipe, [`super::confirm`]); `None`: not a
    /// recipe.
    pub recipe: Option<crate::study::recipe::RecipeFacts>,
}

/// Every knob of a design (SI inside; angles as the degree decimals the user meant, so that
/// every reproduction command prints them exactly).
#[derive(Debug, Clone)]
pub struct DesignParams {
    /// Orientations θ (degrees) as given, before the symmetry cut.
    pub thetas_deg: Vec<f64>,
    /// The `--theta` text (for messages).
    pub theta_text: String,
    /// `--theta` was not given: `thetas_deg` is the default `0:30:0.1`, and a pattern whose
    /// domain it does not span is screened over its whole domain
    /// ([`super::default_domain`]).
    pub theta_default: bool,
    /// Cut θ to the pattern's fundamental domain ([`super::symmetry_words`]).
    pub symmetry_cut: bool,
    /// Normal loads W (N), strictly increasing: the load ladder of every stage.
    pub loads: Loads,
    /// Friction coefficient below which a design counts as superlubric (study: 0.02).
    pub mu_superlubric: f64,
    /// Orientations kept per lower load level of the shortlist ([`super::shortlist`]).
    pub per_level: usize,
    /// Most orientations kept at the top level (all that survive the highest load, up to this).
    pub max_top: usize,
    /// Coarse α grid step (degrees) of the scan over [0, P_α).
    pub alpha_step_deg: f64,
    /// Successive finer α steps (degrees), each scanned over ± half the previous step around
    /// the best α so far.
    pub alpha_refine_deg: Vec<f64>,
    /// Contact-line angle (rad from x) for every θ; `None`: the moiré estimate.
    pub line: Option<f64>,
    /// Length (m) of the α-scan paths.
    pub scan_length: f64,
    /// Sample spacing (m) of the α-scan paths.
    pub scan_step: f64,
    /// Pulling angles per orientation whose friction is estimated (the lowest-corrugation
    /// local minima of the scan, ≥ one refine window apart).
    pub alphas_per_theta: usize,
    /// The friction estimate's knobs.
    pub friction: FrictionParams,
    /// Fabrication tolerance of θ (degrees, ≥ 0): the robust limit holds for every θ within
    /// ± this of the nominal ([`crate::study::tolerance`]).
    pub theta_tol_deg: f64,
    /// Tolerance of the pulling direction in the substrate frame (degrees, ≥ 0).
    pub direction_tol_deg: f64,
    /// Largest sampling step of the θ tolerance (degrees): a window narrower than it cannot
    /// pass (the first sample off the nominal is at most one step away).
    pub theta_tol_step_deg: f64,
    /// Largest sampling step of the direction tolerance (degrees).
    pub direction_tol_step_deg: f64,
    /// Substrate seeds evaluated for the robust limit besides the scene's own (σ_h > 0 only).
    pub seeds: Vec<u64>,
    /// Designs per pattern confirmed with the DEM (0 only with `no_dem`).
    pub confirm: usize,
    /// Loads (N) of the DEM confirmation, each one of `loads`.
    pub confirm_loads: Vec<f64>,
    /// Stop before the DEM.
    pub no_dem: bool,
    /// DEM runs side by side (one thread each).
    pub jobs: usize,
    /// Shard of the DEM confirmation runs to compute ([`crate::runs::shard::Shard::ALL`]: every
    /// run, then the report). With a part, the design computes its share of the runs into
    /// `--out-dir/dem/` and stops before the report; a call without a shard (all shards' `dem/`
    /// runs in the same `--out-dir`) reuses them and writes the report.
    pub dem_shard: crate::runs::shard::Shard,
    /// The DEM protocol of every confirmation run (α and line are set per run).
    pub dem: DemParams,
    /// The study's protocol (10 + 10 + 300 µs) is used; otherwise the report says it is shorter.
    pub dem_is_study_protocol: bool,
    /// Also run the study protocol on the best design at the middle confirmation load, to
    /// measure the shorter protocol's friction difference (only when the protocol is shorter).
    pub protocol_check: bool,
    /// The yield of each answer over fabrication ([`super::yield_stage`]); `None`: the stage
    /// does not run (the default: its DEM decisions take minutes per answer).
    pub fab_yield: Option<super::yield_params::YieldStageParams>,
}
