//! [`Team`]: the threads of one `Sim::run_steps` call, kept hot between the passes of the steps.
//!
//! A step is two passes over fixed chunks with a little sequential work between them (the
//! control layer), ~40 µs per pass on one thread for the study scene. A fork-join pool that
//! wakes its workers for every pass spends a good part of that in hand-offs, so one call of
//! `run_steps` starts its own team of `T − 1` threads (T = `rayon::current_num_threads()`, the
//! cores the run is given) that wait between passes by spinning on a generation counter (then
//! `yield_now`, then short parks, so a machine shared with other jobs is not burnt), and the
//! calling thread publishes each pass and takes part in it.
//!
//! A pass is `job(c)` for every chunk `c` of up to two groups (slider chunks `0..n₀`, then
//! substrate chunks `n₀..n₀+n₁`). Thread `t` owns the contiguous share `[t·n_g/T, (t+1)·n_g/T)`
//! of each group and claims its chunks one by one from its own counters, so a thread meets the
//! same particles in every pass and step (they stay in its cache); a thread that has run out
//! steals from the others' counters, so a slow, late or absent worker never holds the pass up
//! (the calling thread alone can run every chunk). Every chunk is run exactly once per pass,
//! and which thread runs it does not matter: each chunk writes only its own outputs, which the
//! caller combines in chunk order, so results are bit-identical for any number of threads.
//!
//! Protocol (all through atomics):
//! - the caller, with no claim of the previous pass outstanding (its `done` equals its `n`),
//!   stores the job, resets `done`, stores each thread's range (`Release`) and bumps `gen`;
//! - a claim is a `fetch_add(1)` (`Acquire`) on a range counter that returns `next < end`; it
//!   synchronizes with the caller's store of that range, so the job stored before is visible,
//!   and the job cannot be replaced while the claim is outstanding (`done` < `n`);
//! - each thread adds its completed chunks to `done` (`Release`) once it finds every range
//!   empty; the caller waits for `done == n` (`Acquire`), after which every chunk's writes are
//!   visible to it.

use crossbeam_utils::CachePadded;
use std::cell::UnsafeCell;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// A pass: `job(c)` for each chunk `c`.
type Job<'a> = dyn Fn(usize) + Sync + 'a;

/// How long a waiting thread spins before it starts yielding (s).
const SPIN: Duration = Duration::from_micros(50);
/// How long it yields before it parks in short naps.
const YIELD: Duration = Duration::from_millis(1);
/// One nap of a waiting thread.
const NAP: Duration = Duration::from_micros(100);

/// Shared state of a team (see the module doc).
pub(crate) struct Team {
    /// Per thread and group: its range of the current pass's chunk indices, `end << 32 | next`.
    ranges: Vec<CachePadded<[AtomicU64; 2]>>,
    /// Number of passes published so far.
    gen: CachePadded<AtomicU64>,
    /// Chunks of the current pass completed and reported.
    done: CachePadded<AtomicUsize>,
    /// The current pass (lifetime erased: it is only called under a claim, and the caller
    /// keeps it alive until every claim of its pass has completed).
    job: UnsafeCell<Option<*const Job<'static>>>,
    /// Set once: the workers return.
    stop: AtomicBool,
    /// Set while the caller runs steps on its own: waiting workers nap instead of spinning.
    idle: AtomicBool,
    /// A chunk of the pass panicked.
    panicked: AtomicBool,
}

// SAFETY: `job` is written only by the calling thread while no claim is outstanding and read
// by a worker only under a claim (module doc), so the cell is never accessed concurrently; the
// pointee is `Sync`. Every other field is atomic.
unsafe impl Sync for Team {}

impl Team {
    /// A team of `threads` threads (the caller is thread 0).
    fn new(threads: usize) -> Team {
        Team {
            ranges: (0..threads.max(1))
                .map(|_| CachePadded::new([AtomicU64::new(0), AtomicU64::new(0)]))
                .collect(),
            gen: CachePadded::new(AtomicU64::new(0)),
            done: CachePadded::new(AtomicUsize::new(0)),
            job: UnsafeCell::new(None),
            stop: AtomicBool::new(false),
            idle: AtomicBool::new(false),
            panicked: AtomicBool::new(false),
        }
    }

    /// Threads the team was made for, the caller included.
    fn threads(&self) -> usize {
        self.ranges.len()
    }

