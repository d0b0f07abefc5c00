//! [`run`]: the phase loop shared by `equilibrate` and `slide`.

use super::Sample;
use crate::integrator::Sim;
use crate::{checkpoint, DemError};
use std::path::PathBuf;

/// Which protocol.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunKind {
    /// Equilibrate under load only (`equilibrate_time`).
    Equilibrate,
    /// Equilibrate, attach spring and relax, slide (`equilibrate_time + relax_time + slide_time`).
    Slide,
}

/// Phase of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum Phase {
    /// Under load, control layer held laterally.
    Equilibrate,
    /// Spring attached, support at rest.
    Relax,
    /// Support moving.
    Slide,
}

/// Progress report, sent after every sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// Steps done.
    pub step: u64,
    /// Total steps of the run.
    pub total: u64,
    /// Current phase.
    pub phase: Phase,
    /// Latest sample.
    pub sample: Sample,
}

/// Output side of a run: checkpoints and snapshots.
#[derive(Debug, Clone, Default)]
pub struct RunIo {
    /// Checkpoint file, written atomically every `checkpoint_every` steps.
    pub checkpoint: Option<PathBuf>,
    /// Steps between checkpoints (0 = never).
    pub checkpoint_every: u64,
    /// Extended-XYZ file, one frame appended every `xyz_every` steps.
    pub xyz: Option<PathBuf>,
    /// Steps between snapshots (0 = never).
    pub xyz_every: u64,
}

/// Step counts `(equilibrate, relax, slide, sample_every)` of a run of `kind` for `sim`.
pub fn step_counts(sim: &Sim, kind: RunKind) -> (u64, u64, u64, u64) {
    let p = &sim.params;
    let n = |t: f64| (t / sim.dt).round().max(0.0) as u64;
    let (r, s) = match kind {
        RunKind::Equilibrate => (0, 0),
        RunKind::Slide => (n(p.relax_time), n(p.slide_time)),
    };
    (n(p.equilibrate_time), r, s, n(p.sample_interval).max(1))
}

/// Runs (or continues, if `sim.state.step > 0` after a checkpoint load) the protocol `kind`,
/// appending samples to `samples` and calling `progress` after each sample. Phase changes
/// happen at fixed step numbers, so a resumed run is bit-identical to an uninterrupted one.
pub fn run(
    sim: &mut Sim,
    kind: RunKind,
    io: &RunIo,
    samples: &mut Vec<Sample>,
    progress: &mut dyn FnMut(&Progress),
) -> Result<(), DemError> {
    let (ne, nr, ns, every) = step_counts(sim, kind);
    let total = ne + nr + ns;
    let phase = |step: u64| {
        if step < ne {
            Phase::Equilibrate
        } else if step < ne + nr {
            Phase::Relax
        } else {
            Phase::Slide
        }
    };
    if samples.is_empty() {
        samples.push(Sample::from_obs(&sim.observe()));
    }
    while sim.state.step < total {
        let step = sim.state.step;
        if kind == RunKind::Slide && step >= ne && !sim.state.spring_on {
            sim.attach_spring();
        }
        if kind == RunKind::Slide && step >= ne + nr && sim.state.support_v == [0.0; 2] {
            sim.start_support();
        }
        sim.step()?;
        let step = sim.state.step;
        if step.is_multiple_of(every) || step == total {
            sim.check()?;
            let s = Sample::from_obs(&sim.observe());
            samples.push(s);
            progress(&Progress {
                step,
                total,
                phase: phase(step.saturating_sub(1)),
                sample: s,
            });
        }
        if let Some(p) = &io.xyz {
            if io.xyz_every > 0 && step.is_multiple_of(io.xyz_every) {
                super::xyz::append_frame(p, sim).map_err(|e| DemError::Checkpoint {
                    path: p.display().to_string(),
                    why: e.to_string(),
                })?;
            }
        }
        if let Some(p) = &io.checkpoint {
            if io.checkpoint_every > 0 && step.is_multiple_of(io.checkpoint_every) {
                checkpoint::save(p, sim, samples)?;
            }
        }
    }
    Ok(())
}
