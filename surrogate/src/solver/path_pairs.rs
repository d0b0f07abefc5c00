//! [`PathChunk`]: the pair list of one stretch of a straight path, cut to the pairs that can
//! touch above a height floor and refreshed as the slider moves — a neighbour list with a skin,
//! the skin in height rather than in distance (`docs/validation/path-solve.md`).
//!
//! A slider sphere i and a substrate sphere j at lateral distance r touch when the slider's
//! reference plane sits below their touch height `c = h_j + drop_i + √(d² − r²)`. Along a
//! straight path the pair's lateral distance is `r(s)² = r⊥² + (s − s*)²`, so it can rise above
//! a floor F only inside the window `|s − s*| < √(ρ² − r⊥²)` with `ρ² = d² − (F − h − drop)²`.
//! The chunk runs one candidate search (its capsules narrowed to the lateral distance below which
//! any pair can rise above F), keeps the pairs that can rise above F somewhere, and
//! per sub-chunk the ones whose window meets it; a sample then looks at a few hundred pairs
//! instead of every slider sphere. The solve checks that it never relied on a pair below F
//! ([`Solver::solve_loads_partial`]); where it did, that sample is solved again on a longer list
//! (the chunk's whole search, else every pair) and the floor is lowered, so every result is
//! bit-identical to a solve on the full list.

mod kept;

use super::{PairSet, Pose, Solver};
use crate::contact::CandidatePair;
use crate::scene::place;
use std::cell::RefCell;

/// The buffers of a [`PathChunk`], kept per thread between chunks and paths: its swept search
/// and lists allocate nothing once they have grown to the scene's size (a fresh mapping of these
/// ≈ 1 MB per chunk cost more than its search, in page faults); only the one fresh search of
/// its first sample's top, and a sample solved on every pair, take a list of their own.
#[derive(Default)]
struct Buffers {
    wide: PairSet,
    tracks: Vec<Track>,
    above: Vec<Above>,
    live: Vec<Above>,
    ps: PairSet,
}

thread_local! {
    static BUFFERS: RefCell<Vec<Buffers>> = const { RefCell::new(Vec::new()) };
}

/// Where one candidate pair passes along the path.
#[derive(Debug, Clone, Copy)]
struct Track {
    /// Path coordinate s (m) of the closest lateral approach.
    s_star: f64,
    /// Lateral distance² (m²) at the closest approach.
    rp2: f64,
    /// `h + drop` (m): the touch height less `√(d² − r²)`.
    top: f64,
    /// Contact distance² d² (m²).
    d2: f64,
    /// The substrate sphere `[x, y, h]` (m), copied here by the search that reads it, so that
    /// setting a floor streams the tracks instead of gathering from the whole substrate.
    q: [f64; 3],
}

/// A pair that can rise above the floor, with what a sample needs of it (one contiguous
/// record, so a sample streams through its list): its window `[lo, hi]` (m of path), the
/// lateral distance² below which it rises above the floor (m², with margin), its contact
/// distance² (m²), the slider sphere's local position (m) and the substrate sphere `[x, y, h]`.
#[derive(Debug, Clone, Copy)]
struct Above {
    slider: u32,
    substrate: u32,
    lo: f64,
    hi: f64,
    rho2: f64,
    d2: f64,
    local: [f64; 2],
    q: [f64; 3],
}

/// How far a [`PathChunk`] has taken the pairs above its current floor from its tracks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Taken {
    /// The floor was just set: nothing taken.
    NotYet,
    /// One refresh took its live pairs straight from the tracks.
    Once,
    /// `above` holds every pair above the floor.
    Kept,
}

/// The first search of a chunk covers the pairs whose touch height can rise within this many
/// contact distances (plus the band) of the ceiling of every touch height
/// ([`Solver::touch_ceiling`]): 60 nm on the study's 3 µm spheres. In the default design 98 % of
/// chunks find their first sample's top within 10 nm of the ceiling, and a top further down
/// takes one more search (speed only: the capsules' radius, 1.9 µm at 0.5 µm deep, falls to
/// ≈ 0.8 µm; `docs/validation/path-solve.md`, "Sixth round").
const FIRST_DEPTH: f64 = 1.0 / 50.0;

