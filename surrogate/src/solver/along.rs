//! [`Solver::solve_along`]: equilibria at the samples of a straight path, sharing candidate
//! searches and pair lists ([`super::path_pairs::PathChunk`]; `docs/validation/path-solve.md`).

use super::path_pairs::PathChunk;
use super::{Equilibrium, Model, Solver, Warm};
use crate::error::SceneError;
use rayon::prelude::*;

/// Sub-chunks (of `StraightPath::segment` each) sharing one candidate search: a chunk of path
/// runs one search and is solved by one thread (speed only; results are identical for any value).
const CHUNK_SEGMENTS: usize = 12;

/// The pair list's floor sits this many single-contact overlaps `δ(W_max)` below the highest
/// touch height (the z root's first bracket reaches one below it): speed only, a sample that
/// needs more is solved on every pair and the floor lowered (`docs/validation/path-solve.md`).
const BAND_OVERLAPS: f64 = 1.5;

/// After its first sample (a cold start), a chunk raises its floor to this many of the deepest
/// load's z-root depths below the top: the warm-started z root brackets a tenth of a depth
/// around the previous root and the tilt's working set reaches four depths below the top
/// (`docs/validation/path-solve.md`).
const WARM_BAND_DEPTHS: f64 = 5.0;

/// A chunk stops lowering its floor after this many samples that needed every pair, and solves
/// the rest of its samples on every pair (a commensurate path whose top drops by hundreds of nm).
const MAX_WIDENINGS: usize = 16;

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
        let per = if spacing > 0.0 {
            ((segment / spacing).round() as usize).max(1)
        } else {
            1
        };
        // the z root's first bracket for the heaviest load: one contact carrying it all
        let w_max = loads
            .iter()
            .copied()
            .filter(|w| w.is_finite() && *w > 0.0)
            .fold(0.0, f64::max);
        let partial = model != Model::Compliant && w_max > 0.0;
        let band = BAND_OVERLAPS * self.hertz().overlap_for_force(w_max);
        let gmax = self.lever_bound();
        // per chunk, per sample, per load
        type Solved<T> = Vec<Vec<Result<T, SceneError>>>;
        let solve_full = |ps: &super::PairSet, si: f64, which: &[usize]| {
            let w: Vec<f64> = which.iter().map(|&j| loads[j]).collect();
            self.solve_loads_pairs(ps, &w, model)
                .into_iter()
                .zip(which)
                .map(|(r, &j)| r.map(|eq| f(si, j, eq)))
                .collect::<Vec<_>>()
        };
        let all: Vec<usize> = (0..loads.len()).collect();
        // chunks of about CHUNK_SEGMENTS segments, of equal size (no stub of one sample)
        let n_chunks = s.len().div_ceil(per * CHUNK_SEGMENTS).max(1);
        let size = s.len().div_ceil(n_chunks).max(1);
        let chunks: Vec<Solved<T>> = s
            .par_chunks(size)
            .map(|chunk| {
                let mut pc = PathChunk::new(self, theta, origin, e, chunk, band);
                let mut warm = vec![Warm::default(); loads.len()];
                let mut widenings = 0;
                let mut tightened = false;
                let mut out: Solved<T> = Vec::with_capacity(chunk.len());
                for seg in chunk.chunks(per) {
                    let end = seg[seg.len() - 1];
                    pc.refresh(seg[0], end);
                    for &si in seg {
                        if !partial {
                            out.push(solve_full(&pc.full_at(si), si, &all));
                            continue;
                        }
                        let floor = pc.floor;
                        let before = warm.clone();
                        let got = self.solve_loads_partial(
                            pc.partial_at(si),
                            loads,
                            model,
                            floor,
                            gmax,
                            &mut warm,
                        );
                        let missing: Vec<usize> =
                            (0..loads.len()).filter(|&j| got[j].is_none()).collect();
                        let mut redone = Vec::with_capacity(missing.len());
                        // the lowest height the full solves of the missed loads relied on
                        let mut need = f64::INFINITY;
                        if !missing.is_empty() {
                            // from the same warm start, on a longer list: the answer does not
                            // depend on the list (nor, so, on the other loads or the floor).
                            // First every pair of the chunk's search (no new search), then,
                            // for the loads that still missed, every pair
                            // the loads `which` (indices into `loads`) solved on `ps` from
                            // their warm starts before this sample
                            let redo = |ps: &super::PairSet, which: &[usize], floor: f64| {
                                let w: Vec<f64> = which.iter().map(|&j| loads[j]).collect();
                                let mut wm: Vec<Warm> = which.iter().map(|&j| before[j]).collect();
                                let r =
                                    self.solve_loads_partial(ps, &w, model, floor, gmax, &mut wm);
                                (r, wm)
                            };
                            let deeper = pc.searched();
                            let (mut r, mut wm) = if deeper < floor {
                                pc.set_floor(deeper);
                                pc.refresh(si, end);
                                redo(pc.partial_at(si), &missing, deeper)
                            } else {
                                let wm = missing.iter().map(|&j| before[j]).collect();
                                (vec![None; missing.len()], wm)
                            };
                            let still: Vec<usize> =
                                (0..missing.len()).filter(|&m| r[m].is_none()).collect();
                            let full = (!still.is_empty()).then(|| pc.full_at(si));
                            if let Some(full) = &full {
                                let which: Vec<usize> = still.iter().map(|&m| missing[m]).collect();
                                let (rs, wms) = redo(full, &which, f64::NEG_INFINITY);
                                for ((&m, eq), wj) in still.iter().zip(rs).zip(wms) {
                                    r[m] = eq;
                                    wm[m] = wj;
                                }
                            }
                            for ((&j, eq), wj) in missing.iter().zip(r).zip(wm) {
                                need = need.min(wj.need);
                                warm[j] = wj;
                                redone.push(match eq {
                                    Some(eq) => Ok(f(si, j, eq)),
                                    // the error a fresh solve gives
                                    None => {
                                        let full = full.as_ref().expect("solved on every pair");
                                        solve_full(full, si, &[j]).pop().expect("one")
                                    }
                                });
                            }
                        }
                        let mut redone = redone.into_iter();
                        out.push(
                            got.into_iter()
                                .enumerate()
                                .map(|(j, eq)| match eq {
                                    Some(eq) => Ok(f(si, j, eq)),
                                    None => redone.next().expect("one full solve per miss"),
                                })
                                .collect(),
                        );
                        if !missing.is_empty() {
                            // lower the floor below what the full solve needed, by twice
                            // the shortfall (the path keeps going down), for the rest; to
                            // every pair after MAX_WIDENINGS: the list can then miss nothing
                            widenings += 1;
                            let gap = (floor - need).max(0.0);
                            pc.set_floor(if widenings < MAX_WIDENINGS && need.is_finite() {
                                need - gap - 0.25 * band
                            } else {
                                f64::NEG_INFINITY
                            });
                            pc.refresh(si, end);
                        } else if !tightened {
                            // warm starts look this far below the top: raise the floor to it
                            tightened = true;
                            let depth = warm.iter().map(|w| w.depth).fold(0.0, f64::max);
                            let warm_band = WARM_BAND_DEPTHS * depth + 1e-9 * band;
                            if depth.is_finite() && warm_band < band {
                                pc.set_floor(pc.top0 - warm_band);
                                pc.refresh(si, end);
                            }
                        }
                    }
                }
                out
            })
            .collect();
        let mut out: Vec<Result<Vec<T>, SceneError>> = loads
            .iter()
            .map(|_| Ok(Vec::with_capacity(s.len())))
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
}
