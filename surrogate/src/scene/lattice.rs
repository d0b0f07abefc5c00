//! A 2-D Bravais lattice in the horizontal plane.

use crate::error::SceneError;
use crate::units::um_pair_text;
use serde::{Deserialize, Serialize};

/// A 2-D Bravais lattice given by two primitive vectors `a1`, `a2` (m). Sites are
/// `i·a1 + j·a2` for integers `i, j`.
///
/// The named constructors put `a1` along +x, so "one lattice row along x".
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Lattice {
    /// First primitive vector (m).
    pub a1: [f64; 2],
    /// Second primitive vector (m).
    pub a2: [f64; 2],
}

impl Lattice {
    /// Triangular (hexagonal close-packed in-plane) lattice with nearest-neighbour spacing `s` (m):
    /// `a1 = (s, 0)`, `a2 = (s/2, s·√3/2)`.
    pub fn triangular(s: f64) -> Self {
        Lattice {
            a1: [s, 0.0],
            a2: [0.5 * s, 0.5 * 3f64.sqrt() * s],
        }
    }
    /// Square lattice with spacing `s` (m).
    pub fn square(s: f64) -> Self {
        Lattice {
            a1: [s, 0.0],
            a2: [0.0, s],
        }
    }
    /// Rectangular lattice with spacings `sx`, `sy` (m).
    pub fn rectangular(sx: f64, sy: f64) -> Self {
        Lattice {
            a1: [sx, 0.0],
            a2: [0.0, sy],
        }
    }
    /// General (oblique) lattice from two vectors (m).
    pub fn oblique(a1: [f64; 2], a2: [f64; 2]) -> Self {
        Lattice { a1, a2 }
    }

    /// Signed area of the primitive cell `a1 × a2` (m²).
    pub fn cell_area(&self) -> f64 {
        self.a1[0] * self.a2[1] - self.a1[1] * self.a2[0]
    }

    /// Shortest non-zero lattice vector length (m): the nearest-neighbour spacing.
    pub fn min_spacing(&self) -> f64 {
        let mut best = f64::INFINITY;
        for i in -3i32..=3 {
            for j in -3i32..=3 {
                if i == 0 && j == 0 {
                    continue;
                }
                let x = i as f64 * self.a1[0] + j as f64 * self.a2[0];
                let y = i as f64 * self.a1[1] + j as f64 * self.a2[1];
                best = best.min((x * x + y * y).sqrt());
            }
        }
        best
    }

    /// The smallest axis-aligned rectangular repeat cell `(Lx, Ly)` (m) of the lattice, if one
    /// exists with `Lx, Ly` at most `max_mult` primitive-vector lengths (triangular: `(s, s√3)`,
    /// square: `(s, s)`). `None` for oblique lattices with no rectangular supercell.
    pub fn rectangular_cell(&self, max_mult: i32) -> Option<(f64, f64)> {
        let tol = 1e-9 * self.a1[0].hypot(self.a1[1]);
        let mut lx = f64::INFINITY;
        let mut ly = f64::INFINITY;
        for i in -max_mult..=max_mult {
            for j in -max_mult..=max_mult {
                if i == 0 && j == 0 {
                    continue;
                }
                let x = i as f64 * self.a1[0] + j as f64 * self.a2[0];
                let y = i as f64 * self.a1[1] + j as f64 * self.a2[1];
                if y.abs() < tol && x > tol {
                    lx = lx.min(x);
                }
                if x.abs() < tol && y > tol {
                    ly = ly.min(y);
                }
            }
        }
        (lx.is_finite() && ly.is_finite()).then_some((lx, ly))
    }

    /// Lattice coordinates `(u, v)` of a point `p` so that `p = u·a1 + v·a2`.
    pub fn to_lattice_coords(&self, p: [f64; 2]) -> [f64; 2] {
        let det = self.cell_area();
        [
            (p[0] * self.a2[1] - p[1] * self.a2[0]) / det,
            (self.a1[0] * p[1] - self.a1[1] * p[0]) / det,
        ]
    }

    /// Cartesian point (m) of lattice coordinates `(u, v)`.
    pub fn point(&self, u: f64, v: f64) -> [f64; 2] {
        [
            u * self.a1[0] + v * self.a2[0],
            u * self.a1[1] + v * self.a2[1],
        ]
    }

