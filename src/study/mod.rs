//! # The study layer: every workflow of superlube, called by every command
//!
//! A workflow is one function that takes a validated [`surrogate::Scene`] and a parameters
//! struct (SI units), reports progress through a [`Progress`](crate::runs::progress::Progress) callback object, and streams its
//! rows into a [`RowSink`](crate::runs::sink::RowSink) (or returns its SI result). It does no flag parsing and opens no
//! output files: the commands in `src/cli/` parse flags into a scene and parameters, check the
//! output paths, call one workflow function, and write the files through [`Outputs`](crate::runs::output::Outputs).
//!
//! | workflow | function | params | output |
//! |---|---|---|---|
//! | screen | [`screen::screen`] | [`screen::ScreenParams`] | [`rows::ScreenRow`] stream |
//! | one configuration's contacts | [`contacts::contacts`] | [`contacts::ContactsParams`] | `Equilibrium` → [`rows::ContactRow`]s |
//! | landscape | [`landscape::landscape`] | [`landscape::LandscapeParams`] | [`rows::LandscapeRow`] stream + [`landscape::LandscapeStats`] |
//! | corrugation | [`corrugation::corrugation`] | [`corrugation::CorrugationParams`] | [`rows::CorrugationRow`] stream + contact line |
//! | friction | [`friction::friction`] | [`friction::FrictionSweepParams`] | [`rows::FrictionRow`] stream |
//! | design | [`design::design`] | [`design::DesignParams`] | [`design::DesignOutcome`]; `report.md`, CSVs, PNGs under `--out-dir` written from it by `crate::present::design_report` |
//! | figures | [`figures::figures`] | [`figures::FiguresParams`] | one [`figures::Figure`] at a time |
//! | equilibrate | [`equilibrate::equilibrate`] | [`dem_run::DemParams`] | time series + [`rows::EquilibrateReport`] |
//! | slide | [`slide::slide`] | [`dem_run::DemParams`] | time series + [`rows::SlideReport`] |
//! | slide batch | [`batch::run_batch_with`] (runs), [`batch::run_part`] (a shard's part + every row) | [`batch::SlideJob`]s + [`batch::BatchOptions`] | per run `runs/<name>/` files; [`rows::BatchRow`]s, [`rows::ConfigStatsRow`]s |
//! | work-precision diagrams | [`work_precision::work_precision`] | [`work_precision::WorkPrecisionParams`] | [`work_precision::WorkPrecisionRow`]s per tier |
//! | friction campaign | [`campaign::CampaignParams::plan`] → [`batch::run_part`] → [`campaign::figure_rows`] | [`campaign::CampaignParams`] | `runs.csv`, per figure [`rows::ConfigStatsRow`]s + PNG |
//!
//! Shared pieces of this layer: [`record`] (parameters in user units for the sidecar), [`rows`]
//! (ONE row type and schema per kind of output), [`batch`] (DEM runs side by side), [`merge`]
//! (sharded and resumed sweeps). The run machinery the workflows use lives one layer down in
//! [`crate::runs`]: progress reporting, row sinks, output checks and writing, sidecars, the size
//! guard, sweeps, shards, resume and Slurm scripts.
//!
//! Adding a workflow (e.g. a `design` or `friction` study): a file here with a `…Params` struct,
//! an `estimate` for the size guard, a `record` entry, a row type in [`rows`] if it writes rows,
//! and a function `(scene, &params, sink, &dyn Progress) -> Result<stats>` that may call the
//! workflows above; then a thin command in `src/cli/`.
//!
//! ## DEM batches: [`batch`]
//!
//! Independent slide runs side by side: [`batch::run_batch_with`]`(jobs, &BatchOptions {
//! side_by_side, stage, run_notes }, dir, progress) -> Vec<SlideOutcome>` — configurations in
//! ([`batch::SlideJob`]: name, scene at its θ, [`dem_run::DemParams`]), one outcome per job out,
//! in order ([`batch::SlideOutcome`]: the summary [`batch::SlideResult`] or the error, and
//! whether it was reused). `side_by_side` runs at once, one thread each (a lone run gets every
//! thread); progress is one stage over the runs (per-mille of a run, `done/total runs done, k
//! running`, ETA) plus a log line per finished run (and, with `run_notes`, each run's own log
//! lines prefixed with its name). The directory is resumable: `dir/<name>/slide.json` (or
//! `failed.json`) with the same input hash is reused, never rerun; an interrupted run continues
//! from `dir/<name>/slide.ckpt`; a file of other inputs is an error before any work. A blow-up,
//! an engine error or panic, or a lock-in is an outcome of that run only. Helpers:
//! [`batch::run_name`] (directory name from the inputs), [`batch::finished_runs`] (outcomes on
//! disk without running), [`batch::run_part`] (a shard's range of the jobs, then every job's row
//! and the number still missing), [`batch::batch_rows`], [`batch::summary_inputs`] (sidecar
//! inputs of a batch's summary files: the run names and input hashes, the same for every shard).
//! A batch is sharded by cutting its run list ([`Shard::range`](crate::runs::shard::Shard::range)) and letting every shard write
//! into the same directory; the call that finds every run finished writes the summaries (no
//! `merge` needed: the runs' own files are the shards' results). Users: `superlube slide
//! --out-dir` (`src/cli/slide.rs`), `superlube figures --friction` (`src/cli/campaign.rs`), and
//! the design's DEM stage (`design::confirm` re-exports [`batch::run_batch`]).
//!
//! ## Sweeps: `--shard i/n`, `--resume`, `superlube merge`, `superlube slurm`
//!
//! Every sweep follows one contract ([`sweep`](crate::runs::sweep)): **N items in a fixed order, item `i` giving
//! exactly `r` rows** (rows `i·r .. (i+1)·r`), computed independently of which process computes
//! it. Sharding cuts the items into contiguous blocks ([`Shard::range`](crate::runs::shard::Shard::range)); resuming keeps the
//! complete items of `OUT.partial` ([`resume`](crate::runs::resume)); merging concatenates the shards in order
//! ([`merge`]). The shard goes into the output's sidecar as a [`ShardInfo`](crate::runs::sweep::ShardInfo), the sweep's
//! `input_hash` stays that of the unsharded run (the inputs, not the shard, are hashed), so
//! `merge` can check that files belong together and write the unsharded run's sidecar.
//!
//! | sweep | item | rows per item | shard rows (schema) | merge |
//! |---|---|---|---|---|
//! | `screen` | one θ | number of loads | [`rows::ScreenRow`] (`screen`) | concatenation |
//! | `landscape` | one grid point | 1 | [`rows::LandscapeZRow`] (`landscape-z`: exact z) | [`landscape::finish`]: Δz = z − min z over all shards |
//! | `corrugation` | one α | 1 | [`rows::CorrugationRow`] (`corrugation`) | concatenation |
//! | `friction` | one (θ, α) | number of loads | [`rows::FrictionRow`] (`friction`) | concatenation |
//!
//! Plugging in a new sweep (a `friction` sweep, a DEM batch of θ/α/W/seeds, a design's DEM
//! stage) takes a few lines in its command (see `src/cli/screen.rs`):
//!
//! 1. flatten `SweepArgs` (`--shard`, `--resume`) into the command's clap `Args`;
//! 2. describe the sweep: `Sweep { items, rows_per_item, unit: "runs", schema: "friction" }`
//!    (the schema name is free; any schema whose rows are final per item merges by
//!    concatenation), and get the run with `args.sweep.run(sweep, out, &[other output flags])`
//!    — it parses `--shard`, refuses `--shard` without `--out` or with outputs a shard cannot
//!    write, and refuses more shards than items;
//! 3. stream through [`Outputs::stream_sweep`](crate::runs::output::Outputs::stream_sweep)`(role, out, &run, &progress, |items, sink| …)`:
//!    the closure computes exactly the items `items` (a sub-range of `0..N`, already cut to the
//!    shard and past the resumed rows) and pushes their rows in order, e.g. by calling the
//!    workflow on the slice `params.list[items]`; the progress stage should count those items,
//!    so a resumed run shows what it computed;
//! 4. add the command to `SWEEP_COMMANDS` and `prepare_sweep` in `src/cli/mod.rs` (a
//!    `prepare(args) -> Prepared` doing every check without running, with `Prepared::plan()`),
//!    and `superlube slurm` can run it as an array job.
//!
//! A sweep whose final rows need the whole sweep (like the landscape's min z) writes per-item
//! rows from which they follow, under its own schema name, and adds that schema's merge in
//! [`merge::merge`] — used by its unsharded run too, so both give the same bytes.

pub mod batch;
pub mod campaign;
pub mod contacts;
pub mod corrugation;
pub mod dem_run;
pub mod design;
pub mod equilibrate;
pub mod fab_yield;
pub mod fairness;
pub mod figures;
pub mod friction;
pub mod input;
pub mod landscape;
pub mod load;
pub mod merge;
pub mod patterns;
pub mod range;
pub mod recipe;
pub mod record;
pub mod rows;
pub mod screen;
pub mod slide;
pub mod tolerance;
pub mod verdict;
pub mod work_precision;
