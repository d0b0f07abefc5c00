//! # The study layer: every workflow of superlube, called by every command
//!
//! A workflow is one function that takes a validated [`surrogate::Scene`] and a parameters
//! struct (SI units), reports progress through a [`Progress`] callback object, and streams its
//! rows into a [`RowSink`] (or returns its SI result). It does no flag parsing and opens no
//! output files: the commands in `src/cli/` parse flags into a scene and parameters, check the
//! output paths, call one workflow function, and write the files through [`Outputs`].
//!
//! | workflow | function | params | output |
//! |---|---|---|---|
//! | screen | [`screen::screen`] | [`screen::ScreenParams`] | [`rows::ScreenRow`] stream |
//! | one configuration's contacts | [`contacts::contacts`] | [`contacts::ContactsParams`] | `Equilibrium` → [`rows::ContactRow`]s |
//! | landscape | [`landscape::landscape`] | [`landscape::LandscapeParams`] | [`rows::LandscapeRow`] stream + [`landscape::LandscapeStats`] |
//! | corrugation | [`corrugation::corrugation`] | [`corrugation::CorrugationParams`] | [`rows::CorrugationRow`] stream + contact line |
//! | figures | [`figures::figures`] | [`figures::FiguresParams`] | one [`figures::Figure`] at a time |
//! | equilibrate | [`equilibrate::equilibrate`] | [`dem_run::DemParams`] | time series + [`rows::EquilibrateReport`] |
//! | slide | [`slide::slide`] | [`dem_run::DemParams`] | time series + [`rows::SlideReport`] |
//!
//! Shared pieces: [`progress`] (the callback trait and the terminal/log reporter), [`sink`] (row
//! sinks, streaming CSV through `OUT.partial`), [`output`] (path checks before the run, writing
//! every output with its sidecar, failures collected), [`meta`] (the sidecar: resolved scene,
//! parameters, command line, input hash), [`record`] (parameters in user units for the sidecar),
//! [`rows`] (ONE row type and schema per kind of output), [`budget`] (cost estimate and the size
//! guard behind `--force`).
//!
//! Adding a workflow (e.g. a `design` or `friction` study): a file here with a `…Params` struct,
//! an `estimate` for the size guard, a `record` entry, a row type in [`rows`] if it writes rows,
//! and a function `(scene, &params, sink, &dyn Progress) -> Result<stats>` that may call the
//! workflows above; then a thin command in `src/cli/`.

pub mod budget;
pub mod contacts;
pub mod corrugation;
pub mod dem_run;
pub mod equilibrate;
pub mod figures;
pub mod landscape;
pub mod merge;
pub mod meta;
pub mod output;
pub mod progress;
pub mod record;
pub mod resume;
pub mod rows;
pub mod screen;
pub mod shard;
pub mod sink;
pub mod slide;
pub mod slurm;
pub mod sweep;

pub use budget::Estimate;
pub use meta::Inputs;
pub use output::{check_outputs, Outputs, SweepRun};
pub use progress::{Progress, Reporter};
pub use shard::Shard;
pub use sweep::{ShardInfo, Sweep};
