//! [`Chunking`]: how the per-step passes are cut into work items.
//!
//! Chunk sizes depend only on the amount of work (never on the thread count), and every
//! reduction adds its per-chunk partial results in chunk order, so a run is bit-identical on
//! any number of threads — or on one thread, which the engine uses when the work is too small
//! for the fork-join to pay (a few hundred active particles under the active set).

/// Most chunks per pass: enough to balance 2–16 threads with work stealing.
const MAX_CHUNKS: usize = 96;

/// Chunk sizes of the slider and substrate passes and whether to run them in parallel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Chunking {
    /// Slider spheres per chunk.
    pub sl: usize,
    /// Substrate spheres per chunk.
    pub sub: usize,
    /// Whether the passes run on the rayon pool.
    pub par: bool,
}

impl Chunking {
    /// Chunking for `n_sl` slider spheres, `n_sub` substrate spheres and `n_pairs` pairs, with
    /// chunks of at least `min_chunk` particles (a task smaller than ~200 particles costs more
    /// to hand out than to run), in parallel from `parallel_min_work` items on (the fork-join of
    /// a pass costs a few µs, about the work of 2000 particles).
    pub fn for_work(
        n_sl: usize,
        n_sub: usize,
        n_pairs: usize,
        min_chunk: usize,
        parallel_min_work: usize,
    ) -> Chunking {
        let len = |n: usize| n.div_ceil(MAX_CHUNKS).max(min_chunk).max(1);
        Chunking {
            sl: len(n_sl),
            sub: len(n_sub),
            par: n_sl + n_sub + n_pairs >= parallel_min_work && rayon::current_num_threads() > 1,
        }
    }

    /// Number of slider chunks for `n` slider spheres (at least 1).
    pub fn n_sl_chunks(&self, n: usize) -> usize {
        n.div_ceil(self.sl).max(1)
    }
}

/// Picks, at run time, whether the eligible passes run in parallel or on one thread: on a
/// machine shared with other jobs a second thread can make a step slower. Every
/// [`Tuner::PERIOD`] calls of `Sim::run_steps` it times one call in each mode (per step) and
/// keeps the faster. The choice never changes results (chunking is fixed by the work).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tuner {
    calls: u64,
    t_par: f64,
    /// The faster mode at the last probe.
    pub use_par: bool,
    /// The mode of the current call.
    pub use_par_now: bool,
}

impl Default for Tuner {
    fn default() -> Self {
        Tuner {
            calls: 0,
            t_par: 0.0,
            use_par: true,
            use_par_now: true,
        }
    }
}

impl Tuner {
    /// Calls between two probes.
    pub const PERIOD: u64 = 32;

    /// The mode of the next call: probe parallel, probe sequential, or the current choice.
    pub fn begin(&mut self) -> bool {
        match self.calls % Self::PERIOD {
            0 => true,
            1 => false,
            _ => self.use_par,
        }
    }

    /// Records the time per step (s) of the call just made in mode `par`.
    pub fn end(&mut self, per_step: f64) {
        match self.calls % Self::PERIOD {
            0 => self.t_par = per_step,
            1 => self.use_par = self.t_par <= per_step,
            _ => {}
        }
        self.calls += 1;
    }
}
