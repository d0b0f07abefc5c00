//! `--shard i/n` and `--resume`, the flags every sweep command shares, and their checks.

use crate::runs::{output::SweepRun, shard::Shard, sweep::Sweep};
use anyhow::{bail, Result};
use std::path::Path;

/// Sharding and resuming of a sweep (`screen`, `landscape`, `corrugation`).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct SweepArgs {
    /// Compute only shard I of N of the sweep (zero-based, 0 ≤ I < N): the I-th of N
    /// contiguous, nearly equal blocks of its items (θ values, grid points, α values), written
    /// to `--out` with the shard recorded in the sidecar; `superlube merge` joins the N shard
    /// files into the unsharded output, byte for byte. Needs `--out`.
    #[arg(long, value_name = "I/N", allow_hyphen_values = true)]
    pub shard: Option<String>,
    /// Continue an interrupted run of the same command and `--out`: the rows already in
    /// FILE.partial are kept (after checking that its sidecar has the same inputs and shard; a
    /// torn last line is cut off) and only the rest is computed. Without a partial file the run
    /// starts from the beginning.
    #[arg(long)]
    pub resume: bool,
}

impl SweepArgs {
    /// The parsed `--shard` (errors name the flag).
    pub fn shard(&self) -> Result<Option<Shard>> {
        self.shard
            .as_deref()
            .map(|s| Shard::parse(s, "--shard"))
            .transpose()
    }

    /// Checks the flags against the command's outputs — `out` (`--out`) and `extras`, the other
    /// output flags given (a shard writes only its rows) — and makes the run of `sweep`.
    pub fn run(&self, sweep: Sweep, out: Option<&Path>, extras: &[&str]) -> Result<SweepRun> {
        let shard = self.shard()?;
        if shard.is_some() {
            if out.is_none() {
                bail!("`--shard` needs `--out FILE.csv`: `superlube merge` reads the shard's file and its sidecar");
            }
            if let Some(flag) = extras.first() {
                bail!(
                    "`{flag}` cannot be combined with `--shard`: a shard holds only part of the sweep; \
                     write `{flag}` from an unsharded run"
                );
            }
        }
        if self.resume && out.is_none() {
            bail!("`--resume` needs `--out FILE` (the file whose partial output it continues)");
        }
        SweepRun::new(sweep, shard, self.resume)
    }
}
