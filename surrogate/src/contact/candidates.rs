//! Candidate slider–substrate sphere pairs: pairs close enough laterally that they can touch.

use super::CellList;

/// A slider–substrate pair that can touch: lateral distance² `r2` (m²) below `(2R)²`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CandidatePair {
    /// Index into the slider's sphere list.
    pub slider: u32,
    /// Index into the substrate's sphere list.
    pub substrate: u32,
    /// Squared lateral (x, y) centre distance (m²).
    pub r2: f64,
    /// Substrate sphere height h (m).
    pub h: f64,
}

/// Finds, for a set of slider sphere positions, every substrate sphere within a lateral distance
/// `reach` (m). Implementations: [`GridSearch`] (uniform hash grid); a parry3d BVH may add another.
pub trait CandidateSearch: Sync {
    /// Appends to `out` every pair with lateral distance < `reach`, in slider order then
    /// substrate index order (deterministic).
    fn pairs(&self, slider_xy: &[[f64; 2]], reach: f64, out: &mut Vec<CandidatePair>);
}

/// Appends the pair (slider `si` at `p`, substrate `k` at `q = [x, y, h]`) to `out` if their
/// lateral distance² is below `r2max` (m²).
#[inline]
pub(crate) fn push_if_within(
    out: &mut Vec<CandidatePair>,
    si: usize,
    p: [f64; 2],
    k: u32,
    q: [f64; 3],
    r2max: f64,
) {
    let dx = q[0] - p[0];
    let dy = q[1] - p[1];
    let r2 = dx * dx + dy * dy;
    if r2 < r2max {
        out.push(CandidatePair {
            slider: si as u32,
            substrate: k,
            r2,
            h: q[2],
        });
    }
}

/// Uniform bucket grid over the substrate spheres. Build O(n); query O(1) per slider sphere.
#[derive(Debug, Clone)]
pub struct GridSearch {
    spheres: Vec<[f64; 3]>,
    cells: CellList,
}

impl GridSearch {
    /// Builds the grid with cell size `cell` (m) (use the contact reach, 2R).
    pub fn new(spheres: &[[f64; 3]], cell: f64) -> Self {
        let xy: Vec<[f64; 2]> = spheres.iter().map(|p| [p[0], p[1]]).collect();
        GridSearch {
            spheres: spheres.to_vec(),
            cells: CellList::new(&xy, cell),
        }
    }

    /// The substrate spheres `[x, y, h]` (m) the grid was built on.
    pub fn spheres(&self) -> &[[f64; 3]] {
        &self.spheres
    }
}

/// The squared distance (m²) from the point `v` (m) to the segment from `−half` to `+half` (m),
/// `h2 = |half|²`: the closest a substrate sphere at `v` from a slider sphere comes while the
/// slider moves by `±half`. O(1).
#[inline]
pub(crate) fn swept_distance2(v: [f64; 2], half: [f64; 2], h2: f64) -> f64 {
    let t = if h2 > 0.0 {
        ((v[0] * half[0] + v[1] * half[1]) / h2).clamp(-1.0, 1.0)
    } else {
        0.0
    };
    let w = [v[0] - t * half[0], v[1] - t * half[1]];
    w[0] * w[0] + w[1] * w[1]
}

impl GridSearch {
    /// Appends every pair whose lateral distance is below `reach` (m) somewhere on the straight
    /// move of each slider sphere from `p − half` to `p + half` (`p` in `slider_xy`, `half` in
    /// m): the pairs of every pose of a straight stretch of path, from one scan of the cells
    /// around each sphere's swept capsule (those of its bounding box that the capsule's slab
    /// crosses, [`CellList::for_near_segment`]). `r2` is the lateral distance² at `p`. Slider
    /// order, then substrate index order. O(N_slider · (rows + points scanned + hits log hits)).
    pub fn pairs_swept(
        &self,
        slider_xy: &[[f64; 2]],
        half: [f64; 2],
        reach: f64,
        out: &mut Vec<CandidatePair>,
    ) {
        let h2 = half[0] * half[0] + half[1] * half[1];
        let r2max = reach * reach * (1.0 + 1e-9);
        let mut local: Vec<CandidatePair> = Vec::with_capacity(32);
        for (si, p) in slider_xy.iter().enumerate() {
            local.clear();
            self.cells.for_near_segment(*p, half, reach, |k| {
                let q = self.spheres[k as usize];
                let v = [q[0] - p[0], q[1] - p[1]];
                if swept_distance2(v, half, h2) < r2max {
                    local.push(CandidatePair {
                        slider: si as u32,
                        substrate: k,
                        r2: v[0] * v[0] + v[1] * v[1],
                        h: q[2],
                    });
                }
            });
            local.sort_unstable_by_key(|c| c.substrate);
            out.extend_from_slice(&local);
        }
    }
}

