//! [`SweepPlan`]: a checked sweep command's items and cost.

use crate::runs::{budget::Estimate, sweep::Sweep};

/// A checked sweep command: its items and cost (what `superlube slurm` needs to cut it).
#[derive(Debug, Clone)]
pub struct SweepPlan {
    /// The sweep's items.
    pub sweep: Sweep,
    /// Cost of the part this command line computes (its shard).
    pub estimate: Estimate,
}