/// Relative margin on the windows and lateral thresholds (far above the round-off of positions
/// ≈ 1e-16 of the substrate size): a pair is kept a little longer than it needs to be, never
/// dropped while it can matter.
const MARGIN: f64 = 1e-9;

/// The pair list of one chunk of a straight path at rotation θ (see the module documentation).
/// Buffers live as long as the chunk: a sample allocates nothing for its pairs.
pub(crate) struct PathChunk<'a> {
    solver: &'a Solver,
    theta: f64,
    sin_cos: (f64, f64),
    origin: [f64; 2],
    e: [f64; 2],
    /// The first and last sample (m of path).
    span: [f64; 2],
    /// The middle of the chunk (m of path) and the half-span vector (m) its search sweeps.
    mid: f64,
    half: [f64; 2],
    /// The lowest floor (m, absolute) the last candidate search covers.
    searched: f64,
    /// Every pair that can rise above `searched` at some sample of the chunk
    /// (slider-then-substrate order), from one candidate search.
    wide: PairSet,
    tracks: Vec<Track>,
    /// Height floor (m, absolute): every pair touching above it is in a sample's list.
    floor: f64,
    /// The highest touch height (m, absolute) at the chunk's first sample.
    top0: f64,
    above: Vec<Above>,
    /// How far the pairs above the current floor have been taken from the tracks.
    taken: Taken,
    /// Of `above`, those whose window meets the current sub-chunk.
    live: Vec<Above>,
    /// The current sample's partial list (positions filled only for its pairs).
    ps: PairSet,
    /// The sample (m of path) last listed by [`PathChunk::partial_at`] (or the sub-chunk's
    /// first) and the end of the current sub-chunk (`None` before the first): a new floor
    /// refreshes the live pairs from that sample to that end.
    at: f64,
    end: Option<f64>,
}

