//! [`ChunkSolver`]: the equilibria at one chunk of a straight path's samples, solved on the
//! chunk's pair list ([`PathChunk`]) under the rules that place its height floor
//! (`docs/validation/path-solve.md`).

use super::path_pairs::PathChunk;
use super::{Equilibrium, Model, PairSet, Solver, Warm};
use crate::error::SceneError;

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

/// One sample's results, per load: the mapped equilibrium, or the error a solve on every pair
/// gives.
pub(super) type Sample<T> = Vec<Result<T, SceneError>>;

/// What every chunk of one path solve shares: the solver, the loads (N), the model, the map of
/// each equilibrium `f(s, load index, eq)`, and the floor's first band.
pub(super) struct PathJob<'a, F> {
    solver: &'a Solver,
    loads: &'a [f64],
    model: Model,
    f: F,
    /// Whether samples are solved on partial lists (not for the compliant model, nor without a
    /// positive load): else every sample is solved on a fresh search.
    partial: bool,
    /// The floor's first depth (m) below the chunk's top: [`BAND_OVERLAPS`] overlaps of the
    /// heaviest load on one contact.
    band: f64,
    /// Bound on every slider sphere's lever `|arm|/L` ([`Solver::lever_bound`]).
    gmax: f64,
}

impl<'a, T, F> PathJob<'a, F>
where
    F: Fn(f64, usize, Equilibrium) -> T,
{
    /// The job of solving `model` at `loads` (N) along a path of `solver`'s scene. O(loads).
    pub fn new(solver: &'a Solver, loads: &'a [f64], model: Model, f: F) -> Self {
        // the z root's first bracket for the heaviest load: one contact carrying it all
        let w_max = loads
            .iter()
            .copied()
            .filter(|w| w.is_finite() && *w > 0.0)
            .fold(0.0, f64::max);
        PathJob {
            solver,
            loads,
            model,
            f,
            partial: model != Model::Compliant && w_max > 0.0,
            band: BAND_OVERLAPS * solver.hertz().overlap_for_force(w_max),
            gmax: solver.lever_bound(),
        }
    }

    /// Solves the samples `chunk` (m of path, ascending) of the path `origin + s·e` (m) at
    /// rotation `theta` (rad), `per` samples to a sub-chunk: per sample, per load, the mapped
    /// result. One candidate search, then O(live pairs) per sample and load ([`ChunkSolver`]).
    pub fn solve_chunk(
        &self,
        theta: f64,
        origin: [f64; 2],
        e: [f64; 2],
        chunk: &[f64],
        per: usize,
    ) -> Vec<Sample<T>> {
        let mut cs = ChunkSolver {
            job: self,
            pc: PathChunk::new(self.solver, theta, origin, e, chunk, self.band),
            warm: vec![Warm::default(); self.loads.len()],
            widenings: 0,
            tightened: false,
        };
        let mut out = Vec::with_capacity(chunk.len());
        for seg in chunk.chunks(per) {
            cs.pc.enter(seg[0], seg[seg.len() - 1]);
            for &si in seg {
                out.push(cs.sample(si));
            }
        }
        out
    }

    /// The loads `which` (indices into the loads) solved on `ps` at sample `si`, as a solve on
    /// a fresh search gives them (results and errors).
    fn solve_full(&self, ps: &PairSet, si: f64, which: &[usize]) -> Sample<T> {
        let w: Vec<f64> = which.iter().map(|&j| self.loads[j]).collect();
        self.solver
            .solve_loads_pairs(ps, &w, self.model)
            .into_iter()
            .zip(which)
            .map(|(r, &j)| r.map(|eq| (self.f)(si, j, eq)))
            .collect()
    }

    /// The loads `which` solved on the partial list `ps` (every pair above `floor`, m) from
    /// their warm starts `before` (one per load): per load of `which`, the equilibrium or
    /// `None` where it needed a pair below the floor, and its updated warm start.
    fn solve_partial(
        &self,
        ps: &PairSet,
        which: &[usize],
        before: &[Warm],
        floor: f64,
    ) -> (Vec<Option<Equilibrium>>, Vec<Warm>) {
        let w: Vec<f64> = which.iter().map(|&j| self.loads[j]).collect();
        let mut wm: Vec<Warm> = which.iter().map(|&j| before[j]).collect();
        let r = self
            .solver
            .solve_loads_partial(ps, &w, self.model, floor, self.gmax, &mut wm);
        (r, wm)
    }
}

/// The solve of one chunk: its pair list, each load's warm start from the previous sample, and
/// the floor rules — the first floor a band below the top ([`PathChunk::new`]), raised once after
/// the first sample that missed nothing ([`ChunkSolver::tighten`]), lowered after each sample
/// that did ([`ChunkSolver::widen`]). Every result is bit-identical to a solve on every pair.
struct ChunkSolver<'j, 'a, F> {
    job: &'j PathJob<'a, F>,
    pc: PathChunk<'a>,
    warm: Vec<Warm>,
    /// Samples that needed a pair below the floor so far.
    widenings: usize,
    /// Whether the floor was raised after the first sample.
    tightened: bool,
}

