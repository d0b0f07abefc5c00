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

impl Phase {
    /// The phase of step `step` (0-based) of a run of `ne` equilibration steps, then `nr`
    /// relaxation steps, then the slide. O(1).
    pub fn of_step(step: u64, ne: u64, nr: u64) -> Phase {
        if step < ne {
            Phase::Equilibrate
        } else if step < ne + nr {
            Phase::Relax
        } else {
            Phase::Slide
        }
    }
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
        RunKind::Slide => (n(p.protocol.relax_time), n(p.protocol.slide_time)),
    };
    (
        n(p.protocol.equilibrate_time),
        r,
        s,
        n(p.protocol.sample_interval).max(1),
    )
}

/// Steps a fresh `sim` through the slide protocol one [`Sim::step`] at a time, with the phase
/// changes of [`run`] (the pulling spring attached after the equilibration, the support started
/// after the relaxation), calling `after` with the engine after each step: for checks that look
/// inside every step. No samples, checkpoints or snapshots. Cost: the protocol's steps, on the
/// calling thread.
pub fn step_slide(sim: &mut Sim, mut after: impl FnMut(&Sim)) -> Result<(), DemError> {
    let (ne, nr, ns, _) = step_counts(sim, RunKind::Slide);
    for k in 0..ne + nr + ns {
        if k == ne {
            sim.attach_spring();
        }
        if k == ne + nr {
            sim.start_support();
        }
        sim.step()?;
        after(sim);
    }
    Ok(())
}

/// Runs (or continues, if `sim.state.step > 0` after a checkpoint load) the protocol `kind`,
/// appending samples to `samples` and calling `progress` after each sample. Phase changes
/// happen at fixed step numbers, so a resumed run is bit-identical to an uninterrupted one.
/// The `--xyz` file is replaced by a fresh run and continued exactly by a resumed one
/// ([`super::xyz::prepare_file`]). A checkpoint is written only after the state has passed
/// [`Sim::check`], so a blown-up state is never saved.
pub fn run(
    sim: &mut Sim,
    kind: RunKind,
    io: &RunIo,
    samples: &mut Vec<Sample>,
    progress: &mut dyn FnMut(&Progress),
) -> Result<(), DemError> {
    let (ne, nr, ns, every) = step_counts(sim, kind);
    let total = ne + nr + ns;
    let phase = |step: u64| Phase::of_step(step, ne, nr);
    let xyz_err = |p: &std::path::Path, e: std::io::Error| DemError::Checkpoint {
        path: p.display().to_string(),
        why: e.to_string(),
    };
    let xyz = io.xyz.as_deref().filter(|_| io.xyz_every > 0);
    if let Some(p) = xyz {
        super::xyz::prepare_file(p, sim).map_err(|e| xyz_err(p, e))?;
    }
    if samples.is_empty() {
        samples.push(Sample::from_obs(&sim.observe_sample()));
    }
    let next = |step: u64, k: u64| step.checked_div(k).map_or(u64::MAX, |q| (q + 1) * k);
    while sim.state.step < total {
        let step = sim.state.step;
        if kind == RunKind::Slide && step >= ne && !sim.state.spring_on {
            sim.attach_spring();
        }
        if kind == RunKind::Slide && step >= ne + nr && sim.state.support_v == [0.0; 2] {
            sim.start_support();
        }
        // run up to the next event: a sample, a snapshot, a checkpoint, a phase change, the end
        let mut to = total.min(next(step, every));
        if xyz.is_some() {
            to = to.min(next(step, io.xyz_every));
        }
        if io.checkpoint.is_some() {
            to = to.min(next(step, io.checkpoint_every));
        }
        if kind == RunKind::Slide {
            for b in [ne, ne + nr] {
                if b > step {
                    to = to.min(b);
                }
            }
        }
        sim.run_steps(to - step)?;
        let step = sim.state.step;
        let mut checked = false;
        if step.is_multiple_of(every) || step == total {
            sim.check()?;
            checked = true;
            let s = Sample::from_obs(&sim.observe_sample());
            samples.push(s);
            progress(&Progress {
                step,
                total,
                phase: phase(step.saturating_sub(1)),
                sample: s,
            });
        }
        if let Some(p) = xyz {
            if step.is_multiple_of(io.xyz_every) {
                let n = super::xyz::append_frame(p, sim).map_err(|e| xyz_err(p, e))?;
                sim.state.xyz_bytes += n;
                sim.state.xyz_frames += 1;
            }
        }
        if let Some(p) = &io.checkpoint {
            if io.checkpoint_every > 0 && step.is_multiple_of(io.checkpoint_every) {
                if !checked {
                    sim.check()?;
                }
                checkpoint::save(p, sim, samples)?;
            }
        }
    }
    Ok(())
}
