//! The DEM run shared by the equilibrate and slide workflows: scene → [`dem::prepare`] →
//! (resume from a checkpoint) → [`dem::protocol::run()`] with progress (phase, simulated time) →
//! the time series and the run facts. The summaries are made by [`super::equilibrate`] and
//! [`super::slide`].

use super::corrugation::{contact_line, LineChoice};
use super::rows::{label, DemCase, DemSample, RunInfo};
use crate::runs::progress::Progress;
use anyhow::{Context, Result};
use dem::model::Friction;
use dem::protocol::{run, step_counts, Phase, RunIo, RunKind};
use dem::{
    choose_model_at, prepare_at, ModelChoice, ModelRequest, Nominal, Prepared, SimParams, Start,
};
use std::path::PathBuf;
use surrogate::friction::TiltResonance;
use surrogate::units::{n_to_mn, rad_to_deg, s_to_us};
use surrogate::Scene;

/// Parameters of a DEM run (SI).
#[derive(Debug, Clone)]
pub struct DemParams {
    /// Every engine knob. Its `alpha` (pulling direction from the x axis) is set by the run to
    /// contact line + [`DemParams::alpha`].
    pub sim: SimParams,
    /// Pulling angle α from the slider's contact line (rad).
    pub alpha: f64,
    /// Contact-line angle (rad from x); `None`: the moiré estimate.
    pub line: Option<f64>,
    /// How the slider starts.
    pub start: Start,
    /// A friction law replacing the coating's pressure-switched μ (e.g. constant μ).
    pub friction: Option<Friction>,
    /// Checkpoints and snapshots.
    pub io: RunIo,
    /// Continue from this checkpoint if it exists (same inputs; bit-identical result).
    pub resume: Option<PathBuf>,
    /// Which model runs (`--model`, with the CLI's overrides); decides `sim.rigid_z`,
    /// `sim.prune_substrate` and `sim.active_set`.
    pub model: ModelSpec,
}

/// The model asked for: `--model auto|full|reduced`, plus `--rigid-z` (force rigid-z) and
/// `--no-active-set` (integrate every particle).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModelSpec {
    /// auto (default), full or reduced.
    pub request: ModelRequest,
    /// Rigid-z whatever `request` decides (the old `--rigid-z` flag).
    pub force_rigid_z: bool,
    /// Use the active set (exact to round-off; off only for comparisons and timing).
    pub active_set: bool,
}

impl Default for ModelSpec {
    fn default() -> Self {
        ModelSpec {
            request: ModelRequest::Auto,
            force_rigid_z: false,
            active_set: true,
        }
    }
}

/// The reductions for `scene` and `sim` (pulling direction already set) per `spec`, with the
/// reason ([`dem::choose_model_at`] from the run's `nominal` solve; costs, for `auto` with
/// sliding, the Prandtl–Tomlinson path of ~40 solves).
pub fn choose(scene: &Scene, sim: &SimParams, spec: ModelSpec, nominal: &Nominal) -> ModelChoice {
    let mut c = choose_model_at(scene, sim, spec.request, nominal);
    if spec.force_rigid_z && !c.rigid_z {
        c.rigid_z = true;
        c.model = "reduced";
        c.reason = format!("rigid-z forced (κ = {:.4})", c.stiffness_ratio);
    }
    if !spec.active_set {
        c.active_set = false;
        c.reason.push_str("; active set off (asked for)");
    }
    c
}

/// A finished (or failed) DEM run.
pub struct DemOutcome {
    /// The engine and its start facts.
    pub prepared: Prepared,
    /// The time series (also when the run failed: everything sampled until then).
    pub samples: Vec<DemSample>,
    /// Steps taken by this process (after a resume: since the checkpoint).
    pub steps_this_process: u64,
    /// Wall time of this process's steps (s).
    pub wall_s: f64,
    /// Run facts for the summary.
    pub info: RunInfo,
    /// Pattern, θ, W.
    pub case: DemCase,
    /// Why the run stopped early, if it did.
    pub error: Option<dem::DemError>,
}

