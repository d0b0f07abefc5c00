//! [`Prepared`]: a sweep command checked and ready to run, the one skeleton of `screen`,
//! `landscape`, `corrugation` and `friction` (each command's `prepare` makes it after every
//! check; its `execute` runs it; `superlube slurm` asks it for its [`SweepPlan`]).

use super::scene_args::Resolved;
use super::sweep_plan::SweepPlan;
use crate::runs::{budget::Estimate, output::SweepRun};

/// A checked sweep command, ready to run: its flags `A`, the resolved scene, the workflow's
/// parameters `P`, the part of the sweep this command line computes and that part's cost.
pub struct Prepared<A, P> {
    /// The command's flags.
    pub(super) a: A,
    /// The resolved scene, with its warnings.
    pub(super) sc: Resolved,
    /// The workflow's parameters.
    pub(super) params: P,
    /// The part of the sweep this command line computes (its shard, what it resumes).
    pub(super) run: SweepRun,
    /// The cost of that part.
    pub(super) estimate: Estimate,
}

impl<A, P> Prepared<A, P> {
    /// The sweep and its cost (for `superlube slurm`). Cost: a copy of the sweep's description.
    pub fn plan(&self) -> SweepPlan {
        SweepPlan {
            sweep: self.run.sweep.clone(),
            estimate: self.estimate.clone(),
        }
    }
}
