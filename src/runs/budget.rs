//! Size guard: every sweep estimates its cost before it starts, and one above
//! [`MAX_SOLVES`] quasi-static solves is refused unless the user passes `--force`, with the
//! estimated time, memory and output size in the message.

use anyhow::{bail, Result};

/// Largest number of quasi-static solves a run may start without `--force` (about 10 min for the
/// study's 3505-sphere slider on 2 threads; the study's own screen is 1204 solves, a 51×51
/// landscape 2601, the corrugation figure 3.3·10⁵).
pub const MAX_SOLVES: u64 = 2_000_000;

/// Cost of one rigid-z solve per slider sphere (s): 0.54–0.76 ms for the 3505-sphere study
/// slider (docs/validation/screen.md, "Speed", release build) → 2.2·10⁻⁷ s; rounded up. Richer models
/// (rigid-tilt, compliant) cost more.
pub const SOLVE_SECONDS_PER_SPHERE: f64 = 2.5e-7;

/// Estimated cost of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// The flags that set the size, for the message (e.g. "`--theta-deg` × `--load-mn`").
    pub flags: String,
    /// Quasi-static solves.
    pub solves: u64,
    /// Estimated wall time (s).
    pub seconds: f64,
    /// Estimated peak memory (bytes).
    pub memory_bytes: f64,
    /// Estimated size of the output files (bytes).
    pub output_bytes: f64,
}

impl Estimate {
    /// The estimate of `solves` solves of a slider of `slider_spheres` spheres on a substrate of
    /// `substrate_spheres` spheres, parallel over the rayon threads, with `extra_memory` bytes held
    /// on top of the solver (e.g. a plot buffer) and `bytes_per_solve` bytes of output per solve.
    pub fn solves(
        flags: &str,
        solves: u64,
        slider_spheres: usize,
        substrate_spheres: usize,
        extra_memory: f64,
        bytes_per_solve: f64,
    ) -> Estimate {
        let threads = rayon::current_num_threads().max(1) as f64;
        // Solver: substrate spheres + bucket grid + BVH ≈ 200 B each; per thread: the slider's
        // pairs and work arrays ≈ 500 B per slider sphere; a bounded window of rows.
        let memory = 20e6
            + 200.0 * substrate_spheres as f64
            + threads * 500.0 * slider_spheres as f64
            + extra_memory;
        Estimate {
            flags: flags.to_string(),
            solves,
            seconds: solves as f64 * slider_spheres.max(1) as f64 * SOLVE_SECONDS_PER_SPHERE
                / threads,
            memory_bytes: memory,
            output_bytes: solves as f64 * bytes_per_solve,
        }
    }

    /// The estimate of `part` of `whole` equal work items of this sweep (a shard, or what a
    /// resumed run has left): solves, time and output scale, memory does not.
    pub fn part(&self, part: usize, whole: usize) -> Estimate {
        let f = if whole == 0 {
            1.0
        } else {
            part as f64 / whole as f64
        };
        Estimate {
            flags: self.flags.clone(),
            solves: (self.solves as f64 * f).ceil() as u64,
            seconds: self.seconds * f,
            memory_bytes: self.memory_bytes,
            output_bytes: self.output_bytes * f,
        }
    }

    /// The estimated wall time (s) on `threads` threads instead of this process's.
    pub fn seconds_on(&self, threads: usize) -> f64 {
        self.seconds * rayon::current_num_threads().max(1) as f64 / threads.max(1) as f64
    }

    /// One-line description: solves, time, memory, output size.
    pub fn describe(&self) -> String {
        format!(
            "{} quasi-static solves, estimated {} on {} thread(s), memory about {}, output about {}",
            self.solves,
            human_time(self.seconds),
            rayon::current_num_threads(),
            human_bytes(self.memory_bytes),
            human_bytes(self.output_bytes)
        )
    }

    /// Refuses the run above [`MAX_SOLVES`] unless `force`.
    pub fn check(&self, force: bool) -> Result<()> {
        if self.solves > MAX_SOLVES && !force {
            bail!(
                "{}: {} — above the limit of {} solves per run. Pass `--force` to run it anyway, \
                 or make the sweep smaller",
                self.flags,
                self.describe(),
                MAX_SOLVES
            );
        }
        Ok(())
    }
}

/// `12 s`, `3.4 min`, `5.1 h`, `2.3 days`, `4.0 years`.
pub fn human_time(s: f64) -> String {
    if s < 60.0 {
        format!("{s:.0} s")
    } else if s < 3600.0 {
        format!("{:.1} min", s / 60.0)
    } else if s < 86400.0 * 2.0 {
        format!("{:.1} h", s / 3600.0)
    } else if s < 86400.0 * 730.0 {
        format!("{:.1} days", s / 86400.0)
    } else {
        format!("{:.1} years", s / 86400.0 / 365.25)
    }
}

/// `512 B`, `3.2 MB`, `1.3 GB`, `4.0 TB`.
pub fn human_bytes(b: f64) -> String {
    let units = ["B", "kB", "MB", "GB", "TB", "PB"];
    let mut v = b;
    let mut i = 0;
    while v >= 1000.0 && i + 1 < units.len() {
        v /= 1000.0;
        i += 1;
    }
    if i == 0 {
        format!("{v:.0} {}", units[i])
    } else {
        format!("{v:.1} {}", units[i])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_above_the_limit_unless_forced() {
        let e = Estimate::solves("`--grid 100000`", 10_000_000_000, 3505, 12515, 0.0, 50.0);
        let msg = e.check(false).unwrap_err().to_string();
        assert!(msg.contains("--force") && msg.contains("--grid"), "{msg}");
        assert!(msg.contains("estimated") && msg.contains("memory"), "{msg}");
        assert!(e.check(true).is_ok());
        assert!(Estimate::solves("x", 2601, 3505, 12515, 0.0, 50.0)
            .check(false)
            .is_ok());
        assert_eq!(human_bytes(1.3e9), "1.3 GB");
        assert_eq!(human_time(90.0), "1.5 min");
    }
}
