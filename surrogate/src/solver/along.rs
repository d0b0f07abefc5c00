//! [`Solver::solve_along`]: equilibria at the samples of a straight path, sharing candidate
//! searches and pair lists (`chunk_solver.rs`, `path_pairs.rs`; `docs/validation/path-solve.md`).

use super::chunk_solver::{PathJob, Sample};
use super::{Equilibrium, Model, Solver};
use crate::error::SceneError;
use rayon::prelude::*;

/// Sub-chunks (of `StraightPath::segment` each) sharing one candidate search: a chunk of path
/// runs one search and is solved by one thread (speed only; results are identical for any value).
const CHUNK_SEGMENTS: usize = 12;

/// A straight path of slider poses: shifts `origin + s·e` from the scene's placement at
/// rotation θ.
#[derive(Debug, Clone, Copy)]
pub struct StraightPath<'a> {
    /// Slider rotation θ (rad).
    pub theta: f64,
    /// Shift (m) of the sample at s = 0 from the scene's placement.
    pub origin: [f64; 2],
    /// Unit direction e of the path in the substrate plane.
    pub e: [f64; 2],
    /// Distances s (m) of the samples along the path, ascending.
    pub s: &'a [f64],
    /// Length (m) of path sharing one candidate search (speed only; any value > 0 gives the
    /// same results).
    pub segment: f64,
}

impl Solver {
    /// Solves `model` at load `load` (N) at every sample of `path` and maps each equilibrium
    /// with `f(s, eq)`: [`Solver::solve_along_loads`] for one load (same results, same errors:
    /// the first failed sample's).
    pub fn solve_along<T, F>(
        &self,
        path: StraightPath,
        load: f64,
        model: Model,
        f: F,
    ) -> Result<Vec<T>, SceneError>
    where
        T: Send,
        F: Fn(f64, Equilibrium) -> T + Sync,
    {
        self.solve_along_loads(path, &[load], model, |si, _, eq| f(si, eq))
            .pop()
            .expect("one result per load")
    }

    /// [`Solver::solve_along`] for several loads (N) at once. Each sample continues from the
    /// previous one: its z root starts from the previous equilibrium of the same load, and once
    /// a sample escalated to the tilt model ([`Model::Auto`]) the next ones solve the tilt model
    /// directly, from the last two tilted states extrapolated (no rigid-z solve first; where the
    /// untilted state balances, that model's answer is it). So each equilibrium equals
    /// [`Solver::solve_loads_pairs`] on a fresh search
    /// ([`Solver::pairs_at`]) to the solver's tolerances (`force_rtol`, `moment_rtol`), and is
    /// bit-identical whatever the thread count and whichever other loads share the path.
    /// Returns, per load (in the order of `loads`), the mapped samples `f(s, load index, eq)` in
    /// sample order, or that load's first failed solve.
    ///
    /// The samples are cut into chunks of twelve segments of about `path.segment`
    /// (m); a chunk runs one candidate search (each sphere's swept capsule) and keeps, per segment,
    /// the pairs that can touch above a height floor (`PathChunk`): a sample filters and
    /// solves a few hundred pairs, not every slider sphere's. A sample whose solve would need a
    /// pair below the floor is solved again on every pair of the chunk's search where that
    /// reaches deep enough, else on every pair, and the floor lowered. Parallel over
    /// chunks (rayon), deterministic. Cost (study's 3505-sphere slider, 1.75 mN): see
    /// `docs/validation/path-solve.md`.
    pub fn solve_along_loads<T, F>(
        &self,
        path: StraightPath,
        loads: &[f64],
        model: Model,
        f: F,
    ) -> Vec<Result<Vec<T>, SceneError>>
    where
        T: Send,
        F: Fn(f64, usize, Equilibrium) -> T + Sync,
    {
        let StraightPath {
            theta,
            origin,
            e,
            s,
            segment,
        } = path;
        let spacing = if s.len() > 1 {
            (s[s.len() - 1] - s[0]) / (s.len() - 1) as f64
        } else {
            segment
        };
        // samples to a sub-chunk of about `segment`
        let per = if spacing > 0.0 {
            ((segment / spacing).round() as usize).max(1)
        } else {
            1
        };
        // chunks of about CHUNK_SEGMENTS segments, of equal size (no stub of one sample)
        let n_chunks = s.len().div_ceil(per * CHUNK_SEGMENTS).max(1);
        let size = s.len().div_ceil(n_chunks).max(1);
        let job = PathJob::new(self, loads, model, f);
        let chunks: Vec<Vec<Sample<T>>> = s
            .par_chunks(size)
            .map(|chunk| job.solve_chunk(theta, origin, e, chunk, per))
            .collect();
        per_load(loads.len(), s.len(), chunks)
    }
}

/// The samples' results regrouped per load (of `n_loads`, `n_samples` samples in all): each
/// load's mapped samples in order, or its first error. O(samples × loads).
fn per_load<T>(
    n_loads: usize,
    n_samples: usize,
    chunks: Vec<Vec<Sample<T>>>,
) -> Vec<Result<Vec<T>, SceneError>> {
    let mut out: Vec<Result<Vec<T>, SceneError>> = (0..n_loads)
        .map(|_| Ok(Vec::with_capacity(n_samples)))
        .collect();
    for sample in chunks.into_iter().flatten() {
        for (j, r) in sample.into_iter().enumerate() {
            if let Ok(v) = &mut out[j] {
                match r {
                    Ok(t) => v.push(t),
                    Err(e) => out[j] = Err(e),
                }
            }
        }
    }
    out
}