impl<'a> PathChunk<'a> {
    /// The chunk of samples `s` (m, ascending) of the path `origin + s·e` at rotation `theta`:
    /// the highest touch height at its first sample (one fresh search), then one candidate
    /// search over each sphere's swept capsule, narrowed to the pairs that can rise above the
    /// floor `band` (m) below that height (O(N_slider)).
    pub fn new(
        solver: &'a Solver,
        theta: f64,
        origin: [f64; 2],
        e: [f64; 2],
        s: &[f64],
        band: f64,
    ) -> PathChunk<'a> {
        let (a, b) = (s[0], s[s.len() - 1]);
        // every sample of the chunk lies within half its span (plus round-off) of the middle
        let half = 0.5 * (b - a).abs() * (1.0 + 1e-9) + 1e-15;
        let mut buf = BUFFERS.with(|b| b.borrow_mut().pop()).unwrap_or_default();
        let n = solver.slider_count();
        let mut ps = std::mem::take(&mut buf.ps);
        // positions are written for a sample's pairs only; stale entries are never read
        ps.slider_xy.resize(n, [0.0; 2]);
        ps.theta = theta;
        let mut chunk = PathChunk {
            solver,
            theta,
            sin_cos: theta.sin_cos(),
            origin,
            e,
            span: [a, b],
            mid: 0.5 * (a + b),
            half: [half * e[0], half * e[1]],
            searched: f64::INFINITY,
            ps,
            wide: std::mem::take(&mut buf.wide),
            tracks: std::mem::take(&mut buf.tracks),
            floor: f64::NEG_INFINITY,
            top0: f64::NEG_INFINITY,
            above: std::mem::take(&mut buf.above),
            taken: Taken::Kept,
            live: std::mem::take(&mut buf.live),
            at: a,
            end: None,
        };
        // one search serves the first sample's top and the chunk's list: the pairs that can
        // rise above FIRST_DEPTH + band below the ceiling of every touch height; the top at the
        // first sample is the highest of their heights there when it lies above that floor
        // (a top further down, e.g. commensurate hollows, takes a fresh search and a wider one)
        let first = solver.touch_ceiling() - FIRST_DEPTH * solver.touch_reach() - band;
        chunk.search(first);
        let top = chunk.top_of_tracks(a);
        chunk.top0 = if top > first { top } else { chunk.top_at(a) };
        chunk.set_floor(chunk.top0 - band);
        chunk
    }

    /// The highest touch height (m) at sample `si` of the pairs of the last search (−∞ without
    /// one touching): that of a fresh search where it lies above the searched floor (to the
    /// round-off of the tracks' lateral distances; it only places the floor). O(candidates).
    fn top_of_tracks(&self, si: f64) -> f64 {
        self.tracks
            .iter()
            .filter_map(|t| {
                let ds = si - t.s_star;
                let r2 = t.rp2 + ds * ds;
                (r2 < t.d2).then(|| t.top + (t.d2 - r2).sqrt())
            })
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Runs the chunk's candidate search for pairs that can rise above `floor` (m, absolute)
    /// and records where each passes along the path. O(N_slider + candidates).
    fn search(&mut self, floor: f64) {
        let solver = self.solver;
        let pose = self.pose(self.mid);
        self.searched = floor;
        if let Some(covered) = kept::take(&self.kept_name(), floor, &mut self.wide.pairs) {
            // a kept search of a nearby direction: its pairs, this direction's positions
            self.wide.centre = solver.fill_slider_xy(pose, &mut self.wide.slider_xy);
            self.wide.theta = pose.theta;
            self.searched = covered;
        } else {
            let extra = self.reach_out() * kept::SHARE_CHORD;
            solver.pairs_swept_into(pose, self.half, floor, extra, &mut self.wide);
            kept::keep(&self.kept_name(), floor, &self.wide.pairs);
        }
        let (mid, e) = (self.mid, self.e);
        let sub = solver.substrate();
        self.tracks.clear();
        let wide = &self.wide;
        self.tracks.extend(wide.pairs.iter().map(|c| {
            let p = wide.slider_xy[c.slider as usize];
            let q = sub[c.substrate as usize];
            let v = [q[0] - p[0], q[1] - p[1]];
            let along = v[0] * e[0] + v[1] * e[1];
            Track {
                s_star: mid + along,
                rp2: (v[0] * v[0] + v[1] * v[1] - along * along).max(0.0),
                top: c.h + solver.slider_drop(c.slider),
                d2: solver.pair_reach2(c.slider, c.substrate),
                q,
            }
        }));
    }

    /// What this chunk's search is kept and found under ([`kept`]).
    fn kept_name(&self) -> kept::Name {
        kept::Name {
            solver: self.solver.id,
            theta: self.theta,
            origin: self.origin,
            span: self.span,
            e: self.e,
        }
    }

    /// The lowest floor (m, absolute) the chunk's last candidate search covers: setting the
    /// floor down to it takes no new search.
    pub fn searched(&self) -> f64 {
        self.searched
    }

    /// The farthest path coordinate |s| (m) of the chunk from the path's origin: a direction
    /// turned by a chord c moves its poses by at most this times c.
    fn reach_out(&self) -> f64 {
        let h = self.half[0].hypot(self.half[1]);
        self.mid.abs() + h
    }

    fn pose(&self, si: f64) -> Pose {
        Pose {
            theta: self.theta,
            shift: [
                self.origin[0] + si * self.e[0],
                self.origin[1] + si * self.e[1],
            ],
        }
    }

    /// The highest touch height (m) of any pair at sample `si` (−∞ without one), from a fresh
    /// search. O(N_slider).
    fn top_at(&self, si: f64) -> f64 {
        let ps = self.solver.pairs_at(self.pose(si));
        let mut top = f64::NEG_INFINITY;
        for c in &ps.pairs {
            let d2 = self.solver.pair_reach2(c.slider, c.substrate);
            if c.r2 < d2 {
                top = top.max(c.h + self.solver.slider_drop(c.slider) + (d2 - c.r2).sqrt());
            }
        }
        top
    }

    /// The height floor (m, absolute): every pair touching above it is in a sample's list.
    pub fn floor(&self) -> f64 {
        self.floor
    }

    /// The highest touch height (m, absolute) at the chunk's first sample.
    pub fn top0(&self) -> f64 {
        self.top0
    }

    /// Sets the floor (m, absolute) and takes the pairs that can rise above it from the tracks
    /// for the rest of the current sub-chunk, from the sample last listed on (a new candidate
    /// search first where the floor falls below what the last one covered). O(candidates),
    /// plus that search.
    pub fn set_floor(&mut self, floor: f64) {
        if floor < self.searched {
            self.search(floor);
        }
        self.floor = floor;
        self.above.clear();
        self.taken = Taken::NotYet;
        self.live.clear();
        if let Some(end) = self.end {
            self.refresh(self.at, end);
        }
    }

    /// Starts the sub-chunk of samples `[a, b]` (m of path, within the chunk): its samples are
    /// listed from the pairs above the floor whose window meets it. O(candidates) for the first
    /// two sub-chunks after the floor is set, then O(pairs above the floor).
    pub fn enter(&mut self, a: f64, b: f64) {
        self.at = a;
        self.end = Some(b);
        self.refresh(a, b);
    }

    /// The pairs of the tracks that can rise above the floor, with their windows, in the
    /// search's order. O(1) each.
    fn above_tracks(&self) -> impl Iterator<Item = Above> + '_ {
        let floor = self.floor;
        self.tracks
            .iter()
            .zip(&self.wide.pairs)
            .filter_map(move |(t, c)| {
                let rise = floor - t.top;
                let rho2 = if rise > 0.0 {
                    if rise * rise >= t.d2 * (1.0 + MARGIN) {
                        return None;
                    }
                    t.d2 - rise * rise
                } else {
                    t.d2
                };
                let rho2 = rho2 * (1.0 + MARGIN) + MARGIN * MARGIN * t.d2;
                if rho2 <= t.rp2 {
                    return None;
                }
                let w = (rho2 - t.rp2).sqrt() + MARGIN * t.d2.sqrt();
                Some(Above {
                    slider: c.slider,
                    substrate: c.substrate,
                    lo: t.s_star - w,
                    hi: t.s_star + w,
                    rho2,
                    d2: t.d2,
                    local: self.solver.slider_local(c.slider),
                    q: t.q,
                })
            })
    }

    /// Keeps, of the pairs above the floor, those whose window meets `[a, b]` (m of path): the
    /// list every sample of that sub-chunk filters. The first refresh after the floor is set
    /// takes them straight from the tracks (a floor often serves one sub-chunk: the chunk's
    /// first, solved cold); the second keeps every pair above the floor for the next ones.
    /// O(candidates) for those two, then O(pairs above the floor); the same list either way.
    fn refresh(&mut self, a: f64, b: f64) {
        let meets = |x: &Above| x.hi >= a && x.lo <= b;
        let mut live = std::mem::take(&mut self.live);
        live.clear();
        match self.taken {
            Taken::NotYet => {
                self.taken = Taken::Once;
                live.extend(self.above_tracks().filter(meets));
            }
            Taken::Once | Taken::Kept => {
                if self.taken == Taken::Once {
                    self.taken = Taken::Kept;
                    let mut above = std::mem::take(&mut self.above);
                    above.extend(self.above_tracks());
                    self.above = above;
                }
                live.extend(self.above.iter().filter(|x| meets(x)));
            }
        }
        self.live = live;
    }

    /// The partial pair list at sample `si` (m): every pair within contact distance whose touch
    /// height can be above the floor, in the order of a full search, with the exact lateral
    /// distances of [`Solver::pairs_from`]. O(live pairs), no allocation. `si` lies in the
    /// current sub-chunk ([`PathChunk::enter`]), at or after the sample listed before.
    pub fn partial_at(&mut self, si: f64) -> &PairSet {
        self.at = si;
        let pose = self.pose(si);
        let ps = &mut self.ps;
        ps.pairs.clear();
        // the centre and positions as [`Solver::pairs_at`] computes them (same bits)
        let centre = self.solver.centre_at(pose);
        ps.centre = centre;
        for x in &self.live {
            let p = place(centre, self.sin_cos, x.local);
            let (dx, dy) = (x.q[0] - p[0], x.q[1] - p[1]);
            let r2 = dx * dx + dy * dy;
            if r2 < x.d2 && r2 < x.rho2 {
                ps.slider_xy[x.slider as usize] = p;
                ps.pairs.push(CandidatePair {
                    slider: x.slider,
                    substrate: x.substrate,
                    r2,
                    h: x.q[2],
                });
            }
        }
        &self.ps
    }

    /// The full pair list at sample `si` (m): a fresh search ([`Solver::pairs_at`]). O(N_slider).
    pub fn full_at(&self, si: f64) -> PairSet {
        self.solver.pairs_at(self.pose(si))
    }
}