    /// Runs `job(c)` for every `c` in `0..n₀ + n₁` (`groups = [n₀, n₁]`) on the team, the
    /// calling thread included; returns when all have completed. Only the thread that created
    /// the team may call this.
    fn run(&self, groups: [usize; 2], job: &Job<'_>) {
        let n = groups[0] + groups[1];
        if n == 0 {
            return;
        }
        assert!(n < 1 << 31, "too many chunks in one pass");
        let ptr: *const Job<'_> = job;
        // SAFETY: only the lifetime bound is erased; `job` outlives every call through the
        // pointer, since this function returns only after all `n` chunks have completed.
        let ptr: *const Job<'static> = unsafe { std::mem::transmute(ptr) };
        // SAFETY: the previous pass has completed (`done == n` was observed before its `run`
        // returned), so no thread holds a claim and none reads the cell (module doc).
        unsafe { *self.job.get() = Some(ptr) };
        self.done.store(0, Ordering::Relaxed);
        let t = self.ranges.len();
        for (i, r) in self.ranges.iter().enumerate() {
            let mut off = 0;
            for (g, &m) in groups.iter().enumerate() {
                let (a, b) = (off + i * m / t, off + (i + 1) * m / t);
                r[g].store(((b as u64) << 32) | a as u64, Ordering::Release);
                off += m;
            }
        }
        self.gen.fetch_add(1, Ordering::Release);
        self.drain(0);
        let mut wait = Backoff::new();
        while self.done.load(Ordering::Acquire) < n {
            wait.snooze(false);
        }
        if self.panicked.load(Ordering::Relaxed) {
            panic!("a chunk of a DEM pass panicked");
        }
    }

    /// Claims and runs chunks, own range first (`me`), then the others'; reports the count.
    fn drain(&self, me: usize) {
        let t = self.ranges.len();
        let mut count = 0;
        for r in (0..t).flat_map(|k| &*self.ranges[(me + k) % t]) {
            loop {
                let v = r.load(Ordering::Relaxed);
                if v as u32 >= (v >> 32) as u32 {
                    break;
                }
                let v = r.fetch_add(1, Ordering::Acquire);
                let (next, end) = (v as u32, (v >> 32) as u32);
                if next >= end {
                    break;
                }
                // SAFETY: we hold a claim of the current pass, so the cell holds its job and
                // the caller keeps the closure alive until we report the chunk (module doc).
                let job = unsafe { (*self.job.get()).expect("a published pass") };
                let run = std::panic::AssertUnwindSafe(|| {
                    // SAFETY: as above: the pointee is alive while the claim is outstanding.
                    unsafe { (*job)(next as usize) }
                });
                // a panicking chunk still counts as done, so that the pass completes (no
                // thread then runs a chunk whose closure the caller's unwinding would drop);
                // the caller panics once the pass is over (the hook has printed the message)
                if std::panic::catch_unwind(run).is_err() {
                    self.panicked.store(true, Ordering::Relaxed);
                }
                count += 1;
            }
        }
        if count > 0 {
            self.done.fetch_add(count, Ordering::Release);
        }
    }

    /// The loop of worker `me` (1..threads): wait for a pass, take part, until stopped.
    fn work(&self, me: usize) {
        let mut seen = 0;
        loop {
            let mut wait = Backoff::new();
            loop {
                if self.stop.load(Ordering::Acquire) {
                    return;
                }
                let g = self.gen.load(Ordering::Acquire);
                if g != seen {
                    seen = g;
                    break;
                }
                wait.snooze(self.idle.load(Ordering::Relaxed));
            }
            self.drain(me);
        }
    }

    /// Tells the workers to return (after the pass in progress, if any).
    fn stop(&self) {
        self.stop.store(true, Ordering::Release);
    }

    /// `true`: the caller runs on its own for a while (waiting workers nap); `false`: passes
    /// follow (waiting workers spin).
    fn set_idle(&self, idle: bool) {
        self.idle.store(idle, Ordering::Relaxed);
    }
}

/// The calling thread's handle on a running team (see [`with_team`]).
pub(crate) struct Crew<'t> {
    team: &'t Team,
    workers: Vec<std::thread::Thread>,
}

impl Crew<'_> {
    /// Runs `job(c)` for every chunk `c` of the `groups` on the team ([`Team::run`]).
    #[inline]
    pub fn run(&self, groups: [usize; 2], job: &Job<'_>) {
        self.team.run(groups, job);
    }

    /// `true`: the caller runs on its own for a while (the workers nap); `false`: passes
    /// follow (the workers are woken and spin between passes).
    pub fn set_idle(&self, idle: bool) {
        self.team.set_idle(idle);
        if !idle {
            self.workers.iter().for_each(|w| w.unpark());
        }
    }
}

impl Drop for Crew<'_> {
    /// Stops the workers, also when the caller unwinds (the scope then joins them).
    fn drop(&mut self) {
        self.team.stop();
        self.workers.iter().for_each(|w| w.unpark());
    }
}

