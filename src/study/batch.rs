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
use super::meta::{input_differences, scene_file, sidecar_path, Inputs, Sidecar};
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
    /// Slider advance / support advance over the window.
    pub advance_ratio: f64,
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

/// The finished file `path` for `inputs`: `None` when absent, only partial, or without its
/// sidecar (interrupted between the two renames: redone); an error when its sidecar names
/// other inputs (never mixed).
fn finished(path: &Path, inputs: &Inputs) -> Result<Option<PathBuf>> {
    if !path.exists() {
        return Ok(None);
    }
    let s = match Sidecar::of(path) {
        Ok(s) => s,
        Err(_) if !sidecar_path(path).exists() => return Ok(None),
        Err(e) => return Err(e),
    };
    if s.input_hash != inputs.hash() {
        let diff = input_differences(&s.inputs(), inputs, 8);
        bail!(
            "{} was made with other inputs than this batch's run ({}): never mixed; remove it or use another output directory",
            path.display(),
            if diff.is_empty() {
                format!("written by superlube {}", s.version)
            } else {
                diff.join("; ")
            }
        );
    }
    Ok(s.complete.then(|| path.to_path_buf()))
}

/// Reads the finished JSON file `path` (see [`finished`]).
fn load_json<T: DeserializeOwned>(path: &Path, inputs: &Inputs) -> Result<Option<T>> {
    match finished(path, inputs)? {
        None => Ok(None),
        Some(p) => {
            let text =
                std::fs::read_to_string(&p).with_context(|| format!("reading {}", p.display()))?;
            Ok(Some(serde_json::from_str(&text).with_context(|| {
                format!("{} is not a run summary of this version", p.display())
            })?))
        }
    }
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
        .and_then(|_| slide(&job.scene, &params, progress))
    {
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
/// running anything. Errors: a result file of other inputs.
pub fn finished_runs(jobs: &[SlideJob], dir: &Path) -> Result<Vec<Option<SlideOutcome>>> {
    jobs.iter()
        .map(|j| reuse(dir, j, &job_inputs(j)))
        .collect()
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
/// that cannot be built; a failing run is an outcome.
pub fn run_batch_with(
    jobs: &[SlideJob],
    opts: &BatchOptions,
    dir: &Path,
    progress: &dyn Progress,
) -> Result<Vec<SlideOutcome>> {
    let inputs: Vec<Inputs> = jobs.iter().map(job_inputs).collect();
    let mut out: Vec<Option<SlideOutcome>> = Vec::with_capacity(jobs.len());
    for (j, i) in jobs.iter().zip(&inputs) {
        out.push(reuse(dir, j, i)?);
    }
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
