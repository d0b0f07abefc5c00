//! [`SweepCommands`]: the sweep commands that `superlube slurm` cuts into shards, handed to it
//! by the command line's root (which knows every command) so that it need not import it.

use super::sweep_plan::SweepPlan;
use anyhow::Result;

/// The sweep commands (those with `--shard`/`--resume`) and the check of one's command line.
pub struct SweepCommands {
    /// Their names, as typed after `superlube`.
    pub names: &'static [&'static str],
    /// Parses and checks a sweep command line (`superlube <words>`) exactly as running it
    /// would, without running it: the command's name and its [`SweepPlan`]. Cost: the
    /// command's checks (no solve).
    pub check: fn(&[String]) -> Result<(&'static str, SweepPlan)>,
}