/// The pulling direction (rad from x) of `p` for `scene`, and the line it is measured from.
pub fn direction(scene: &Scene, p: &DemParams) -> (LineChoice, f64) {
    let line = contact_line(scene, p.line);
    (line, line.angle + p.alpha)
}

fn phase_name(p: Phase) -> &'static str {
    match p {
        Phase::Equilibrate => "equilibrate",
        Phase::Relax => "relax",
        Phase::Slide => "slide",
    }
}

/// Prepares, resumes if asked, and runs protocol `kind` of `scene` with `p`, reporting the
/// phase and simulated time through `progress`. Errors before the first step (bad inputs, a
/// checkpoint that does not match) are returned; a failure during the run is in
/// [`DemOutcome::error`] with the samples up to it.
pub fn run_dem(
    scene: &Scene,
    p: &DemParams,
    kind: RunKind,
    progress: &dyn Progress,
) -> Result<DemOutcome> {
    let (line, dir) = direction(scene, p);
    let mut sim_params = p.sim.clone();
    sim_params.protocol.alpha = dir;
    // the surrogate's equilibrium at the load: solved once, for the model choice and the start
    let nominal = Nominal::solve(scene, sim_params.protocol.load)?;
    let choice = choose(scene, &sim_params, p.model, &nominal);
    choice.apply(&mut sim_params);
    progress.note(&format!("model: {} ({})", choice.model, choice.reason));
    let tilt = TiltResonance::with_ties(
        scene,
        sim_params.mount.k_slider_xy,
        sim_params.mount.k_substrate_xy,
        sim_params.mount.control_sphere_radius,
    );
    // Only where the coating may fail while sliding (the auto model's test).
    if let Some(t) =
        tilt.filter(|t| t.expected() && p.friction.is_none() && choice.coating_may_fail)
    {
        progress.note(&format!(
            "note: {t}: where contacts fail, this run's friction depends strongly on K1 (tri-tri \
             30°, 2.45 mN: μ = 0.039 at the study's 10⁶ N/m, 0.107 at 10⁷; docs/validation/friction.md, \
             \"The mount's resonance\")"
        ));
    }
    let mut prepared = prepare_at(scene, sim_params, p.start, p.friction, &nominal)?;
    start_notes(&prepared, line, dir, p, progress);
    let sim = &mut prepared.sim;
    let mut samples = resume(p, sim, progress)?;
    let (ne, nr, ns, _) = step_counts(sim, kind);
    let total = ne + nr + ns;
    let first = sim.state.step;
    let t_end = s_to_us(total as f64 * sim.dt);
    progress.stage(
        match kind {
            RunKind::Equilibrate => "equilibrate",
            RunKind::Slide => "slide",
        },
        total,
        "steps",
    );
    progress.update(
        first,
        &format!(
            "{}, t = {:.2}/{:.2} µs",
            phase_name(Phase::of_step(first, ne, nr)),
            s_to_us(sim.state.t),
            t_end
        ),
    );
    let t0 = std::time::Instant::now();
    let res = run(sim, kind, &p.io, &mut samples, &mut |q| {
        progress.update(
            q.step,
            &format!(
                "{}, t = {:.2}/{:.2} µs",
                phase_name(q.phase),
                q.sample.t_us,
                t_end
            ),
        );
    });
    progress.finish();
    let wall_s = t0.elapsed().as_secs_f64();
    let steps = sim.state.step - first;
    let info = run_info(
        p,
        dir,
        &prepared,
        steps,
        wall_s,
        choice,
        tilt.map(|t| t.ratio),
    );
    let case = DemCase {
        pattern: scene.pattern.clone(),
        theta_deg: label(rad_to_deg(scene.slider.theta)),
        load_mn: label(n_to_mn(prepared.sim.params.protocol.load)),
    };
    Ok(DemOutcome {
        prepared,
        samples,
        steps_this_process: steps,
        wall_s,
        info,
        case,
        error: res.err(),
    })
}

