//! The study layer's batch runner: independent `slide` runs side by side, one thread each.
//!
//! [`run_batch`] takes a list of slide configurations ([`SlideJob`]: a name, the scene at its θ,
//! the DEM parameters with α and the line set), the number of runs side by side and an output
//! directory, and returns one [`SlideOutcome`] per job, **in the jobs' order**. Runs side by side
//! get one thread each (the process's threads divided by the runs side by side; a lone run gets
//! all of them). DEM results do not depend on the thread count, so a run gives the same bytes
//! alone or side by side.
//!
//! Each run writes into `dir/<name>/`: `slide.csv` (time series) and `slide.json` (the summary
//! of `superlube slide --json`), each with its sidecar — the same `input_hash` as
//! `superlube slide` with the same scene and flags — or, when the run stops early (blow-up),
//! `failed.json` with the reason (and the time series up to the failure). A run whose result
//! file is there with the same inputs is reused, never rerun (also a failed one: its failure is
//! the result of those inputs); one interrupted mid-run resumes from its checkpoint
//! `slide.ckpt` (written every `io.checkpoint_every` steps of its parameters, bit-identical
//! resume). A result file whose sidecar names other inputs is never used nor overwritten: the
//! batch stops before any work with an error naming the file. Lock-in is not a failure: the
//! summary says `locked_in`. A failing run does not stop the others.
//!
//! Progress: one stage ([`BatchOptions::stage`]) over the runs still to compute, in per-mille of
//! a run (so the reporter's ETA follows the runs' own progress), with `done/total runs done, k
//! running` as status, and one log line per finished run.

use super::dem_run::DemParams;
use super::meta::{scene_file, Inputs};
use super::progress::Progress;
use super::record;
use super::sink::csv_bytes;
use super::slide::slide;
use super::Outputs;
use anyhow::{bail, Context, Result};
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
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

/// Reads the finished JSON file `path` ([`crate::runs::stored::load_json`]).
fn load_json<T: DeserializeOwned>(path: &Path, inputs: &Inputs) -> Result<Option<T>> {
    crate::runs::stored::load_json(path, inputs, "this batch's run", "", "run summary")
}

/// The model facts in the `slide.json` of a finished run (`None` for a failed or missing one).
pub fn run_facts(o: &SlideOutcome) -> Option<RunFacts> {
    o.result.as_ref()?;
    let text = std::fs::read_to_string(o.dir.join("slide.json")).ok()?;
    serde_json::from_str(&text).ok()
}

/// Reports the batch as one stage: the sum over runs of the fraction done (in per-mille of a
/// run), with the number of finished and running runs as status.
struct BatchProgress<'a> {
    parent: &'a dyn Progress,
    /// Fraction done per run to do, runs finished, runs running.
    state: Mutex<(Vec<f64>, usize, usize)>,
}

impl BatchProgress<'_> {
    fn set(&self, k: usize, f: f64) {
        let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
        s.0[k] = f.clamp(0.0, 1.0);
        let done: f64 = s.0.iter().sum();
        let status = format!("{}/{} runs done, {} running", s.1, s.0.len(), s.2);
        drop(s);
        self.parent.update((done * 1000.0).round() as u64, &status);
    }

    fn started(&self, k: usize) {
        self.state.lock().unwrap_or_else(|e| e.into_inner()).2 += 1;
        self.set(k, 0.0);
    }

    fn finished(&self, k: usize) {
        {
            let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
            s.1 += 1;
            s.2 = s.2.saturating_sub(1);
        }
        self.set(k, 1.0);
    }
}

/// One run's view of the batch progress.
struct RunProgress<'a> {
    batch: &'a BatchProgress<'a>,
    k: usize,
    total: Mutex<u64>,
    /// `Some(name)`: forward notes prefixed with the run's name.
    notes: Option<&'a str>,
}

