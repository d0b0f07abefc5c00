//! Options and the run loop shared by `superlube equilibrate` and `superlube slide` (the DEM
//! tier): scene → [`dem::prepare`] → [`dem::protocol::run`] (progress bar, checkpoints,
//! snapshots) → time series and summary files.

use super::corrugation::{check_alpha, check_line_deg};
use super::SceneArgs;
use crate::output::{csv_text, write_atomic, write_or_stdout};
use anyhow::{bail, Context, Result};
use dem::model::{Constant, Friction};
use dem::protocol::{run, step_counts, Progress, RunIo, RunKind, Sample};
use dem::{prepare, Prepared, SimParams, Start};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use serde::Serialize;
use std::path::PathBuf;
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::units::{deg_to_rad, mn_to_n, rad_to_deg, s_to_us, us_to_s, NM};
use surrogate::Scene;

/// How the slider starts.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum StartKind {
    /// At the surrogate's quasi-static equilibrium height (contacts already loaded): short
    /// equilibration.
    Surrogate,
    /// Resting `--gap-nm` above first touch, falling under the load.
    Gap,
}

/// Which DEM model (`--model`).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelArg {
    /// The cheapest model within its measured error for this scene (reason printed).
    Auto,
    /// Slider spheres on their k_z springs.
    Full,
    /// Rigid-z: slider spheres rigid in z on the control layer.
    Reduced,
}

/// DEM options shared by `equilibrate` and `slide`.
#[derive(clap::Args, Debug)]
pub struct DemArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Slider orientation θ in degrees [default: the scene file's theta_deg, else 0].
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub theta: Option<f64>,
    /// Normal load W in mN.
    #[arg(
        long = "load-mn",
        value_name = "MN",
        default_value_t = 1.4,
        allow_hyphen_values = true
    )]
    pub load_mn: f64,
    /// Pulling angle α in degrees from the slider's contact line (as in `superlube corrugation`),
    /// |α| ≤ 180: α = 90 pulls perpendicular to the contact lines. The pulling direction from the
    /// substrate x axis is line + α; both are printed and reported in the JSON summary.
    #[arg(
        long,
        value_name = "DEG",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    pub alpha: f64,
    /// Contact-line angle in degrees from the substrate x axis. Default: the moiré estimate of
    /// `superlube corrugation` (square-tri at θ = 0: along x, 0°; the substrate row a1 when the
    /// lattices are commensurate).
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    pub line_deg: Option<f64>,
    /// Equilibration time under load in µs (control layer held laterally).
    #[arg(
        long = "equilibrate-us",
        value_name = "US",
        default_value_t = 10.0,
        allow_hyphen_values = true
    )]
    pub equilibrate_us: f64,
    /// Time step in µs [default: 0.25 × the estimated stable step, printed at start].
    #[arg(long = "dt-us", value_name = "US", allow_hyphen_values = true)]
    pub dt_us: Option<f64>,
    /// Start at the surrogate's equilibrium or from a gap.
    #[arg(long, value_enum, default_value_t = StartKind::Surrogate)]
    pub start: StartKind,
    /// Gap in nm above first touch for `--start gap`.
    #[arg(long = "gap-nm", value_name = "NM", default_value_t = 20.0)]
    pub gap_nm: f64,
    /// Model: auto picks rigid-z where its measured error is small for this scene (the choice
    /// and its reason are printed and in the JSON); pruning and the active set are exact and on
    /// in every model.
    #[arg(long, value_enum, default_value_t = ModelArg::Auto)]
    pub model: ModelArg,
    /// Reduction: slider spheres move rigidly with the control layer in z (replaces the stiff
    /// 10⁶ N/m z-springs; allows a ~30× larger time step). Same as `--model reduced`.
    #[arg(long = "rigid-z")]
    pub rigid_z: bool,
    /// Reduction: leave out substrate spheres that the slider can never touch along its path
    /// (exact; on in every `--model`, kept for compatibility).
    #[arg(long)]
    pub prune: bool,
    /// Integrate every particle every step instead of only the active set (the active set is
    /// exact to round-off; this is for comparisons and timing).
    #[arg(long = "no-active-set")]
    pub no_active_set: bool,
    /// Constant friction coefficient for every contact instead of the coating's pressure-switched
    /// μ1/μ2 (reference runs).
    #[arg(long, value_name = "MU")]
    pub mu: Option<f64>,
    /// Sampling interval of the time series in µs.
    #[arg(long = "sample-us", value_name = "US", default_value_t = 0.1)]
    pub sample_us: f64,
    /// Time-series CSV (written atomically); stdout if absent.
    #[arg(long, value_name = "FILE.csv")]
    pub out: Option<PathBuf>,
    /// JSON summary file (written atomically); printed to stdout if absent and `--out` is given.
    #[arg(long, value_name = "FILE.json")]
    pub json: Option<PathBuf>,
    /// Checkpoint file, written atomically every `--checkpoint-every` steps.
    #[arg(long, value_name = "FILE")]
    pub checkpoint: Option<PathBuf>,
    /// Steps between checkpoints.
    #[arg(
        long = "checkpoint-every",
        value_name = "STEPS",
        default_value_t = 100_000
    )]
    pub checkpoint_every: u64,
    /// Continue from `--checkpoint` if it exists (same inputs required; bit-identical result).
    #[arg(long, requires = "checkpoint")]
    pub resume: bool,
    /// Extended-XYZ snapshot file (OVITO reads it); one frame every `--xyz-every` steps.
    #[arg(long, value_name = "FILE.xyz")]
    pub xyz: Option<PathBuf>,
    /// Steps between snapshots.
    #[arg(long = "xyz-every", value_name = "STEPS", default_value_t = 10_000)]
    pub xyz_every: u64,
}

