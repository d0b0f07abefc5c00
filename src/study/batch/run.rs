//! The runner: a batch's stored runs reused, the others run side by side, one thread pool each.

use super::job::{job_inputs, BatchOptions, Failure, SlideJob, SlideOutcome, SlideResult};
use super::progress::{BatchProgress, RunProgress};
use crate::runs::meta::Inputs;
use crate::runs::output::Outputs;
use crate::runs::progress::Progress;
use crate::runs::sink::csv_bytes;
use crate::study::slide::slide;
use anyhow::{bail, Context, Result};
use serde::de::DeserializeOwned;
use std::path::Path;
use std::sync::Mutex;

/// Reads the finished JSON file `path` ([`crate::runs::stored::load_json`]).
fn load_json<T: DeserializeOwned>(path: &Path, inputs: &Inputs) -> Result<Option<T>> {
    crate::runs::stored::load_json(path, inputs, "this batch's run", "", "run summary")
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
                if p.is::<crate::runs::progress::Cancelled>() {
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
                crate::runs::output::SERIES_ROLE,
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
                        crate::runs::output::SUMMARY_ROLE,
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
                            if r.locked_in {
                                format!(
                                    "; {}",
                                    crate::study::slide::locked_in_words(r.advance_ratio)
                                )
                            } else {
                                String::new()
                            },
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