impl Progress for RunProgress<'_> {
    fn stage(&self, _: &str, total: u64, _: &str) {
        *self.total.lock().unwrap_or_else(|e| e.into_inner()) = total.max(1);
    }
    fn advance(&self, _: u64) {}
    fn update(&self, done: u64, _: &str) {
        let t = *self.total.lock().unwrap_or_else(|e| e.into_inner());
        self.batch.set(self.k, done as f64 / t as f64);
    }
    fn note(&self, line: &str) {
        if let Some(name) = self.notes {
            self.batch.parent.note(&format!("{name}: {line}"));
        }
    }
    fn finish(&self) {}
}

/// The outcome of `job` from the files of an earlier run, if there are any.
fn reuse(dir: &Path, job: &SlideJob, inputs: &Inputs) -> Result<Option<SlideOutcome>> {
    let run_dir = dir.join(&job.name);
    let out = |result: Option<SlideResult>, error: Option<String>| SlideOutcome {
        name: job.name.clone(),
        dir: run_dir.clone(),
        result,
        error,
        reused: true,
    };
    if let Some(r) = load_json::<SlideResult>(&run_dir.join("slide.json"), inputs)? {
        return Ok(Some(out(Some(r), None)));
    }
    if let Some(f) = load_json::<Failure>(&run_dir.join("failed.json"), inputs)? {
        return Ok(Some(out(None, Some(f.error))));
    }
    Ok(None)
}

/// Runs one job on the current thread pool and writes its files.
fn run_one(dir: &Path, job: &SlideJob, inputs: &Inputs, progress: &dyn Progress) -> SlideOutcome {
    let dir = dir.join(&job.name);
    let mut params = job.params.clone();
    let ckpt = dir.join("slide.ckpt");
    params.io.checkpoint = Some(ckpt.clone());
    params.resume = Some(ckpt.clone());
    let t0 = std::time::Instant::now();
    let mut outs = Outputs::new(inputs.clone(), vec![]);
    let (result, error) = match std::fs::create_dir_all(&dir)
        .map_err(anyhow::Error::from)
        .and_then(|_| {
            // an engine panic (e.g. on blown-up coordinates) fails this run only
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                slide(&job.scene, &params, progress)
            }))
            .unwrap_or_else(|p| {
                if p.is::<crate::study::progress::Cancelled>() {
                    std::panic::resume_unwind(p); // the caller's interrupt, not this run's failure
                }
                let msg = p
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| p.downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "unknown panic".into());
                Err(anyhow::anyhow!("the DEM engine panicked: {msg}"))
            })
        }) {
        Err(e) => (None, Some(format!("{e:#}"))),
        Ok((run, report)) => {
            outs.write(
                "--out",
                Some(&dir.join("slide.csv")),
                csv_bytes(&run.samples),
                Some(run.samples.len() as u64),
            );
            match (report, run.error) {
                (Some(rep), None) => {
                    let text = serde_json::to_string_pretty(&rep).map(|t| t + "\n");
                    let parsed: Option<SlideResult> = text
                        .as_ref()
                        .ok()
                        .and_then(|t| serde_json::from_str(t).ok());
                    outs.write(
                        "--json",
                        Some(&dir.join("slide.json")),
                        text.map(String::into_bytes).map_err(Into::into),
                        None,
                    );
                    (parsed, None)
                }
                (_, e) => (
                    None,
                    Some(e.map_or("the run stopped early".into(), |e| e.to_string())),
                ),
            }
        }
    };
    if let Some(e) = &error {
        let f = Failure {
            error: e.clone(),
            wall_s: t0.elapsed().as_secs_f64(),
        };
        let text = serde_json::to_string_pretty(&f).map(|t| t + "\n");
        outs.write(
            "failed",
            Some(&dir.join("failed.json")),
            text.map(String::into_bytes).map_err(Into::into),
            None,
        );
    }
    let error = match (error, outs.finish()) {
        (e, Ok(())) => e,
        (Some(e), Err(w)) => Some(format!("{e}; also: {w:#}")),
        (None, Err(w)) => Some(format!("{w:#}")),
    };
    if error.is_none() {
        let _ = std::fs::remove_file(&ckpt);
    }
    SlideOutcome {
        name: job.name.clone(),
        dir,
        result: if error.is_none() { result } else { None },
        error,
        reused: false,
    }
}

