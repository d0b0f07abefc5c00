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
    /// around each sphere's swept capsule (a third of the disc search's cells for a 3 µm
    /// stretch). `r2` is the lateral distance² at `p`. Slider order, then substrate index order.
    pub fn pairs_swept(
        &self,
        slider_xy: &[[f64; 2]],
        half: [f64; 2],
        reach: f64,
        out: &mut Vec<CandidatePair>,
    ) {
        let h2 = half[0] * half[0] + half[1] * half[1];
        let r2max = reach * reach * (1.0 + 1e-9);
        let ext = [half[0].abs() + reach, half[1].abs() + reach];
        let mut local: Vec<CandidatePair> = Vec::with_capacity(32);
        for (si, p) in slider_xy.iter().enumerate() {
            local.clear();
            let lo = [p[0] - ext[0], p[1] - ext[1]];
            let hi = [p[0] + ext[0], p[1] + ext[1]];
            self.cells.for_in_box(lo, hi, |k| {
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
