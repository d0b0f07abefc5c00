//! [`RepeatCell`]: the substrate's repeat cell over which a landscape is mapped.

use crate::scene::Lattice;

/// A repeat cell of the substrate lattice spanned by `a` and `b` (m): points `u·a + v·b` with
/// `u, v ∈ [0, 1]`. Translating the slider by `a` or `b` maps the substrate onto itself, so the
/// equilibrium height is periodic over the cell (exactly, for a flat substrate far larger than
/// the slider).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RepeatCell {
    /// First edge (m). Along +x for a rectangular cell.
    pub a: [f64; 2],
    /// Second edge (m). Along +y for a rectangular cell.
    pub b: [f64; 2],
    /// Whether the cell is the axis-aligned rectangle `[0, Lx] × [0, Ly]`.
    pub rectangular: bool,
}

impl RepeatCell {
    /// The smallest axis-aligned rectangular repeat cell of `lattice`
    /// ([`Lattice::rectangular_cell`] with `max_mult`; triangular spacing s: s × s√3), or, for
    /// oblique lattices without one, the primitive parallelogram `a1, a2`.
    pub fn for_lattice(lattice: &Lattice, max_mult: i32) -> RepeatCell {
        match lattice.rectangular_cell(max_mult) {
            Some((lx, ly)) => RepeatCell {
                a: [lx, 0.0],
                b: [0.0, ly],
                rectangular: true,
            },
            None => RepeatCell {
                a: lattice.a1,
                b: lattice.a2,
                rectangular: false,
            },
        }
    }

    /// The point `u·a + v·b` (m).
    pub fn point(&self, u: f64, v: f64) -> [f64; 2] {
        [u * self.a[0] + v * self.b[0], u * self.a[1] + v * self.b[1]]
    }

    /// Cell coordinates `(u, v)` of the point `p` (m), not wrapped.
    pub fn coords(&self, p: [f64; 2]) -> [f64; 2] {
        let det = self.a[0] * self.b[1] - self.a[1] * self.b[0];
        [
            (p[0] * self.b[1] - p[1] * self.b[0]) / det,
            (self.a[0] * p[1] - self.a[1] * p[0]) / det,
        ]
    }

    /// Bounding box `[[x_lo, y_lo], [x_hi, y_hi]]` (m) of the cell.
    pub fn bounding_box(&self) -> [[f64; 2]; 2] {
        let c = [
            [0.0, 0.0],
            self.a,
            self.b,
            [self.a[0] + self.b[0], self.a[1] + self.b[1]],
        ];
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in c {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        [lo, hi]
    }
}
