//! The jobs of a batch, what becomes of them, and their names and recorded inputs.

use crate::runs::meta::{scene_file, Inputs};
use crate::study::dem_run::DemParams;
use crate::study::record;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;
use surrogate::Scene;

/// One slide run of a batch.
#[derive(Debug, Clone)]
pub struct SlideJob {
    /// Directory name of the run (unique within the batch).
    pub name: String,
    /// The scene, with the slider at the run's θ.
    pub scene: Scene,
    /// The run's DEM parameters (α, line, protocol).
    pub params: DemParams,
}

/// The result of a run as read back from `slide.json` (user units).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct SlideResult {
    /// Mean spring force over the measuring window (mN).
    pub friction_mN: f64,
    /// Its standard deviation (mN).
    pub friction_std_mN: f64,
    /// friction / W.
    pub mu: f64,
    /// Mean contact number over the window.
    pub mean_contacts: f64,
    /// Largest P_max over the window (GPa).
    pub max_p_max_GPa: f64,
    /// Mean number of failed contacts over the window.
    pub mean_failed_contacts: f64,
    /// The slider locked in.
    pub locked_in: bool,
    /// Slider advance / support advance over the window (`None`: too short a window to tell,
    /// written as `null`).
    #[serde(default)]
    pub advance_ratio: Option<f64>,
    /// Steps of the run.
    pub steps: u64,
    /// Wall time of the run (s).
    pub wall_s: f64,
}

/// The model facts of a finished run as read back from `slide.json` ([`run_facts`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunFacts {
    /// Model used: `full` or `reduced`.
    pub model: String,
    /// `--model` as asked: `auto`, `full` or `reduced`.
    pub model_requested: String,
    /// Slider spheres rigid in z.
    pub rigid_z: bool,
    /// Time step used (µs).
    pub dt_us: f64,
}

/// A failed run's record (`failed.json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Failure {
    /// Why it stopped.
    pub error: String,
    /// Wall time until then (s).
    pub wall_s: f64,
}

/// What became of one job.
#[derive(Debug, Clone)]
pub struct SlideOutcome {
    /// The job's name.
    pub name: String,
    /// The run's directory.
    pub dir: PathBuf,
    /// Its summary, if it completed.
    pub result: Option<SlideResult>,
    /// Why it failed, if it did.
    pub error: Option<String>,
    /// Whether the result was reused from an earlier run.
    pub reused: bool,
}

/// How a batch runs (besides its jobs and directory).
#[derive(Debug, Clone)]
pub struct BatchOptions {
    /// Runs side by side (≥ 1; more than the jobs to do is cut to their number).
    pub side_by_side: usize,
    /// Name of the progress stage.
    pub stage: String,
    /// Forward each run's log lines (model choice, time step, resume point), prefixed with the
    /// run's name.
    pub run_notes: bool,
}

impl Default for BatchOptions {
    fn default() -> Self {
        BatchOptions {
            side_by_side: 1,
            stage: "DEM runs".into(),
            run_notes: false,
        }
    }
}

/// The inputs recorded for a job (the same as `superlube slide` records).
pub fn job_inputs(job: &SlideJob) -> Inputs {
    Inputs {
        workflow: "slide".into(),
        scene: Some(scene_file(&job.scene)),
        params: record::dem(&job.scene, &job.params),
    }
}

/// The model facts in the `slide.json` of a finished run (`None` for a failed or missing one).
pub fn run_facts(o: &SlideOutcome) -> Option<RunFacts> {
    o.result.as_ref()?;
    let text = std::fs::read_to_string(o.dir.join("slide.json")).ok()?;
    serde_json::from_str(&text).ok()
}

/// `E` of a run name: the slider's Young's modulus (GPa), `-` the substrate's when the two
/// bodies' materials differ.
fn material_label(scene: &Scene) -> String {
    use crate::study::rows::label;
    use surrogate::units::pa_to_gpa;
    let (sl, sb) = (scene.slider_material(), scene.substrate_material());
    if sl == sb {
        format!("{}", label(pa_to_gpa(sl.youngs)))
    } else {
        format!(
            "{}-{}",
            label(pa_to_gpa(sl.youngs)),
            label(pa_to_gpa(sb.youngs))
        )
    }
}

/// The directory name of a run: `<pattern>_th<θ>_a<α>_W<W>_sh<σ_h>_s<seed>_E<E>` (degrees,
/// mN, µm, GPa as printed by [`crate::study::rows::label`]; the seed part only when σ_h > 0, where it
/// matters; `E<E_slider>-<E_substrate>` when the bodies' materials differ).
pub fn run_name(scene: &Scene, params: &DemParams) -> String {
    use crate::study::rows::label;
    use surrogate::units::{m_to_um, n_to_mn, rad_to_deg};
    let sh = label(m_to_um(scene.substrate.sigma_h));
    let seed = if sh > 0.0 {
        format!("_s{}", scene.substrate.seed)
    } else {
        String::new()
    };
    format!(
        "{}_th{}_a{}_W{}_sh{}{}_E{}",
        scene.pattern.replace(['/', '\\', ' '], "-"),
        label(rad_to_deg(scene.slider.theta)),
        label(rad_to_deg(params.alpha)),
        label(n_to_mn(params.sim.protocol.load)),
        sh,
        seed,
        material_label(scene),
    )
}