/// Run facts reported in every JSON summary.
#[derive(Debug, Serialize)]
#[allow(non_snake_case)]
pub struct RunInfo {
    /// Time step used (µs).
    pub dt_us: f64,
    /// Estimated critical step (µs) and its dominating mode.
    pub dt_crit_us: f64,
    /// Mode that sets the critical step.
    pub dt_crit_mode: &'static str,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Contact-line angle from the substrate x axis (degrees).
    pub line_deg: f64,
    /// Pulling direction from the substrate x axis = line + α (degrees).
    pub direction_deg: f64,
    /// Moving particles (substrate + slider + control body).
    pub particles: usize,
    /// Substrate spheres left out by `--prune`.
    pub pruned_substrate: usize,
    /// Particle-steps per wall second.
    pub particle_steps_per_s: f64,
    /// Reductions in use.
    pub rigid_z: bool,
    /// Substrate pruning in use.
    pub prune: bool,
    /// Model in use (`full` or `reduced`) and what was asked for (`--model`).
    pub model: &'static str,
    /// `--model` as given.
    pub model_requested: &'static str,
    /// Why this model: the rigid-z criterion and the exact reductions.
    pub model_reason: String,
    /// Active set in use.
    pub active_set: bool,
    /// Mean number of particles integrated per step (active set; all otherwise).
    pub mean_active_particles: f64,
}

/// A finished run: the engine, its samples and facts.
pub struct Finished {
    pub prepared: Prepared,
    pub samples: Vec<Sample>,
    pub steps_this_process: u64,
    pub wall_s: f64,
    pub info: RunInfo,
}

fn positive(v: f64, field: &str) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        bail!("`{field}`: {v} must be a positive number")
    }
}

