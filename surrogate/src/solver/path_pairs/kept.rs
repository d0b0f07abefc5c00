//! Swept candidate searches kept per thread, so that a later chunk of the same slider, rotation,
//! origin and span reuses one instead of scanning every slider sphere's capsule again: the same
//! path solved again at other loads (a tolerance search's disproof, then its verification), and
//! the paths of nearby directions (a tolerance box's direction offsets).
//!
//! A search kept for direction e_ref is widened by `r·c` (r the chunk's farthest path
//! coordinate from the origin, c = [`SHARE_CHORD`]): every pose `origin + s·e` of a direction
//! with `|e − e_ref| ≤ c` lies within `|s|·c ≤ r·c` of the pose `origin + s·e_ref`, so the kept
//! pairs are a superset of that direction's own search, in the same order (slider, then
//! substrate index). The chunk recomputes every track from its own positions and keeps the pairs
//! that can rise above its floor, exactly as after its own search, so every list and result is
//! bit-identical (`docs/validation/path-solve.md`).

use crate::contact::CandidatePair;
use std::cell::RefCell;

/// The largest chord `|e − e_ref|` between a chunk's direction and a kept search's for which the
/// search is reused, and the widening it costs that search (per metre of path from the origin):
/// 0.035 (2°) widens a 12 µm path's last chunk by 0.42 µm. Speed only.
pub(super) const SHARE_CHORD: f64 = 0.035;

/// Searches kept per thread (the most recent; a tolerance box's batch of samples at a few θ
/// offsets, two chunks each). Memory: each holds the candidate pairs of one chunk (≈ 0.3–1 MB
/// for the study's 3505-sphere slider).
const KEEP: usize = 8;

/// One kept search: what names it and its pairs.
struct Kept {
    key: Key,
    /// Its direction e_ref.
    e: [f64; 2],
    /// The floor (m, absolute) it covers.
    floor: f64,
    pairs: Vec<CandidatePair>,
}

/// The solver, θ, origin and span (bits) a search is kept for.
type Key = (u64, u64, [u64; 2], [u64; 2]);

/// What a chunk's search is kept and found under: its solver's id, its rotation θ (rad), its
/// origin (m), the span of its samples (m of path) and its direction e.
pub(super) struct Name {
    pub solver: u64,
    pub theta: f64,
    pub origin: [f64; 2],
    pub span: [f64; 2],
    pub e: [f64; 2],
}

thread_local! {
    static KEPT: RefCell<Vec<Kept>> = const { RefCell::new(Vec::new()) };
    /// Searches reused on this thread (tests).
    #[cfg(test)]
    static REUSED: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

fn key(c: &Name) -> Key {
    (
        c.solver,
        c.theta.to_bits(),
        c.origin.map(f64::to_bits),
        c.span.map(f64::to_bits),
    )
}

/// Fills `pairs` from a kept search for the chunk `c` (its key, and a direction within
/// [`SHARE_CHORD`]) that covers `floor` (m, absolute), and returns the floor that search covers;
/// `None` (nothing written) where none is kept. O(pairs).
pub(super) fn take(c: &Name, floor: f64, pairs: &mut Vec<CandidatePair>) -> Option<f64> {
    let k = key(c);
    let e = c.e;
    KEPT.with(|kept| {
        let mut kept = kept.borrow_mut();
        let i = kept.iter().rposition(|x| {
            x.key == k && x.floor <= floor && (x.e[0] - e[0]).hypot(x.e[1] - e[1]) <= SHARE_CHORD
        })?;
        // the most recently used last
        let x = kept.remove(i);
        pairs.clear();
        pairs.extend_from_slice(&x.pairs);
        let covered = x.floor;
        kept.push(x);
        #[cfg(test)]
        REUSED.with(|r| r.set(r.get() + 1));
        Some(covered)
    })
}

/// Keeps the search `found` of the chunk `c`, just run for `floor` (m, absolute) along its
/// direction and widened by [`SHARE_CHORD`], dropping the least recently used beyond [`KEEP`].
/// O(pairs), no allocation once the pool has grown.
pub(super) fn keep(c: &Name, floor: f64, found: &[CandidatePair]) {
    let k = key(c);
    KEPT.with(|kept| {
        let mut kept = kept.borrow_mut();
        let mut pairs = if kept.len() >= KEEP {
            kept.remove(0).pairs
        } else {
            Vec::new()
        };
        pairs.clear();
        pairs.extend_from_slice(found);
        kept.push(Kept {
            key: k,
            e: c.e,
            floor,
            pairs,
        });
    });
}

/// Forgets every kept search of this thread (tests: a chunk with nothing to reuse).
#[cfg(test)]
pub(super) fn clear() {
    KEPT.with(|kept| kept.borrow_mut().clear());
}

/// Searches reused on this thread so far (tests).
#[cfg(test)]
pub(super) fn reused() -> usize {
    REUSED.with(|r| r.get())
}
