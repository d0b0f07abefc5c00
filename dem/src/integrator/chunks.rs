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