impl DemArgs {
    /// The scene (with θ applied) and the knobs; `relax_us`/`slide_us`/`speed` only for slide.
    pub fn setup(&self, relax_us: f64, slide_us: f64, speed: f64) -> Result<(Scene, SimParams)> {
        let file = self.scene.scene_file()?;
        let mut scene = file.into_scene()?;
        let theta = self.theta.or(file.slider.theta_deg).unwrap_or(0.0);
        if !theta.is_finite() {
            bail!("`--theta`: {theta} must be finite");
        }
        scene.slider.theta = deg_to_rad(theta);
        positive(self.load_mn, "--load-mn")?;
        let alpha = check_alpha(self.alpha)?;
        let line = match check_line_deg(self.line_deg)? {
            Some(l) => l,
            None => contact_line_direction(&scene, scene.slider.theta, &MapParams::default()).angle,
        };
        let direction = line + alpha;
        positive(self.equilibrate_us, "--equilibrate-us")?;
        positive(self.sample_us, "--sample-us")?;
        if let Some(dt) = self.dt_us {
            positive(dt, "--dt-us")?;
        }
        if let Some(mu) = self.mu {
            if !(mu.is_finite() && mu >= 0.0) {
                bail!("`--mu`: {mu} must be a non-negative number");
            }
        }
        let mut p = SimParams {
            dt: self.dt_us.map(us_to_s),
            load: mn_to_n(self.load_mn),
            alpha: direction,
            equilibrate_time: us_to_s(self.equilibrate_us),
            relax_time: us_to_s(relax_us),
            slide_time: us_to_s(slide_us),
            support_speed: speed,
            sample_interval: us_to_s(self.sample_us),
            ..SimParams::default()
        };
        self.model_choice(&scene, &p)?.apply(&mut p);
        Ok((scene, p))
    }

    /// The model for `scene` and `p` per `--model`, `--rigid-z` and `--no-active-set`.
    pub fn model_choice(&self, scene: &Scene, p: &SimParams) -> Result<dem::ModelChoice> {
        let request = match self.model {
            ModelArg::Auto => dem::ModelRequest::Auto,
            ModelArg::Full => dem::ModelRequest::Full,
            ModelArg::Reduced => dem::ModelRequest::Reduced,
        };
        let mut c = dem::choose_model(scene, p, request)?;
        if self.rigid_z && !c.rigid_z {
            c.rigid_z = true;
            c.model = "reduced";
            c.reason = format!("rigid-z forced by --rigid-z (κ = {:.4})", c.stiffness_ratio);
        }
        if self.no_active_set {
            c.active_set = false;
            c.reason.push_str("; active set off (--no-active-set)");
        }
        Ok(c)
    }