/// The outcomes of the jobs that finished earlier (`None` for those still to run), without
/// running anything. Errors: result files of other inputs (or unreadable ones), every such run
/// named in one error (a folder of an older build's runs is refused at once, not run by run).
pub fn finished_runs(jobs: &[SlideJob], dir: &Path) -> Result<Vec<Option<SlideOutcome>>> {
    let inputs: Vec<Inputs> = jobs.iter().map(job_inputs).collect();
    stored_runs(jobs, &inputs, dir)
}

/// [`finished_runs`] with each job's recorded inputs `inputs` (in job order).
fn stored_runs(
    jobs: &[SlideJob],
    inputs: &[Inputs],
    dir: &Path,
) -> Result<Vec<Option<SlideOutcome>>> {
    let mut out: Vec<Option<SlideOutcome>> = Vec::with_capacity(jobs.len());
    let mut refused: Vec<(&str, String)> = Vec::new();
    for (j, i) in jobs.iter().zip(inputs) {
        match reuse(dir, j, i) {
            Ok(o) => out.push(o),
            Err(e) => {
                refused.push((j.name.as_str(), format!("{e:#}")));
                out.push(None);
            }
        }
    }
    if let [(_, first), rest @ ..] = refused.as_slice() {
        const SHOWN: usize = 6;
        bail!(
            "{} of {} stored runs under {} cannot be reused (nothing was run): {}{}; remove {} or use another output directory",
            refused.len(),
            jobs.len(),
            dir.display(),
            first,
            if rest.is_empty() {
                String::new()
            } else {
                let names: Vec<&str> = rest.iter().take(SHOWN).map(|(n, _)| *n).collect();
                format!(
                    " (and {} more: {}{})",
                    rest.len(),
                    names.join(", "),
                    if rest.len() > SHOWN { ", …" } else { "" }
                )
            },
            if refused.len() == jobs.len() {
                dir.display().to_string()
            } else if rest.is_empty() {
                "that run's folder".to_string()
            } else {
                "those runs' folders".to_string()
            },
        );
    }
    Ok(out)
}

/// Runs `jobs` (see the module docs) with up to `side_by_side` runs at once, under `dir`, with
/// the progress stage `confirm (DEM)` (the design's). See [`run_batch_with`].
pub fn run_batch(
    jobs: &[SlideJob],
    side_by_side: usize,
    dir: &Path,
    progress: &dyn Progress,
) -> Result<Vec<SlideOutcome>> {
    run_batch_with(
        jobs,
        &BatchOptions {
            side_by_side,
            stage: "confirm (DEM)".into(),
            run_notes: false,
        },
        dir,
        progress,
    )
}

