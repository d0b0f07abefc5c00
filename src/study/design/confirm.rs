//! The design's DEM confirmation: independent `slide` runs side by side, one thread each.
//!
//! **Interface** (the smallest the design needs; the one place to switch to the study layer's
//! batch runner): [`run_batch`] takes a list of slide configurations ([`SlideJob`]: a name, the
//! scene at its θ, the DEM parameters with α and the line set), a number of runs side by side
//! and an output directory, and returns one [`SlideOutcome`] per job, in order. Runs side by
//! side get one thread each (a lone run all of them).
//!
//! Each run writes into `dir/<name>/`: `slide.csv` (time series) and `slide.json` (the summary
//! of `superlube slide --json`), each with its sidecar — the same `input_hash` as
//! `superlube slide` with the same scene and flags — or, when the run stops early (blow-up),
//! `failed.json` with the reason (and the time series up to the failure). A run whose result
//! file is there with the same inputs is reused, not rerun; one interrupted mid-run resumes
//! from its checkpoint `slide.ckpt` (written every `checkpoint_every` steps, bit-identical
//! resume). Lock-in is not a failure: the summary says `locked_in`. A failing run does not stop
//! the others.

use crate::study::dem_run::DemParams;
use crate::study::meta::{scene_file, Inputs};
use crate::study::progress::Progress;
use crate::study::record;
use crate::study::sink::csv_bytes;
use crate::study::slide::slide;
use crate::study::Outputs;
use anyhow::{Context, Result};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use surrogate::Scene;

use super::store::Store;

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

/// The inputs recorded for a job (the same as `superlube slide` records).
pub fn job_inputs(job: &SlideJob) -> Inputs {
    Inputs {
        workflow: "slide".into(),
        scene: Some(scene_file(&job.scene)),
        params: record::dem(&job.scene, &job.params),
    }
}

/// Reports the batch as one stage: the sum over runs of the fraction done (in per-mille of a
/// run), with the number of finished runs as status.
struct BatchProgress<'a> {
    parent: &'a dyn Progress,
    state: Mutex<(Vec<f64>, usize)>,
}

impl BatchProgress<'_> {
    fn set(&self, k: usize, f: f64) {
        let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
        s.0[k] = f.clamp(0.0, 1.0);
        let done: f64 = s.0.iter().sum();
        let status = format!("{}/{} runs done", s.1, s.0.len());
        drop(s);
        self.parent.update((done * 1000.0).round() as u64, &status);
    }

    fn finished(&self, k: usize) {
        {
            let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
            s.1 += 1;
        }
        self.set(k, 1.0);
    }
}

/// One run's view of the batch progress.
struct RunProgress<'a> {
    batch: &'a BatchProgress<'a>,
    k: usize,
    total: Mutex<u64>,
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
    fn note(&self, _: &str) {}
    fn finish(&self) {}
}

fn reuse(store: &Store, job: &SlideJob, inputs: &Inputs) -> Result<Option<SlideOutcome>> {
    let dir = store.path(&job.name);
    let out = |result: Option<SlideResult>, error: Option<String>| SlideOutcome {
        name: job.name.clone(),
        dir: dir.clone(),
        result,
        error,
        reused: true,
    };
    if let Some(r) = store.load_json::<SlideResult>(&format!("{}/slide.json", job.name), inputs)? {
        return Ok(Some(out(Some(r), None)));
    }
    if let Some(f) = store.load_json::<Failure>(&format!("{}/failed.json", job.name), inputs)? {
        return Ok(Some(out(None, Some(f.error))));
    }
    Ok(None)
}

/// Runs one job on the current thread pool and writes its files.
fn run_one(
    store: &Store,
    job: &SlideJob,
    inputs: &Inputs,
    progress: &dyn Progress,
) -> SlideOutcome {
    let dir = store.path(&job.name);
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

/// Runs `jobs` (see the module docs) with up to `side_by_side` runs at once, under `dir`; each
/// run gets the process's threads divided by the runs side by side (one each when they fill the
/// cores; all of them for a lone run). DEM results are the same for any thread count. Progress: one stage `confirm` over the runs still to compute. Errors:
/// only a stage file of other inputs (never mixed) or an unwritable directory; a failing run is
/// an outcome.
pub fn run_batch(
    jobs: &[SlideJob],
    side_by_side: usize,
    dir: &Path,
    progress: &dyn Progress,
) -> Result<Vec<SlideOutcome>> {
    let store = Store::new(dir);
    let inputs: Vec<Inputs> = jobs.iter().map(job_inputs).collect();
    let mut out: Vec<Option<SlideOutcome>> = Vec::with_capacity(jobs.len());
    for (j, i) in jobs.iter().zip(&inputs) {
        out.push(reuse(&store, j, i)?);
    }
    let todo: Vec<usize> = (0..jobs.len()).filter(|&k| out[k].is_none()).collect();
    if !todo.is_empty() {
        progress.stage("confirm (DEM)", 1000 * todo.len() as u64, "‰ of runs");
        let batch = BatchProgress {
            parent: progress,
            state: Mutex::new((vec![0.0; todo.len()], 0)),
        };
        let next = Mutex::new(0usize);
        let results: Mutex<Vec<(usize, SlideOutcome)>> = Mutex::new(Vec::new());
        let workers = side_by_side.clamp(1, todo.len());
        // one thread per run when the runs fill the cores; a lone run takes them all
        let per_run = (rayon::current_num_threads() / workers).max(1);
        std::thread::scope(|s| -> Result<()> {
            let mut handles = Vec::new();
            for _ in 0..workers {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(per_run)
                    .build()
                    .context("creating a one-thread pool for a DEM run")?;
                let (todo, next, results, batch, store, inputs) =
                    (&todo, &next, &results, &batch, &store, &inputs);
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
                    };
                    let o = pool.install(|| run_one(store, &jobs[k], &inputs[k], &rp));
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
                dir: store.path(&j.name),
                result: None,
                error: Some("the run did not finish (its worker stopped)".into()),
                reused: false,
            })
        })
        .collect())
}