impl Drop for PathChunk<'_> {
    /// Hands the buffers back to this thread's pool.
    fn drop(&mut self) {
        let buf = Buffers {
            wide: std::mem::take(&mut self.wide),
            tracks: std::mem::take(&mut self.tracks),
            above: std::mem::take(&mut self.above),
            live: std::mem::take(&mut self.live),
            ps: std::mem::take(&mut self.ps),
        };
        BUFFERS.with(|b| b.borrow_mut().push(buf));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;
    use proptest::prelude::*;

    /// The touch height `h + drop + √(d² − r²)` (m) of a pair of a fresh search.
    fn height(solver: &Solver, c: &CandidatePair) -> f64 {
        let d2 = solver.pair_reach2(c.slider, c.substrate);
        c.h + solver.slider_drop(c.slider) + (d2 - c.r2).max(0.0).sqrt()
    }

    fn key(c: &CandidatePair) -> (u32, u32, u64, u64) {
        (c.slider, c.substrate, c.r2.to_bits(), c.h.to_bits())
    }

    /// One sample's list: its pairs' keys and a hash of their slider positions.
    type List = (Vec<(u32, u32, u64, u64)>, u64);

    /// Every sample's list of `pc`, lowering the floor by `lower` (m) halfway.
    fn lists(pc: &mut PathChunk, s: &[f64], lower: f64) -> Vec<List> {
        let mut out = Vec::new();
        for (k, &si) in s.iter().enumerate() {
            pc.enter(si, si);
            if k == s.len() / 2 {
                let f = pc.floor() - lower;
                pc.set_floor(f);
            }
            let ps = pc.partial_at(si);
            let xy: u64 = ps
                .pairs
                .iter()
                .map(|c| ps.slider_xy[c.slider as usize])
                .fold(0, |h, p| {
                    h.rotate_left(7) ^ p[0].to_bits() ^ p[1].to_bits().rotate_left(3)
                });
            out.push((ps.pairs.iter().map(key).collect(), xy));
        }
        out
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// A chunk that reuses the search kept by a chunk of a nearby direction (same slider,
        /// θ, origin and span) gives every sample the same list, bit for bit, as a chunk with
        /// nothing kept, also after its floor is lowered. Wide bands put the floor near the
        /// kept search's edge (the test fails when the widening is removed).
        #[test]
        fn a_kept_search_gives_the_same_lists(
            theta_deg in 0.0f64..60.0,
            dir_deg in 0.0f64..360.0,
            turn_deg in -2.0f64..2.0,
            second in any::<bool>(),
            band in 0.3e-6f64..1.5e-6,
            lower in 0.0f64..900e-9,
            rough in any::<bool>(),
        ) {
            let mut sc = Scene::preset("square-tri").unwrap();
            sc.slider.radius = 20e-6;
            sc.substrate.size = [100e-6, 100e-6];
            sc.substrate.sigma_h = if rough { 0.01e-6 } else { 0.0 };
            let solver = Solver::new(&sc).unwrap();
            let theta = theta_deg.to_radians();
            let dir = |d: f64| [d.to_radians().cos(), d.to_radians().sin()];
            // the second chunk of a 12 µm path, or the first
            let s: Vec<f64> = (0..=20).map(|k| (k as f64 + if second { 100.0 } else { 0.0 }) * 0.06e-6).collect();
            let origin = [0.2e-6, -0.1e-6];
            kept::clear();
            let fresh = lists(&mut PathChunk::new(&solver, theta, origin, dir(dir_deg), &s, band), &s, lower);
            kept::clear();
            // the kept search's direction turned by up to 2°
            drop(PathChunk::new(&solver, theta, origin, dir(dir_deg + turn_deg), &s, band));
            let before = kept::reused();
            let again = lists(&mut PathChunk::new(&solver, theta, origin, dir(dir_deg), &s, band), &s, lower);
            prop_assert!(kept::reused() > before, "the kept search was not reused");
            prop_assert_eq!(fresh, again);
        }

    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// After any sequence of moves along the path, shorter and longer than the skin (the
        /// window a pair is kept beyond its closest approach), a sample's list holds exactly the
        /// pairs of a fresh search that touch above the floor (plus, within the margin, a few
        /// below it), with bit-identical lateral distances, in the fresh search's order, also
        /// after the floor is lowered (a wider search); and `full_at` is a fresh search. Flat
        /// and rough substrates, two pattern pairs.
        #[test]
        fn updated_list_matches_a_fresh_search(
            theta_deg in 0.0f64..60.0,
            dir_deg in 0.0f64..360.0,
            ox in -1.5e-6f64..1.5e-6,
            oy in -1.5e-6f64..1.5e-6,
            moves in proptest::collection::vec(0.001e-6f64..1.5e-6, 2..12),
            band in 5e-9f64..600e-9,
            lower in 0.0f64..900e-9,
            rough in any::<bool>(),
            tri in any::<bool>(),
        ) {
            let mut sc = Scene::preset(if tri { "tri-tri" } else { "square-tri" }).unwrap();
            sc.slider.radius = 12e-6;
            sc.substrate.size = [80e-6, 80e-6];
            sc.substrate.sigma_h = if rough { 0.01e-6 } else { 0.0 };
            let solver = Solver::new(&sc).unwrap();
            let (theta, dir) = (theta_deg.to_radians(), dir_deg.to_radians());
            let e = [dir.cos(), dir.sin()];
            let mut s = vec![0.0];
            for m in &moves {
                s.push(s[s.len() - 1] + m);
            }
            let mut pc = PathChunk::new(&solver, theta, [ox, oy], e, &s, band);
            // one sub-chunk for the whole chunk, then one per sample (both are valid uses), then
            // the whole chunk below a lowered floor (a new, wider candidate search; the new
            // floor refreshes the live pairs itself)
            for phase in 0..3 {
                let per_sample = phase == 1;
                if !per_sample {
                    pc.enter(s[0], s[s.len() - 1]);
                }
                if phase == 2 {
                    let f = pc.floor() - lower;
                    pc.set_floor(f);
                }
                let floor = pc.floor();
                for &si in &s {
                    if per_sample {
                        pc.enter(si, si);
                    }
                    let pose = Pose { theta, shift: [ox + si * e[0], oy + si * e[1]] };
                    let fresh = solver.pairs_at(pose);
                    let full = pc.full_at(si);
                    prop_assert_eq!(
                        fresh.pairs.iter().map(key).collect::<Vec<_>>(),
                        full.pairs.iter().map(key).collect::<Vec<_>>()
                    );
                    let list: Vec<_> = pc.partial_at(si).pairs.iter().map(key).collect();
                    let above: Vec<_> = fresh
                        .pairs
                        .iter()
                        .filter(|c| height(&solver, c) > floor)
                        .map(key)
                        .collect();
                    // the list is an ordered sub-sequence of the fresh search holding `above`
                    let mut it = fresh.pairs.iter().map(key);
                    for k in &list {
                        prop_assert!(it.any(|f| f == *k), "{:?} not in the fresh order", k);
                    }
                    for k in &above {
                        prop_assert!(list.contains(k), "{:?} above the floor is missing", k);
                    }
                    // positions of the listed spheres are the fresh search's
                    let ps = pc.partial_at(si);
                    for c in &ps.pairs {
                        let i = c.slider as usize;
                        prop_assert_eq!(ps.slider_xy[i], fresh.slider_xy[i]);
                    }
                    prop_assert_eq!(ps.centre, fresh.centre);
                }
            }
        }
    }
}
