//! [`CellList`]: uniform 2-D bucket grid over the substrate spheres' (x, y), shared by the
//! quasi-static pair search ([`super::GridSearch`]) and the DEM neighbour list.

/// Uniform grid with cell size ≥ the list cutoff; CSR storage (`start`, `items`). Build O(n),
/// query O(1) per point (3×3 cells).
#[derive(Debug, Clone, Default)]
pub struct CellList {
    origin: [f64; 2],
    cell: f64,
    nx: usize,
    ny: usize,
    start: Vec<u32>,
    items: Vec<u32>,
}

impl CellList {
    /// Bins `points` (m) into cells of size `cell` (m).
    pub fn new(points: &[[f64; 2]], cell: f64) -> Self {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if points.is_empty() || !lo[0].is_finite() || !hi[0].is_finite() {
            lo = [0.0; 2];
            hi = [0.0; 2];
        }
        let nx = (((hi[0] - lo[0]) / cell).floor() as usize + 1).min(1 << 20);
        let ny = (((hi[1] - lo[1]) / cell).floor() as usize + 1).min(1 << 20);
        let mut s = CellList {
            origin: lo,
            cell,
            nx,
            ny,
            start: vec![0; nx * ny + 1],
            items: vec![0; points.len()],
        };
        let cells: Vec<usize> = points.iter().map(|p| s.cell_of(*p)).collect();
        for &c in &cells {
            s.start[c + 1] += 1;
        }
        for c in 0..nx * ny {
            s.start[c + 1] += s.start[c];
        }
        let mut fill = s.start.clone();
        for (n, &c) in cells.iter().enumerate() {
            s.items[fill[c] as usize] = n as u32;
            fill[c] += 1;
        }
        s
    }

    fn cell_of(&self, p: [f64; 2]) -> usize {
        let i = ((p[0] - self.origin[0]) / self.cell).floor().max(0.0) as usize;
        let j = ((p[1] - self.origin[1]) / self.cell).floor().max(0.0) as usize;
        j.min(self.ny - 1) * self.nx + i.min(self.nx - 1)
    }

    /// Calls `f(index)` for every binned point in the 3×3 cells around `p` (superset of the
    /// points within one cell size of `p`).
    pub fn for_near(&self, p: [f64; 2], f: impl FnMut(u32)) {
        self.for_within_cells(p, 1, f);
    }

    /// Calls `f(index)` for every binned point in the (2·span + 1)² cells around `p` (superset of
    /// the points within `span` cell sizes of `p`), row by row, in binning order within a cell.
    pub fn for_within_cells(&self, p: [f64; 2], span: i64, mut f: impl FnMut(u32)) {
        let fi = ((p[0] - self.origin[0]) / self.cell).floor();
        let fj = ((p[1] - self.origin[1]) / self.cell).floor();
        if !(fi.is_finite() && fj.is_finite()) {
            return;
        }
        let (ci, cj) = (fi as i64, fj as i64);
        for j in (cj - span).max(0)..=(cj + span).min(self.ny as i64 - 1) {
            for i in (ci - span).max(0)..=(ci + span).min(self.nx as i64 - 1) {
                let c = j as usize * self.nx + i as usize;
                for &n in &self.items[self.start[c] as usize..self.start[c + 1] as usize] {
                    f(n);
                }
            }
        }
    }

    /// Calls `f(index)` for every binned point in the cells that meet the box `[lo, hi]` (m),
    /// row by row, in binning order within a cell (a superset of the points inside the box).
    pub fn for_in_box(&self, lo: [f64; 2], hi: [f64; 2], mut f: impl FnMut(u32)) {
        // cell coordinates clamped to the grid (truncation is the floor once clamped at 0)
        let cell = |v: f64, o: f64, n: usize| -> Option<usize> {
            let x = (v - o) / self.cell;
            if !x.is_finite() {
                return None;
            }
            Some(if x <= 0.0 { 0 } else { (x as usize).min(n - 1) })
        };
        if hi[0] < self.origin[0] || hi[1] < self.origin[1] {
            return;
        }
        let (Some(i0), Some(i1), Some(j0), Some(j1)) = (
            cell(lo[0], self.origin[0], self.nx),
            cell(hi[0], self.origin[0], self.nx),
            cell(lo[1], self.origin[1], self.ny),
            cell(hi[1], self.origin[1], self.ny),
        ) else {
            return;
        };
        for j in j0..=j1 {
            for i in i0..=i1 {
                let c = j * self.nx + i;
                for &n in &self.items[self.start[c] as usize..self.start[c + 1] as usize] {
                    f(n);
                }
            }
        }
    }

    /// Cell size (m).
    pub fn cell(&self) -> f64 {
        self.cell
    }
}