/// Runs `jobs` (see the module docs) with up to `opts.side_by_side` runs at once, under `dir`;
/// each run gets the process's threads divided by the runs side by side (one each when they
/// fill the cores; all of them for a lone run). Returns one outcome per job, in order. Errors:
/// only a result file of other inputs (checked for every job before any work) or a thread pool
/// that cannot be built; a failing run is an outcome. Stored runs: as [`finished_runs`].
pub fn run_batch_with(
    jobs: &[SlideJob],
    opts: &BatchOptions,
    dir: &Path,
    progress: &dyn Progress,
) -> Result<Vec<SlideOutcome>> {
    let inputs: Vec<Inputs> = jobs.iter().map(job_inputs).collect();
    let mut out = stored_runs(jobs, &inputs, dir)?;
    let todo: Vec<usize> = (0..jobs.len()).filter(|&k| out[k].is_none()).collect();
    if !todo.is_empty() {
        progress.stage(&opts.stage, 1000 * todo.len() as u64, "‰ of runs");
        let batch = BatchProgress {
            parent: progress,
            state: Mutex::new((vec![0.0; todo.len()], 0, 0)),
        };
        let next = Mutex::new(0usize);
        let results: Mutex<Vec<(usize, SlideOutcome)>> = Mutex::new(Vec::new());
        let workers = opts.side_by_side.clamp(1, todo.len());
        // one thread per run when the runs fill the cores; a lone run takes them all
        let per_run = (rayon::current_num_threads() / workers).max(1);
        std::thread::scope(|s| -> Result<()> {
            let mut handles = Vec::new();
            for _ in 0..workers {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(per_run)
                    .build()
                    .context("creating a thread pool for a DEM run")?;
                let (todo, next, results, batch, inputs) =
                    (&todo, &next, &results, &batch, &inputs);
                handles.push(s.spawn(move || loop {
                    let slot = {
                        let mut n = next.lock().unwrap_or_else(|e| e.into_inner());
                        let k = *n;
                        *n += 1;
                        k
                    };
                    let Some(&k) = todo.get(slot) else { break };
                    let rp = RunProgress {
                        batch,
                        k: slot,
                        total: Mutex::new(1),
                        notes: opts.run_notes.then_some(jobs[k].name.as_str()),
                    };
                    batch.started(slot);
                    let o = pool.install(|| run_one(dir, &jobs[k], &inputs[k], &rp));
                    batch.finished(slot);
                    let line = match (&o.result, &o.error) {
                        (Some(r), _) => format!(
                            "DEM {}: μ = {:.5}{} ({:.0} s)",
                            o.name,
                            r.mu,
                            if r.locked_in { ", LOCKED IN" } else { "" },
                            r.wall_s
                        ),
                        (None, Some(e)) => format!("DEM {}: FAILED: {e}", o.name),
                        _ => format!("DEM {}: no result", o.name),
                    };
                    progress.note(&line);
                    results
                        .lock()
                        .unwrap_or_else(|e| e.into_inner())
                        .push((k, o));
                }));
            }
            for h in handles {
                let _ = h.join();
            }
            Ok(())
        })?;
        progress.finish();
        for (k, o) in results.into_inner().unwrap_or_else(|e| e.into_inner()) {
            out[k] = Some(o);
        }
    }
    Ok(out
        .into_iter()
        .zip(jobs)
        .map(|(o, j)| {
            o.unwrap_or_else(|| SlideOutcome {
                name: j.name.clone(),
                dir: dir.join(&j.name),
                result: None,
                error: Some("the run did not finish (its worker stopped)".into()),
                reused: false,
            })
        })
        .collect())
}

/// The directory name of a run: `<pattern>_th<θ>_a<α>_W<W>_sh<σ_h>_s<seed>_E<E>` (degrees,
/// mN, µm, GPa as printed by [`super::rows::label`]; the seed part only when σ_h > 0, where it
/// matters).
pub fn run_name(scene: &Scene, params: &DemParams) -> String {
    use super::rows::label;
    use surrogate::units::{m_to_um, n_to_mn, pa_to_gpa, rad_to_deg};
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
        label(n_to_mn(params.sim.load)),
        sh,
        seed,
        label(pa_to_gpa(scene.material.youngs)),
    )
}

/// The rows of `runs.csv` for `jobs`, from their outcomes (`None`: not run yet), in order.
pub fn batch_rows(jobs: &[SlideJob], outcomes: &[Option<SlideOutcome>]) -> Vec<BatchRow> {
    jobs.iter()
        .zip(outcomes)
        .map(|(j, o)| {
            let facts = o.as_ref().and_then(run_facts);
            BatchRow::new(j, o.as_ref(), facts.as_ref())
        })
        .collect()
}

/// The inputs of a batch's summary files: the run names and each run's input hash (the same
/// for a sharded and an unsharded batch).
pub fn summary_inputs(workflow: &str, jobs: &[SlideJob], extra: serde_json::Value) -> Inputs {
    let runs: Vec<serde_json::Value> = jobs
        .iter()
        .map(|j| serde_json::json!({"name": j.name, "input_hash": job_inputs(j).hash()}))
        .collect();
    Inputs {
        workflow: workflow.into(),
        scene: None,
        params: serde_json::json!({"runs": runs, "batch": extra}),
    }
}