    /// Prepares, resumes if asked, runs `kind` with a progress bar, writes the time series.
    pub fn execute(&self, scene: &Scene, params: SimParams, kind: RunKind) -> Result<Finished> {
        let start = match self.start {
            StartKind::Surrogate => Start::Surrogate,
            StartKind::Gap => Start::Gap(positive(self.gap_nm, "--gap-nm")? * NM),
        };
        let friction = self.mu.map(|mu| Friction::Constant(Constant { mu }));
        let choice = self.model_choice(scene, &params)?;
        eprintln!("model: {} ({})", choice.model, choice.reason);
        let mut prepared = prepare(scene, params, start, friction)?;
        let sim = &mut prepared.sim;
        eprintln!(
            "stable step estimate: {:.4e} µs ({}); using dt = {:.4e} µs; {} particles ({} substrate spheres pruned)",
            s_to_us(prepared.stable.dt_crit),
            prepared.stable.mode,
            s_to_us(sim.dt),
            sim.particles(),
            prepared.start.pruned
        );
        eprintln!(
            "pulling direction: {:.3}° from x = contact line {:.3}° ({}) + α {:.3}°",
            rad_to_deg(sim.params.alpha),
            rad_to_deg(sim.params.alpha) - self.alpha,
            if self.line_deg.is_some() {
                "given by --line-deg"
            } else {
                "moiré estimate"
            },
            self.alpha
        );
        if sim.dt > prepared.stable.dt_crit {
            eprintln!(
                "warning: dt = {:.4e} µs exceeds the stable step estimate {:.4e} µs; the run will stop if it blows up",
                s_to_us(sim.dt),
                s_to_us(prepared.stable.dt_crit)
            );
        }
        let mut samples = Vec::new();
        if self.resume {
            let path = self
                .checkpoint
                .as_ref()
                .expect("clap: --resume requires --checkpoint");
            if path.exists() {
                samples = dem::checkpoint::load(path, sim)
                    .with_context(|| format!("resuming from {}", path.display()))?;
                eprintln!(
                    "resumed at step {} (t = {:.3} µs)",
                    sim.state.step,
                    s_to_us(sim.state.t)
                );
            } else {
                eprintln!("no checkpoint at {} yet: starting fresh", path.display());
            }
        }
        let (ne, nr, ns, _) = step_counts(sim, kind);
        let total = ne + nr + ns;
        let first = sim.state.step;
        let pb = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
        pb.set_style(
            ProgressStyle::with_template(
                "{prefix} {bar:30} {percent:>3}% t = {msg} µs [{elapsed_precise} < {eta_precise}]",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        pb.set_prefix(match kind {
            RunKind::Equilibrate => "equilibrate",
            RunKind::Slide => "slide",
        });
        pb.set_position(first);
        let io = RunIo {
            checkpoint: self.checkpoint.clone(),
            checkpoint_every: self.checkpoint_every,
            xyz: self.xyz.clone(),
            xyz_every: self.xyz_every,
        };
        let t0 = std::time::Instant::now();
        let res = run(sim, kind, &io, &mut samples, &mut |p: &Progress| {
            pb.set_position(p.step);
            pb.set_message(format!(
                "{:.2}/{:.2}",
                p.sample.t_us,
                s_to_us(sim_total_time(total, p))
            ));
        });
        pb.finish_and_clear();
        let wall_s = t0.elapsed().as_secs_f64();
        // Whatever happened, keep the time series computed so far.
        write_or_stdout(self.out.as_deref(), &csv_text(&samples)?)?;
        res?;
        let steps = sim.state.step - first;
        let direction_deg = rad_to_deg(sim.params.alpha);
        let info = RunInfo {
            alpha_deg: self.alpha,
            line_deg: direction_deg - self.alpha,
            direction_deg,
            dt_us: s_to_us(sim.dt),
            dt_crit_us: s_to_us(prepared.stable.dt_crit),
            dt_crit_mode: prepared.stable.mode,
            particles: sim.particles(),
            pruned_substrate: prepared.start.pruned,
            particle_steps_per_s: steps as f64 * sim.particles() as f64 / wall_s.max(1e-9),
            rigid_z: sim.params.rigid_z,
            prune: sim.params.prune_substrate,
            model: choice.model,
            model_requested: choice.requested,
            model_reason: choice.reason,
            active_set: sim.params.active_set,
            mean_active_particles: sim.state.stats.particle_steps as f64
                / sim.state.step.max(1) as f64
                + 1.0,
        };
        Ok(Finished {
            prepared,
            samples,
            steps_this_process: steps,
            wall_s,
            info,
        })
    }

    /// Writes the JSON summary to `--json`, or to stdout when the time series went to `--out`.
    pub fn write_summary<T: Serialize>(&self, summary: &T) -> Result<()> {
        let text = serde_json::to_string_pretty(summary)? + "\n";
        match (&self.json, &self.out) {
            (Some(p), _) => write_atomic(p, text.as_bytes()),
            (None, Some(_)) => {
                print!("{text}");
                Ok(())
            }
            (None, None) => {
                eprint!("{text}");
                Ok(())
            }
        }
    }
}

fn sim_total_time(total: u64, p: &Progress) -> f64 {
    // simulated end time (s) from the current sample's time per step
    if p.step == 0 {
        0.0
    } else {
        us_to_s(p.sample.t_us) / p.step as f64 * total as f64
    }
}