impl<T, F> ChunkSolver<'_, '_, F>
where
    F: Fn(f64, usize, Equilibrium) -> T,
{
    /// Every load at sample `si` (m of path, in the current sub-chunk, after the one before):
    /// on the partial list, and the loads it missed again on longer ones ([`ChunkSolver::redo`]).
    /// O(live pairs) per load but for those.
    fn sample(&mut self, si: f64) -> Sample<T> {
        let job = self.job;
        if !job.partial {
            let all: Vec<usize> = (0..job.loads.len()).collect();
            return job.solve_full(&self.pc.full_at(si), si, &all);
        }
        let floor = self.pc.floor();
        let before = self.warm.clone();
        let got = job.solver.solve_loads_partial(
            self.pc.partial_at(si),
            job.loads,
            job.model,
            floor,
            job.gmax,
            &mut self.warm,
        );
        let missing: Vec<usize> = (0..job.loads.len()).filter(|&j| got[j].is_none()).collect();
        if missing.is_empty() {
            let out = got
                .into_iter()
                .enumerate()
                .map(|(j, eq)| Ok((job.f)(si, j, eq.expect("solved"))))
                .collect();
            self.tighten();
            return out;
        }
        let (redone, need) = self.redo(si, &missing, &before, floor);
        let mut redone = redone.into_iter();
        let out = got
            .into_iter()
            .enumerate()
            .map(|(j, eq)| match eq {
                Some(eq) => Ok((job.f)(si, j, eq)),
                None => redone.next().expect("one full solve per miss"),
            })
            .collect();
        self.widen(floor, need);
        out
    }

    /// The loads `missing` of sample `si` solved again from their warm starts `before`, on a
    /// longer list: the answer does not depend on the list (nor, so, on the other loads or the
    /// floor). First every pair of the chunk's search where it reaches below `floor` (m; no new
    /// search, the floor lowered to it), then every pair for the loads that still missed.
    /// Returns their results (in the order of `missing`) and the lowest height (m, absolute)
    /// they relied on.
    fn redo(
        &mut self,
        si: f64,
        missing: &[usize],
        before: &[Warm],
        floor: f64,
    ) -> (Sample<T>, f64) {
        let job = self.job;
        let deeper = self.pc.searched();
        let (mut r, mut wm) = if deeper < floor {
            self.pc.set_floor(deeper);
            job.solve_partial(self.pc.partial_at(si), missing, before, deeper)
        } else {
            let wm = missing.iter().map(|&j| before[j]).collect();
            (vec![None; missing.len()], wm)
        };
        let still: Vec<usize> = (0..missing.len()).filter(|&m| r[m].is_none()).collect();
        let full = (!still.is_empty()).then(|| self.pc.full_at(si));
        if let Some(full) = &full {
            let which: Vec<usize> = still.iter().map(|&m| missing[m]).collect();
            let (rs, wms) = job.solve_partial(full, &which, before, f64::NEG_INFINITY);
            for ((&m, eq), wj) in still.iter().zip(rs).zip(wms) {
                r[m] = eq;
                wm[m] = wj;
            }
        }
        let mut need = f64::INFINITY;
        let mut out = Vec::with_capacity(missing.len());
        for ((&j, eq), wj) in missing.iter().zip(r).zip(wm) {
            need = need.min(wj.need);
            self.warm[j] = wj;
            out.push(match eq {
                Some(eq) => Ok((job.f)(si, j, eq)),
                // the error a fresh solve gives
                None => {
                    let full = full.as_ref().expect("solved on every pair");
                    job.solve_full(full, si, &[j]).pop().expect("one")
                }
            });
        }
        (out, need)
    }

    /// After a sample that needed the heights down to `need` (m) below the floor `floor` (m):
    /// the floor goes below `need` by twice the shortfall (the path keeps going down), for the
    /// rest; to every pair after [`MAX_WIDENINGS`]: the list can then miss nothing.
    fn widen(&mut self, floor: f64, need: f64) {
        self.widenings += 1;
        let gap = (floor - need).max(0.0);
        let band = self.job.band;
        self.pc
            .set_floor(if self.widenings < MAX_WIDENINGS && need.is_finite() {
                need - gap - 0.25 * band
            } else {
                f64::NEG_INFINITY
            });
    }

    /// After the first sample that missed nothing: warm starts look [`WARM_BAND_DEPTHS`] of the
    /// deepest load's z-root depth below the top; the floor rises to there where that is above
    /// the first band. Once per chunk.
    fn tighten(&mut self) {
        if self.tightened {
            return;
        }
        self.tightened = true;
        let band = self.job.band;
        let depth = self.warm.iter().map(|w| w.depth).fold(0.0, f64::max);
        let warm_band = WARM_BAND_DEPTHS * depth + 1e-9 * band;
        if depth.is_finite() && warm_band < band {
            let top0 = self.pc.top0();
            self.pc.set_floor(top0 - warm_band);
        }
    }
}
