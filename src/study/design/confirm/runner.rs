//! [`DemRunner`]: how the DEM confirmation runs a batch of `slide` runs. In a design, the
//! study layer's batch runner ([`BatchRunner`]: side by side, one thread each, each run
//! reused by its input hash or resumed from its checkpoint); in a test, an oracle.

use crate::runs::progress::Progress;
use crate::study::batch::{run_batch, SlideJob, SlideOutcome};
use anyhow::Result;
use std::path::Path;

/// Runs a batch of DEM `slide` runs.
pub trait DemRunner: Sync {
    /// The outcomes of `jobs`, in order, `threads` runs side by side, each in `dir/<name>/`;
    /// a failing run is an outcome with its error, not an `Err`. Cost: the runs.
    fn run(
        &self,
        jobs: &[SlideJob],
        threads: usize,
        dir: &Path,
        progress: &dyn Progress,
    ) -> Result<Vec<SlideOutcome>>;
}

/// The study layer's batch runner ([`run_batch`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct BatchRunner;

impl DemRunner for BatchRunner {
    fn run(
        &self,
        jobs: &[SlideJob],
        threads: usize,
        dir: &Path,
        progress: &dyn Progress,
    ) -> Result<Vec<SlideOutcome>> {
        run_batch(jobs, threads, dir, progress)
    }
}