/// Notes the stable step and dt, the particles, the pulling direction (`dir`, rad from x) and
/// the line it is measured from, and a dt beyond the stable step.
fn start_notes(
    prepared: &Prepared,
    line: LineChoice,
    dir: f64,
    p: &DemParams,
    progress: &dyn Progress,
) {
    let sim = &prepared.sim;
    progress.note(&format!(
        "stable step estimate: {:.4e} µs ({}); using dt = {:.4e} µs; {} particles ({} substrate spheres pruned)",
        s_to_us(prepared.stable.dt_crit),
        prepared.stable.mode,
        s_to_us(sim.dt),
        sim.particles(),
        prepared.start.pruned
    ));
    progress.note(&format!(
        "pulling direction: {:.3}° from x = contact line {:.3}° ({}) + α {:.3}°",
        rad_to_deg(dir),
        rad_to_deg(line.angle),
        if line.given {
            format!("given by {}", crate::study::input::Input::LineDeg)
        } else {
            "moiré estimate".to_string()
        },
        rad_to_deg(p.alpha)
    ));
    if sim.dt > prepared.stable.dt_crit {
        progress.note(&format!(
            "warning: dt = {:.4e} µs exceeds the stable step estimate {:.4e} µs; the run will stop if it blows up",
            s_to_us(sim.dt),
            s_to_us(prepared.stable.dt_crit)
        ));
    }
}

/// The samples of the checkpoint `p.resume` restored into `sim` (noted), or none when there is
/// no checkpoint (yet).
fn resume(p: &DemParams, sim: &mut dem::Sim, progress: &dyn Progress) -> Result<Vec<DemSample>> {
    let mut samples = Vec::new();
    if let Some(path) = &p.resume {
        if path.exists() {
            samples = dem::checkpoint::load(path, sim)
                .with_context(|| format!("resuming from {}", path.display()))?;
            progress.note(&format!(
                "resumed at step {} (t = {:.3} µs)",
                sim.state.step,
                s_to_us(sim.state.t)
            ));
        } else {
            progress.note(&format!(
                "no checkpoint at {} yet: starting fresh",
                path.display()
            ));
        }
    }
    Ok(samples)
}

/// The run facts of the summary: direction (`dir`, rad from x) and the line, dt and the stable
/// step, particles, throughput over the `steps` this process took in `wall_s` (s), the model
/// `choice`, the mount's tilt-pair ratio, the active set's mean size.
fn run_info(
    p: &DemParams,
    dir: f64,
    prepared: &Prepared,
    steps: u64,
    wall_s: f64,
    choice: ModelChoice,
    tilt_pair_ratio: Option<f64>,
) -> RunInfo {
    let sim = &prepared.sim;
    let alpha_deg = label(rad_to_deg(p.alpha));
    RunInfo {
        alpha_deg,
        line_deg: rad_to_deg(dir) - alpha_deg,
        direction_deg: rad_to_deg(dir),
        dt_us: s_to_us(sim.dt),
        dt_crit_us: s_to_us(prepared.stable.dt_crit),
        dt_crit_mode: prepared.stable.mode,
        particles: sim.particles(),
        pruned_substrate: prepared.start.pruned,
        particle_steps_per_s: steps as f64 * sim.particles() as f64 / wall_s.max(1e-9),
        rigid_z: sim.params.mount.rigid_z,
        prune: sim.params.active.prune_substrate,
        model: choice.model,
        model_requested: choice.requested,
        model_reason: choice.reason,
        tilt_pair_ratio,
        active_set: sim.params.active.enabled,
        mean_active_particles: sim.state.stats.particle_steps as f64 / sim.state.step.max(1) as f64
            + 1.0,
    }
}