/// A shard's part of a batch and what is left: runs the jobs `range` (with `opts`) after
/// checking every job's earlier files (errors before any work), then reads back every job's
/// outcome. Returns the rows of all jobs in order and the number still missing (other shards).
pub fn run_part(
    jobs: &[SlideJob],
    range: std::ops::Range<usize>,
    opts: &BatchOptions,
    dir: &Path,
    progress: &dyn Progress,
) -> Result<(Vec<BatchRow>, usize)> {
    let before = finished_runs(jobs, dir)?;
    let done = before.iter().filter(|o| o.is_some()).count();
    let todo_here = range.clone().filter(|&k| before[k].is_none()).count();
    progress.note(&format!(
        "{} runs in all, {} finished earlier (reused, not rerun); this call runs {} of runs {}..{} ({} side by side)",
        jobs.len(),
        done,
        todo_here,
        range.start,
        range.end,
        opts.side_by_side.min(todo_here.max(1))
    ));
    run_batch_with(&jobs[range], opts, dir, progress)?;
    let after = finished_runs(jobs, dir)?;
    let missing = after.iter().filter(|o| o.is_none()).count();
    Ok((batch_rows(jobs, &after), missing))
}

use super::rows::BatchRow;

impl BatchRow {
    /// The row of `job` with its outcome (`None`: not run yet) and the model facts of its
    /// summary.
    pub fn new(job: &SlideJob, o: Option<&SlideOutcome>, facts: Option<&RunFacts>) -> BatchRow {
        use super::rows::label;
        use surrogate::units::{m_to_um, n_to_mn, pa_to_gpa, rad_to_deg, s_to_us};
        let (s, p) = (&job.scene, &job.params.sim);
        let r = o.and_then(|o| o.result.as_ref());
        let (status, error) = match o {
            None => (
                "missing",
                "not run yet (another shard's run, or an interrupted batch)".to_string(),
            ),
            Some(o) => match (&o.result, &o.error) {
                (Some(_), _) => ("ok", String::new()),
                (None, e) => (
                    "failed",
                    e.clone().unwrap_or_else(|| "no result".to_string()),
                ),
            },
        };
        BatchRow {
            name: job.name.clone(),
            pattern: s.pattern.clone(),
            theta_deg: label(rad_to_deg(s.slider.theta)),
            alpha_deg: label(rad_to_deg(job.params.alpha)),
            load_mN: label(n_to_mn(p.load)),
            sigma_h_um: label(m_to_um(s.substrate.sigma_h)),
            seed: s.substrate.seed,
            E_GPa: label(pa_to_gpa(s.material.youngs)),
            p_crit_GPa: label(pa_to_gpa(s.coating.p_crit)),
            mu1: s.coating.mu1,
            mu2: s.coating.mu2,
            mu_constant: match &job.params.friction {
                Some(dem::model::Friction::Constant(c)) => Some(c.mu),
                _ => None,
            },
            mount: s.slider.mount.name().to_string(),
            model_requested: job.params.model.request.name().to_string(),
            model: facts.map(|f| f.model.clone()).unwrap_or_default(),
            rigid_z: facts.map(|f| f.rigid_z),
            equilibrate_us: label(s_to_us(p.equilibrate_time)),
            relax_us: label(s_to_us(p.relax_time)),
            slide_us: label(s_to_us(p.slide_time)),
            speed_m_s: p.support_speed,
            dt_us: facts.map(|f| f.dt_us).or(p.dt.map(|d| label(s_to_us(d)))),
            friction_mN: r.map(|r| r.friction_mN),
            friction_std_mN: r.map(|r| r.friction_std_mN),
            mu: r.map(|r| r.mu),
            mean_contacts: r.map(|r| r.mean_contacts),
            max_p_max_GPa: r.map(|r| r.max_p_max_GPa),
            mean_failed_contacts: r.map(|r| r.mean_failed_contacts),
            locked_in: r.map(|r| r.locked_in),
            advance_ratio: r.and_then(|r| r.advance_ratio),
            steps: r.map(|r| r.steps),
            wall_s: r.map(|r| r.wall_s),
            status: status.to_string(),
            error,
        }
    }
}
