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

//!
//! Files: `job.rs` (the jobs, their outcomes and names), `run.rs` (the runner: reuse, one run,
//! runs side by side), `progress.rs` (the batch's progress over its runs), `summary.rs` (the
//! rows of `runs.csv`, the summary files' inputs and a shard's part of a batch).

mod job;
mod progress;
mod run;
mod summary;

pub use job::{
    job_inputs, run_facts, run_name, BatchOptions, Failure, RunFacts, SlideJob, SlideOutcome,
    SlideResult,
};
pub use run::{finished_runs, run_batch, run_batch_with};
pub use summary::{batch_rows, run_part, summary_inputs};