impl CandidateSearch for GridSearch {
    fn pairs(&self, slider_xy: &[[f64; 2]], reach: f64, out: &mut Vec<CandidatePair>) {
        let r2max = reach * reach;
        let span = (reach / self.cells.cell()).ceil() as i64;
        let mut local: Vec<CandidatePair> = Vec::with_capacity(16);
        for (si, p) in slider_xy.iter().enumerate() {
            local.clear();
            self.cells.for_within_cells(*p, span, |k| {
                push_if_within(&mut local, si, *p, k, self.spheres[k as usize], r2max)
            });
            local.sort_by_key(|c| c.substrate);
            out.extend_from_slice(&local);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// `pairs_swept` as it was before the capsule scan: every cell of each capsule's box.
    fn pairs_swept_box(
        g: &GridSearch,
        slider_xy: &[[f64; 2]],
        half: [f64; 2],
        reach: f64,
    ) -> Vec<CandidatePair> {
        let h2 = half[0] * half[0] + half[1] * half[1];
        let r2max = reach * reach * (1.0 + 1e-9);
        let ext = [half[0].abs() + reach, half[1].abs() + reach];
        let mut out = Vec::new();
        for (si, p) in slider_xy.iter().enumerate() {
            let mut local = Vec::new();
            let lo = [p[0] - ext[0], p[1] - ext[1]];
            let hi = [p[0] + ext[0], p[1] + ext[1]];
            g.cells.for_in_box(lo, hi, |k| {
                let q = g.spheres[k as usize];
                let v = [q[0] - p[0], q[1] - p[1]];
                if swept_distance2(v, half, h2) < r2max {
                    local.push(CandidatePair {
                        slider: si as u32,
                        substrate: k,
                        r2: v[0] * v[0] + v[1] * v[1],
                        h: q[2],
                    });
                }
            });
            local.sort_unstable_by_key(|c| c.substrate);
            out.extend_from_slice(&local);
        }
        out
    }

    /// Substrate points (µm scale, in m): a jittered lattice of pitch `a` or uniform random.
    fn points(lattice: bool, a: f64, n: usize, seed: u64) -> Vec<[f64; 3]> {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let side = (n as f64).sqrt().ceil() as usize;
        (0..n)
            .map(|k| {
                if lattice {
                    let (i, j) = ((k % side) as f64, (k / side) as f64);
                    [i * a + 0.5 * j * a, j * a * 0.75f64.sqrt(), 0.0]
                } else {
                    let s = side as f64 * a;
                    [
                        rng.random_range(0.0..s),
                        rng.random_range(0.0..s),
                        rng.random_range(-1e-7..1e-7),
                    ]
                }
            })
            .collect()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        /// The capsule scan finds exactly the pairs of the bounding-box scan, in the same order,
        /// and visits a subsequence of the box's points.
        #[test]
        fn capsule_scan_matches_box_scan(
            lattice in any::<bool>(),
            seed in any::<u64>(),
            cell_f in prop_oneof![0.1f64..0.5, 0.5f64..3.0],
            dir in prop_oneof![
                Just(0.0), Just(90.0), Just(180.0), Just(-90.0), Just(45.0), Just(0.3),
                -180.0f64..180.0
            ],
            len_f in prop_oneof![Just(0.0), Just(1e-160), 0.0f64..0.3, 0.0f64..8.0],
            reach_f in prop_oneof![Just(1.0), 0.0f64..1.0, 0.5f64..3.0],
            sliders in proptest::collection::vec((-0.3f64..1.3, -0.3f64..1.3), 1..40),
        ) {
            let a = 3e-6;
            let span = 20.0 * a;
            let slider_xy: Vec<[f64; 2]> =
                sliders.iter().map(|&(x, y)| [x * span, y * span]).collect();
            let (s, c) = dir.to_radians().sin_cos();
            let half = [len_f * a * c, len_f * a * s];
            let reach = reach_f * a;
            // the random points, and points just inside each capsule's edge (sides and caps)
            let mut subs = points(lattice, a, 400, seed);
            let len = half[0].hypot(half[1]);
            let e = if len > 0.0 { [half[0] / len, half[1] / len] } else { [1.0, 0.0] };
            let d = reach * (1.0 - 1e-10);
            for p in &slider_xy {
                for t in [-1.0, -0.5, 0.0, 0.5, 1.0] {
                    for side in [-1.0, 1.0] {
                        let (x, y) = (p[0] + t * half[0], p[1] + t * half[1]);
                        subs.push([x - side * d * e[1], y + side * d * e[0], 0.0]);
                        let cap = 0.7 * t * side;
                        subs.push([x + d * (cap * e[0] - side * 0.7 * e[1]), y + d * (cap * e[1] + side * 0.7 * e[0]), 0.0]);
                    }
                }
            }
            // and points just inside the cell corners within reach of a segment: a cell the scan
            // skipped wrongly would hold one (the grid's origin and size are unchanged by them)
            let cell = cell_f * a;
            let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
            for q in &subs {
                for k in 0..2 {
                    lo[k] = lo[k].min(q[k]);
                    hi[k] = hi[k].max(q[k]);
                }
            }
            let h2 = half[0] * half[0] + half[1] * half[1];
            let mut probes = Vec::new();
            for p in &slider_xy {
                let ext = [half[0].abs() + reach, half[1].abs() + reach];
                let c0 = [((p[0] - ext[0] - lo[0]) / cell).floor(), ((p[1] - ext[1] - lo[1]) / cell).floor()];
                let c1 = [((p[0] + ext[0] - lo[0]) / cell).floor(), ((p[1] + ext[1] - lo[1]) / cell).floor()];
                if (c1[0] - c0[0]) * (c1[1] - c0[1]) > 4000.0 {
                    continue;
                }
                for i in c0[0] as i64..=c1[0] as i64 {
                    for j in c0[1] as i64..=c1[1] as i64 {
                        for (di, dj) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                            let nudge = [1e-9 - di as f64 * 2e-9, 1e-9 - dj as f64 * 2e-9];
                            let q = [
                                lo[0] + ((i + di) as f64 + nudge[0]) * cell,
                                lo[1] + ((j + dj) as f64 + nudge[1]) * cell,
                            ];
                            let inside = q[0] > lo[0] && q[0] < hi[0] && q[1] > lo[1] && q[1] < hi[1];
                            let v = [q[0] - p[0], q[1] - p[1]];
                            if inside && swept_distance2(v, half, h2) < reach * reach * (1.0 - 1e-9) {
                                probes.push([q[0], q[1], 0.0]);
                            }
                        }
                    }
                }
            }
            subs.extend(probes);
            let g = GridSearch::new(&subs, cell);
            let mut got = Vec::new();
            g.pairs_swept(&slider_xy, half, reach, &mut got);
            let want = pairs_swept_box(&g, &slider_xy, half, reach);
            prop_assert_eq!(&got, &want);
            for p in &slider_xy {
                let ext = [half[0].abs() + reach, half[1].abs() + reach];
                let mut boxed = Vec::new();
                g.cells.for_in_box([p[0] - ext[0], p[1] - ext[1]], [p[0] + ext[0], p[1] + ext[1]], |k| boxed.push(k));
                let mut it = boxed.iter();
                g.cells.for_near_segment(*p, half, reach, |k| {
                    assert!(it.any(|&b| b == k), "not a subsequence of the box scan");
                });
            }
        }
    }

    /// The capsule scan skips cells for an oblique stretch whose box is wide in cells (and
    /// none for an axis-aligned one).
    #[test]
    fn capsule_scan_skips_cells_off_the_slab() {
        let a = 3e-6;
        let g = GridSearch::new(&points(true, a, 900, 0), a / 3.0);
        let count = |half: [f64; 2], box_scan: bool| {
            let (p, reach, mut n) = ([45e-6, 40e-6], 0.5 * a, 0);
            let ext = [half[0].abs() + reach, half[1].abs() + reach];
            if box_scan {
                let (lo, hi) = (
                    [p[0] - ext[0], p[1] - ext[1]],
                    [p[0] + ext[0], p[1] + ext[1]],
                );
                g.cells.for_in_box(lo, hi, |_| n += 1);
            } else {
                g.cells.for_near_segment(p, half, reach, |_| n += 1);
            }
            n
        };
        let oblique = [8e-6, -8e-6];
        assert!(count(oblique, false) * 2 < count(oblique, true));
        assert_eq!(count([4e-6, 0.0], false), count([4e-6, 0.0], true));
    }
}
