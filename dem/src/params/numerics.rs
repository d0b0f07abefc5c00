//! [`NumericsParams`]: how the equations are integrated — time step, neighbour skin, the 0 K
//! viscous bath, the parallel passes' chunking and the overlap guard.

use serde::{Deserialize, Serialize};

/// The integrator's knobs (SI). None of them is a property of the physical system; all but
/// `parallel_min_work` and `chunk_min` change results (the step, the bath) within their
/// measured tolerances (docs/validation/dem-integrator.md).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NumericsParams {
    /// Time step (s). `None`: `dt_safety ×` the stable-step estimate of [`crate::stability`].
    pub dt: Option<f64>,
    /// Fraction of the estimated critical step used when `dt` is `None` (–).
    pub dt_safety: f64,
    /// Neighbour-list skin (m): pairs within `2R + skin` are listed; the list is rebuilt when
    /// any particle has moved more than `skin/2` since the last build.
    pub skin: f64,
    /// Damping time τ (s) of the 0 K Langevin-equivalent viscous damping; `f64::INFINITY` = off.
    pub damping_time: f64,
    /// Frame of that damping.
    pub damping_frame: DampingFrame,
    /// Smallest work chunk (particles) of the parallel passes. Chunk sizes depend only on the
    /// work and this knob, never on the thread count, so results are bit-identical for any
    /// number of threads.
    pub chunk_min: usize,
    /// Below this many active particles + pairs a step runs on one thread (handing a pass to
    /// the team of threads costs a few µs); above it `Sim::run_steps` times both modes now and
    /// then and keeps the faster (on a shared machine a second thread can be slower). 0 forces
    /// the parallel passes (tests). Does not change results.
    pub parallel_min_work: usize,
    /// Largest admissible overlap as a fraction of the sphere radius (the smaller of the
    /// slider's and the substrate's when they differ); beyond it the run stops
    /// with [`crate::DemError::Unstable`].
    pub overlap_bound: f64,
}

impl Default for NumericsParams {
    fn default() -> Self {
        NumericsParams {
            dt: None,
            dt_safety: 0.25,
            skin: 0.3e-6,
            damping_time: 1e-6,
            damping_frame: DampingFrame::Relative,
            chunk_min: 192,
            parallel_min_work: 2500,
            overlap_bound: 0.1,
        }
    }
}

/// In which frame the 0 K Langevin-equivalent viscous damping `−m (v − v_ref)/τ` acts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum DampingFrame {
    /// Substrate spheres: absolute (lab frame, they are tethered to fixed sites). Slider spheres:
    /// relative to the control layer's velocity. Control layer: z absolute, x/y relative to the
    /// support's velocity. A steadily sliding slider feels no drag, so the pulling-spring force
    /// measures contact friction only (default).
    Relative,
    /// Every particle damped against its absolute velocity (a plain `fix viscous`/`fix langevin`
    /// at 0 K). A slider sliding at v then feels an extra drag `Σm·v/τ` that adds to the spring
    /// force: 0.011 mN for the study scene at 0.1 m/s.
    Absolute,
}
