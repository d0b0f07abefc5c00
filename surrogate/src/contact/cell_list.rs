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
        if let Some(cells) = self.box_cells(lo, hi) {
            self.for_rows(cells, &mut f);
        }
    }

    /// Calls `f(index)` for the points of the cells `[i0, i1, j0, j1]` (inclusive), row by row.
    #[inline(always)]
    fn for_rows(&self, [i0, i1, j0, j1]: [usize; 4], f: &mut impl FnMut(u32)) {
        for j in j0..=j1 {
            self.for_row(j, i0, i1, f);
        }
    }

    /// The cells `[i0, i1, j0, j1]` (inclusive, clamped to the grid) that meet the box
    /// `[lo, hi]` (m); `None` when the box lies below or left of the grid or is not finite. O(1).
    fn box_cells(&self, lo: [f64; 2], hi: [f64; 2]) -> Option<[usize; 4]> {
        // cell coordinates clamped to the grid (truncation is the floor once clamped at 0)
        let cell = |v: f64, o: f64, n: usize| -> Option<usize> {
            let x = (v - o) / self.cell;
            if !x.is_finite() {
                return None;
            }
            Some(if x <= 0.0 { 0 } else { (x as usize).min(n - 1) })
        };
        if hi[0] < self.origin[0] || hi[1] < self.origin[1] {
            return None;
        }
        Some([
            cell(lo[0], self.origin[0], self.nx)?,
            cell(hi[0], self.origin[0], self.nx)?,
            cell(lo[1], self.origin[1], self.ny)?,
            cell(hi[1], self.origin[1], self.ny)?,
        ])
    }

    /// Calls `f(index)` for the points of cells `i0..=i1` of row `j`, in binning order.
    #[inline(always)]
    fn for_row(&self, j: usize, i0: usize, i1: usize, f: &mut impl FnMut(u32)) {
        let c = j * self.nx;
        let items = &self.items[self.start[c + i0] as usize..self.start[c + i1 + 1] as usize];
        for &n in items {
            f(n);
        }
    }

    /// Calls `f(index)` for every binned point in the cells of the box around the capsule
    /// `{p + t·half : t ∈ [−1, 1]} ⊕ disc(reach)` (`p`, `half`, `reach` in m) — the cells
    /// [`CellList::for_in_box`] visits for `[p − |half| − reach, p + |half| + reach]` — that
    /// can hold a point within `reach` of the segment, in the same order (row by row, binning
    /// order within a cell): every point of those box cells within `reach` of the segment is
    /// visited; for an oblique `half` whose box is wide in cells, fewer of the others.
    ///
    /// A point within `reach` of the segment lies in the slab `|n·(q − p)| ≤ reach` (`n` the
    /// segment's unit normal, `n_x > 0`), so a row may visit only the columns where the slab
    /// crosses its y band (clamped to the box): `x − p_x ∈ [(−ρ − max n_y·w) / n_x,
    /// (ρ − min n_y·w) / n_x]` over the band's `w = y − p_y`, `ρ` = `reach`, every bound widened
    /// by 1e-7 of the box size plus cell (far above the round-off of positions and binning). That
    /// costs a few flops per row, so it is used only where it skips two or more columns per row
    /// (cells small against the capsule, a long oblique stretch); otherwise, and for a segment
    /// within 0.6° of the x axis or of length ≲ 1e-154 m, each row of the box is scanned whole.
    /// O(rows + points visited); one contiguous run of points per row.
    pub fn for_near_segment(
        &self,
        p: [f64; 2],
        half: [f64; 2],
        reach: f64,
        mut f: impl FnMut(u32),
    ) {
        let ext = [half[0].abs() + reach, half[1].abs() + reach];
        let lo = [p[0] - ext[0], p[1] - ext[1]];
        let hi = [p[0] + ext[0], p[1] + ext[1]];
        let Some(cells) = self.box_cells(lo, hi) else {
            return;
        };
        let [i0, i1, j0, j1] = cells;
        // the slab skips two columns per row only in a box four or more columns wide
        if i1 - i0 < 3 {
            return self.for_rows(cells, &mut f);
        }
        let h2 = half[0] * half[0] + half[1] * half[1];
        // the unit normal, oriented to n_x ≥ 0
        let len = h2.sqrt();
        let sign = if half[1] > 0.0 { 1.0 } else { -1.0 };
        let n = [sign * half[1] / len, -sign * half[0] / len];
        let pad = 1e-7 * (ext[0] + ext[1] + self.cell);
        let inv_cell = 1.0 / self.cell;
        // half the slab's width along x (m, widened), and the shift of its edges along x per
        // row (cells)
        let w = (reach + pad) / n[0] + pad;
        let slope = -n[1] / n[0] * inv_cell;
        let row_cols = 2.0 * w * inv_cell + slope.abs() * self.cell + 2.0;
        if !(h2 >= f64::MIN_POSITIVE && n[0] > 0.01 && row_cols + 2.0 <= (i1 - i0 + 1) as f64) {
            return self.for_rows(cells, &mut f);
        }
        // the slab's edges on the line y = p_y, in cells from the grid's origin
        let e_lo = (p[0] - self.origin[0] - w) * inv_cell;
        let e_hi = (p[0] - self.origin[0] + w) * inv_cell;
        let (oy, last) = (self.origin[1], (self.nx - 1) as f64);
        let (b_lo, b_hi) = (lo[1] - p[1] - pad, hi[1] - p[1] + pad);
        for j in j0..=j1 {
            // the row's y band less p_y, in the box (the last row also holds the points above
            // the grid)
            let y0 = oy + j as f64 * self.cell - p[1];
            let w_lo = (y0 - pad).max(b_lo);
            let w_hi = if j + 1 == self.ny {
                b_hi
            } else {
                (y0 + self.cell + pad).min(b_hi)
            };
            let (u, v) = (slope * w_lo, slope * w_hi);
            // columns (points left and right of the grid are binned at its edges); truncation is
            // the floor once clamped at i0 ≥ 0
            let c_lo = (e_lo + u.min(v)).max(i0 as f64).min(last) as usize;
            let c_hi = (e_hi + u.max(v)).max(0.0).min(i1 as f64) as usize;
            if c_lo <= c_hi {
                self.for_row(j, c_lo, c_hi, &mut f);
            }
        }
    }

    /// Cell size (m).
    pub fn cell(&self) -> f64 {
        self.cell
    }
}
