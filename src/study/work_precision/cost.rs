//! What a setting costs: the process's CPU time (user + system, every thread, from
//! `getrusage(RUSAGE_SELF)`, plus its waited-for child processes', `RUSAGE_CHILDREN`: the
//! LAMMPS run of the tiers diagram) and the wall time of one closure. CPU time is the cost the diagrams
//! plot: the machine the study runs on is shared, so wall time measures the neighbours too.

use std::time::Instant;

/// CPU and wall seconds of one measured piece of work.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Cost {
    /// CPU seconds of this process (user + system, summed over its threads).
    pub cpu_s: f64,
    /// Wall-clock seconds.
    pub wall_s: f64,
}

/// CPU seconds used so far by this process (user + system, every thread) and by the child
/// processes it has waited for.
pub fn process_cpu_s() -> f64 {
    usage_s(libc::RUSAGE_SELF) + usage_s(libc::RUSAGE_CHILDREN)
}

fn usage_s(who: libc::c_int) -> f64 {
    // SAFETY: getrusage writes into the zeroed struct we own; RUSAGE_SELF and RUSAGE_CHILDREN
    // are always valid.
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    let rc = unsafe { libc::getrusage(who, &mut u) };
    if rc != 0 {
        return 0.0;
    }
    let tv = |t: libc::timeval| {
        std::time::Duration::new(t.tv_sec.max(0) as u64, (t.tv_usec.max(0) as u32) * 1000)
            .as_secs_f64()
    };
    tv(u.ru_utime) + tv(u.ru_stime)
}

/// Runs `f` and returns its value with what it cost.
pub fn measure<T>(f: impl FnOnce() -> T) -> (T, Cost) {
    let (c0, w0) = (process_cpu_s(), Instant::now());
    let v = f();
    let cost = Cost {
        cpu_s: process_cpu_s() - c0,
        wall_s: w0.elapsed().as_secs_f64(),
    };
    (v, cost)
}

/// Runs `f` repeatedly until at least `min_cpu_s` CPU seconds have passed (at least once) and
/// returns its last value with the cost of **one** call (total / calls): for settings whose
/// single call is below the clock's resolution (a solve of ~1 ms).
pub fn measure_repeated<T>(min_cpu_s: f64, mut f: impl FnMut() -> T) -> (T, Cost) {
    let (c0, w0) = (process_cpu_s(), Instant::now());
    let mut calls = 0u32;
    loop {
        let v = f();
        calls += 1;
        let cpu = process_cpu_s() - c0;
        if cpu >= min_cpu_s || calls >= 10_000 {
            let n = calls as f64;
            return (
                v,
                Cost {
                    cpu_s: cpu / n,
                    wall_s: w0.elapsed().as_secs_f64() / n,
                },
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cpu_time_grows_with_work() {
        let (_, c) = measure(|| {
            let mut x = 0u64;
            for i in 0..20_000_000u64 {
                x = x.wrapping_mul(6364136223846793005).wrapping_add(i);
            }
            std::hint::black_box(x)
        });
        assert!(c.cpu_s > 0.0 && c.wall_s > 0.0, "{c:?}");
    }
}