/// Runs `f` with a team of `threads` threads: the calling thread and `threads − 1` scoped
/// workers, joined before this returns. A worker that cannot be spawned is left out (the team
/// works with any number of workers, none included).
pub(crate) fn with_team<R>(threads: usize, f: impl FnOnce(&Crew<'_>) -> R) -> R {
    let team = Team::new(threads);
    std::thread::scope(|s| {
        let team = &team;
        let workers = (1..team.threads())
            .filter_map(|me| {
                std::thread::Builder::new()
                    .name(format!("dem-team-{me}"))
                    .spawn_scoped(s, move || team.work(me))
                    .ok()
                    .map(|h| h.thread().clone())
            })
            .collect();
        let crew = Crew { team, workers };
        f(&crew)
    })
}

/// Waiting: spin, then yield, then nap (see [`SPIN`], [`YIELD`], [`NAP`]).
struct Backoff {
    start: Option<Instant>,
    spins: u32,
}

impl Backoff {
    fn new() -> Backoff {
        Backoff {
            start: None,
            spins: 0,
        }
    }

    /// One wait; `nap` skips the spinning.
    #[inline]
    fn snooze(&mut self, nap: bool) {
        if nap {
            std::thread::park_timeout(NAP);
            return;
        }
        self.spins = self.spins.wrapping_add(1);
        // read the clock only every 64 waits
        if !self.spins.is_multiple_of(64) {
            std::hint::spin_loop();
            return;
        }
        let t = self.start.get_or_insert_with(Instant::now).elapsed();
        if t < SPIN {
            std::hint::spin_loop();
        } else if t < SPIN + YIELD {
            std::thread::yield_now();
        } else {
            std::thread::park_timeout(NAP);
        }
    }
}

/// A mutable slice shared by the chunks of a pass, each taking its own disjoint range.
pub(crate) struct Shards<'a, T> {
    ptr: *mut T,
    len: usize,
    _life: std::marker::PhantomData<&'a mut [T]>,
}

// SAFETY: elements are reached only through `Shards::range`, whose callers guarantee that no
// two live ranges overlap; `T: Send` lets a range be written on another thread.
unsafe impl<T: Send> Sync for Shards<'_, T> {}

impl<'a, T> Shards<'a, T> {
    /// Shares `s` for one pass.
    pub fn new(s: &'a mut [T]) -> Shards<'a, T> {
        Shards {
            ptr: s.as_mut_ptr(),
            len: s.len(),
            _life: std::marker::PhantomData,
        }
    }

    /// Elements `a..b`, clamped to the slice.
    ///
    /// # Safety
    /// No other reference into `a..b` may be live while the returned one is: callers take the
    /// range of one chunk, and the team runs each chunk once per pass.
    #[allow(clippy::mut_from_ref)]
    #[inline]
    pub unsafe fn range(&self, a: usize, b: usize) -> &mut [T] {
        let b = b.min(self.len);
        let a = a.min(b);
        // SAFETY: `a..b` lies inside the slice borrowed for `'a`; exclusivity is the caller's
        // contract above.
        unsafe { std::slice::from_raw_parts_mut(self.ptr.add(a), b - a) }
    }
}

/// Where the passes of a step run: on the calling thread alone, or on a team.
#[derive(Clone, Copy)]
pub(crate) enum Exec<'a, 't> {
    /// In chunk order on the calling thread.
    Alone,
    /// On a running team.
    Team(&'a Crew<'t>),
}

impl Exec<'_, '_> {
    /// `job(c)` for every chunk `c` in `0..n₀ + n₁` (`groups = [n₀, n₁]`: slider chunks, then
    /// substrate chunks): on the team when there is one and `par` (the pass is large enough to
    /// share), else in order on this thread. Same results either way.
    #[inline]
    pub fn pass(self, par: bool, groups: [usize; 2], job: &Job<'_>) {
        let n = groups[0] + groups[1];
        match self {
            Exec::Team(crew) if par && n > 1 => crew.run(groups, job),
            _ => (0..n).for_each(job),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{with_team, Exec};
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Every chunk of every pass runs exactly once, whatever the team size (more threads than
    /// cores included), and passes do not overlap.
    #[test]
    fn each_chunk_runs_once_per_pass() {
        for threads in [1, 2, 3, 5] {
            let runs: Vec<AtomicUsize> = (0..40).map(|_| AtomicUsize::new(0)).collect();
            let passes = 300;
            with_team(threads, |crew| {
                for p in 0..passes {
                    let groups = [p % 13, (p * 7) % 27];
                    let n = groups[0] + groups[1];
                    Exec::Team(crew).pass(true, groups, &|c| {
                        assert!(c < n);
                        // a chunk of the previous pass would have left an odd count behind
                        runs[c].fetch_add(1, Ordering::Relaxed);
                    });
                    for (c, r) in runs.iter().enumerate() {
                        let k = r.swap(0, Ordering::Relaxed);
                        assert_eq!(
                            k,
                            usize::from(c < n),
                            "pass {p}, chunk {c}, {threads} threads"
                        );
                    }
                }
            });
        }
    }

    /// A chunk that panics on any thread makes the pass panic on the calling thread, after the
    /// pass is over (the workers then stop).
    #[test]
    fn a_panicking_chunk_is_reported_by_the_caller() {
        let r = std::panic::catch_unwind(|| {
            with_team(3, |crew| {
                Exec::Team(crew).pass(true, [8, 8], &|c| {
                    if c == 11 {
                        panic!("chunk 11 fails (expected by the test)");
                    }
                });
            })
        });
        assert!(r.is_err());
    }
}
