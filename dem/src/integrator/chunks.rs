//! [`Chunking`]: how the per-step passes are cut into work items.
//!
//! Chunk sizes depend only on the amount of work (never on the thread count), and every
//! reduction adds its per-chunk partial results in chunk order, so a run is bit-identical on
//! any number of threads — or on one thread, which the engine uses when the work is too small
//! for a team of threads to pay (a few hundred active particles under the active set).

/// Most chunks per pass: enough to balance 2–16 threads with work stealing ([`super::team`]).
const MAX_CHUNKS: usize = 96;

/// Chunk sizes of the slider and substrate passes and whether to run them in parallel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Chunking {
    /// Slider spheres per chunk.
    pub sl: usize,
    /// Substrate spheres per chunk.
    pub sub: usize,
    /// Whether the passes are large enough to share between threads.
    pub par: bool,
}

impl Chunking {
    /// Chunking for `n_sl` slider spheres, `n_sub` substrate spheres and `n_pairs` pairs, with
    /// chunks of at least `min_chunk` particles (smaller chunks were measured slower on 2–16
    /// threads: more hand-outs and cache lines shared between threads), in parallel from
    /// `parallel_min_work` items on (handing a pass to a team and waiting for it costs a few
    /// µs, about the work of 2000 particles).
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

/// Picks, at run time, whether the eligible passes run on a team of threads or on the calling
/// thread alone: on a machine shared with other jobs a second thread can make a step slower.
/// A *probe* times alternating segments of steps in each mode, [`Tuner::PROBE_SEGMENTS`] in
/// all, each about [`Tuner::SEGMENT_S`] long, and keeps the mode with the smaller best time
/// per step (interference only slows a segment down, so the best of three is robust to it:
/// parallel is never kept when its best is slower, and one disturbed segment does not make it
/// lose). Between probes, a parallel stretch of at least a segment whose time per step is worse
/// than the one-thread best of the last probe (other jobs took cores since) switches to one
/// thread at once. A probe runs at the start and again after every [`Tuner::REPROBE_S`] of run
/// time. The choice never changes results (chunking is fixed by the work).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tuner {
    /// The faster mode at the last probe (parallel until the first probe ends).
    pub use_par: bool,
    /// Probe segments left (even: a parallel segment next, odd: one thread).
    left: u32,
    /// Best time per step (s) in this probe: `[one thread, parallel]`.
    best: [f64; 2],
    /// Steps per probe segment: `[one thread, parallel]`.
    seg: [u64; 2],
    /// Run time (s) since the last probe ended.
    since: f64,
    /// Best one-thread time per step (s) of the last probe.
    one_ref: f64,
}

impl Default for Tuner {
    fn default() -> Self {
        Tuner {
            use_par: true,
            left: Self::PROBE_SEGMENTS,
            best: [f64::INFINITY; 2],
            seg: [8; 2],
            since: 0.0,
            one_ref: f64::INFINITY,
        }
    }
}

impl Tuner {
    /// Segments of one probe (half in each mode).
    pub const PROBE_SEGMENTS: u32 = 6;
    /// Target length of a probe segment (s).
    pub const SEGMENT_S: f64 = 1e-3;
    /// Run time between two probes (s).
    pub const REPROBE_S: f64 = 4.0;

    /// Whether the next steps may run in parallel (a probe is due or parallel was faster).
    pub fn wants_par(&self) -> bool {
        self.left > 0 || self.use_par
    }

    /// The mode and length (steps, at most `remaining`) of the next segment.
    pub fn plan(&self, remaining: u64) -> (bool, u64) {
        if self.left > 0 {
            let par = self.left.is_multiple_of(2);
            (par, remaining.min(self.seg[par as usize]))
        } else {
            (self.use_par, remaining)
        }
    }

    /// Records a segment of `steps` steps in mode `par` that took `secs` seconds.
    pub fn record(&mut self, par: bool, steps: u64, secs: f64) {
        if steps == 0 {
            return;
        }
        if self.left == 0 {
            if par && steps >= self.seg[1] && secs / steps as f64 > self.one_ref {
                self.use_par = false;
            }
            self.since += secs;
            if self.since > Self::REPROBE_S {
                self.left = Self::PROBE_SEGMENTS;
            }
            return;
        }
        let m = par as usize;
        let per = secs / steps as f64;
        self.best[m] = self.best[m].min(per);
        self.seg[m] = ((Self::SEGMENT_S / per.max(1e-9)).ceil() as u64).clamp(4, 1 << 16);
        self.left -= 1;
        if self.left == 0 {
            self.use_par = self.best[1] < self.best[0];
            self.one_ref = self.best[0];
            self.best = [f64::INFINITY; 2];
            self.since = 0.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Tuner;

    /// Runs a probe with per-step times `par` / `one` (s) for the segments, in order.
    fn probe(t: &mut Tuner, par: [f64; 3], one: [f64; 3]) {
        for k in 0..3 {
            let (p, n) = t.plan(1000);
            assert!(p);
            t.record(true, n, par[k] * n as f64);
            let (p, n) = t.plan(1000);
            assert!(!p);
            t.record(false, n, one[k] * n as f64);
        }
    }

    #[test]
    fn the_faster_mode_wins_and_one_disturbed_segment_does_not_decide() {
        let mut t = Tuner::default();
        assert!(t.wants_par());
        // parallel 1.8x faster, but its first segment was hit by another job
        probe(&mut t, [9e-5, 4.4e-5, 4.5e-5], [8e-5, 8.1e-5, 8e-5]);
        assert!(t.use_par && t.wants_par());
        // segments sized to ~1 ms
        assert_eq!(t.plan(u64::MAX), (true, u64::MAX));
        // the next probe comes after REPROBE_S of run time; parallel is slower now
        t.record(true, 100_000, Tuner::REPROBE_S + 1.0);
        probe(&mut t, [9e-5, 8.5e-5, 9.5e-5], [8e-5, 12e-5, 8.2e-5]);
        assert!(!t.use_par && !t.wants_par());
        assert_eq!(t.plan(50), (false, 50));
    }

    #[test]
    fn a_parallel_stretch_slower_than_one_thread_switches_to_one_thread() {
        let mut t = Tuner::default();
        probe(&mut t, [4.5e-5, 4.4e-5, 4.6e-5], [8e-5, 8.1e-5, 8e-5]);
        assert!(t.use_par);
        // other jobs took the cores: a long parallel call at 9e-5 s per step
        t.record(true, 6000, 6000.0 * 9e-5);
        assert!(!t.use_par && !t.wants_par());
        // until the next probe
        t.record(false, 100_000, Tuner::REPROBE_S);
        assert!(t.wants_par());
    }

    #[test]
    fn probe_segments_last_about_a_millisecond() {
        let mut t = Tuner::default();
        let (_, n) = t.plan(1000);
        t.record(true, n, 1e-5 * n as f64);
        let (_, n) = t.plan(1000);
        t.record(false, n, 5e-5 * n as f64);
        assert_eq!(t.plan(1000), (true, 100));
        t.record(true, 100, 1e-3);
        assert_eq!(t.plan(1000), (false, 20));
    }
}
