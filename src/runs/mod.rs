//! # The run machinery: how a workflow's results reach the disk
//!
//! Below the workflows of [`crate::study`] and above the physics crates: path checks and the
//! size guard before a run ([`budget`], [`output`]), row sinks streaming through `OUT.partial`
//! ([`sink`]), the sidecar recording the inputs of every file ([`meta`]), progress reporting
//! ([`progress`]), and the sweep contract behind `--shard`, `--resume` and the Slurm scripts
//! ([`sweep`], [`shard`], [`resume`], [`slurm`]). Nothing here knows a workflow or a flag name;
//! the layer check (`.ci/layers`) keeps clap and `crate::cli` out.

pub mod budget;
pub mod meta;
pub mod output;
pub mod progress;
pub mod resume;
pub mod shard;
pub mod sink;
pub mod slurm;
pub mod stored;
pub mod sweep;

pub use budget::Estimate;
pub use meta::Inputs;
pub use output::{check_outputs, Outputs, SweepRun};
pub use progress::{Progress, Reporter};
pub use shard::Shard;
pub use sweep::{ShardInfo, Sweep};
