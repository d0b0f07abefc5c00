//! Candidate slider–substrate sphere pairs: pairs close enough laterally that they can touch.

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

/// Uniform bucket grid over the substrate spheres. Build O(n); query O(1) per slider sphere.
#[derive(Debug, Clone)]
pub struct GridSearch {
    spheres: Vec<[f64; 3]>,
    origin: [f64; 2],
    cell: f64,
    nx: usize,
    ny: usize,
    start: Vec<u32>,
    items: Vec<u32>,
}

impl GridSearch {
    /// Builds the grid with cell size `cell` (m) (use the contact reach, 2R).
    pub fn new(spheres: &[[f64; 3]], cell: f64) -> Self {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in spheres {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if spheres.is_empty() {
            lo = [0.0; 2];
            hi = [0.0; 2];
        }
        let nx = ((hi[0] - lo[0]) / cell).floor() as usize + 1;
        let ny = ((hi[1] - lo[1]) / cell).floor() as usize + 1;
        let mut count = vec![0u32; nx * ny + 1];
        let idx = |p: &[f64; 3]| {
            let i = (((p[0] - lo[0]) / cell).floor() as usize).min(nx - 1);
            let j = (((p[1] - lo[1]) / cell).floor() as usize).min(ny - 1);
            j * nx + i
        };
        for p in spheres {
            count[idx(p) + 1] += 1;
        }
        for k in 1..count.len() {
            count[k] += count[k - 1];
        }
        let start = count.clone();
        let mut fill = count;
        let mut items = vec![0u32; spheres.len()];
        for (n, p) in spheres.iter().enumerate() {
            let c = idx(p);
            items[fill[c] as usize] = n as u32;
            fill[c] += 1;
        }
        GridSearch {
            spheres: spheres.to_vec(),
            origin: lo,
            cell,
            nx,
            ny,
            start,
            items,
        }
    }

    /// The substrate spheres `[x, y, h]` (m) the grid was built on.
    pub fn spheres(&self) -> &[[f64; 3]] {
        &self.spheres
    }
}

impl CandidateSearch for GridSearch {
    fn pairs(&self, slider_xy: &[[f64; 2]], reach: f64, out: &mut Vec<CandidatePair>) {
        let r2max = reach * reach;
        let span = (reach / self.cell).ceil() as i64;
        let mut local: Vec<CandidatePair> = Vec::with_capacity(16);
        for (si, p) in slider_xy.iter().enumerate() {
            let ci = ((p[0] - self.origin[0]) / self.cell).floor() as i64;
            let cj = ((p[1] - self.origin[1]) / self.cell).floor() as i64;
            local.clear();
            for j in (cj - span).max(0)..=(cj + span).min(self.ny as i64 - 1) {
                for i in (ci - span).max(0)..=(ci + span).min(self.nx as i64 - 1) {
                    let c = j as usize * self.nx + i as usize;
                    for &k in &self.items[self.start[c] as usize..self.start[c + 1] as usize] {
                        let q = self.spheres[k as usize];
                        let dx = q[0] - p[0];
                        let dy = q[1] - p[1];
                        let r2 = dx * dx + dy * dy;
                        if r2 < r2max {
                            local.push(CandidatePair {
                                slider: si as u32,
                                substrate: k,
                                r2,
                                h: q[2],
                            });
                        }
                    }
                }
            }
            local.sort_by_key(|c| c.substrate);
            out.extend_from_slice(&local);
        }
    }
}