    /// All lattice sites inside the disc of radius `r` (m) centred on the site at the origin, in
    /// a deterministic order (row-major in lattice coordinates). Points on the rim (within 1e-9
    /// relative) are included.
    pub fn sites_in_disc(&self, r: f64) -> Vec<[f64; 2]> {
        let (imax, jmax) = self.index_bounds(r, r);
        let r2 = r * r * (1.0 + 1e-9);
        let mut out = Vec::new();
        for j in -jmax..=jmax {
            for i in -imax..=imax {
                let p = self.point(i as f64, j as f64);
                if p[0] * p[0] + p[1] * p[1] <= r2 {
                    out.push(p);
                }
            }
        }
        out
    }

    /// All lattice sites inside the axis-aligned rectangle `|x| ≤ lx/2, |y| ≤ ly/2` (m), in a
    /// deterministic order (row-major in lattice coordinates).
    pub fn sites_in_rect(&self, lx: f64, ly: f64) -> Vec<[f64; 2]> {
        let hx = 0.5 * lx * (1.0 + 1e-12);
        let hy = 0.5 * ly * (1.0 + 1e-12);
        let (imax, jmax) = self.index_bounds(hx.hypot(hy), hx.hypot(hy));
        let mut out = Vec::new();
        for j in -jmax..=jmax {
            for i in -imax..=imax {
                let p = self.point(i as f64, j as f64);
                if p[0].abs() <= hx && p[1].abs() <= hy {
                    out.push(p);
                }
            }
        }
        out
    }

    pub(crate) fn index_bounds(&self, rx: f64, ry: f64) -> (i64, i64) {
        // |u| ≤ r·|a2|/|det| and |v| ≤ r·|a1|/|det| bound the lattice indices of a disc of radius r.
        let det = self.cell_area().abs();
        let r = rx.max(ry);
        let l1 = self.a1[0].hypot(self.a1[1]);
        let l2 = self.a2[0].hypot(self.a2[1]);
        (
            (r * l2 / det).ceil() as i64 + 1,
            (r * l1 / det).ceil() as i64 + 1,
        )
    }

    /// Checks the lattice is non-degenerate and finite. `field` names it in errors.
    pub fn validate(&self, field: &str) -> Result<(), SceneError> {
        let all = [self.a1[0], self.a1[1], self.a2[0], self.a2[1]];
        if all.iter().any(|v| !v.is_finite()) {
            return Err(SceneError::invalid(
                field,
                format!(
                    "a1_um = {}, a2_um = {}",
                    um_pair_text(self.a1),
                    um_pair_text(self.a2)
                ),
                "lattice vectors must be finite",
            ));
        }
        let l1 = self.a1[0].hypot(self.a1[1]);
        let l2 = self.a2[0].hypot(self.a2[1]);
        if l1 <= 0.0 || l2 <= 0.0 || self.cell_area().abs() < 1e-6 * l1 * l2 {
            return Err(SceneError::invalid(
                field,
                format!(
                    "a1_um = {}, a2_um = {}",
                    um_pair_text(self.a1),
                    um_pair_text(self.a2)
                ),
                "lattice vectors must be non-zero and not parallel",
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn study_sliders_hold_3505_spheres() {
        let s = 3e-6;
        assert_eq!(Lattice::triangular(s).sites_in_disc(93.5e-6).len(), 3505);
        assert_eq!(Lattice::square(s).sites_in_disc(100e-6).len(), 3505);
    }

    #[test]
    fn rectangular_cells() {
        let s = 3e-6;
        let (lx, ly) = Lattice::triangular(s).rectangular_cell(4).unwrap();
        assert!((lx - s).abs() < 1e-15 && (ly - s * 3f64.sqrt()).abs() < 1e-15);
        let (lx, ly) = Lattice::square(s).rectangular_cell(4).unwrap();
        assert!((lx - s).abs() < 1e-15 && (ly - s).abs() < 1e-15);
        assert!((Lattice::triangular(s).min_spacing() - s).abs() < 1e-15);
    }

    #[test]
    fn degenerate_lattice_is_rejected() {
        let l = Lattice::oblique([3e-6, 0.0], [6e-6, 0.0]);
        let e = l.validate("substrate.lattice").unwrap_err();
        assert!(e.to_string().contains("substrate.lattice"));
    }
}
