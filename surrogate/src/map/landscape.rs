//! [`Landscape`]: the equilibrium height z of the slider translated over the substrate's
//! repeat cell, and its periodic interpolation.

use super::{check_slider_stays_on_substrate, MapParams, RepeatCell};
use crate::error::SceneError;
use crate::solver::{Model, Solver, StraightPath};
use rayon::prelude::*;

/// Equilibrium height of the slider over an N×N grid of shifts spanning one substrate repeat
/// cell (SI). Grid point `(i, j)`, `i, j ∈ 0..N`, is the shift `(i/(N−1))·a + (j/(N−1))·b` of the
/// slider centre from the scene's offset: **both cell edges are included**, so the last row and
/// column repeat the first ones and periodicity can be checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Landscape {
    /// The repeat cell mapped.
    pub cell: RepeatCell,
    /// Points per side N.
    pub n: usize,
    /// Slider rotation θ (rad).
    pub theta: f64,
    /// Normal load W (N).
    pub load: f64,
    /// Heights z (m), row-major: `z[j·N + i]`.
    pub z: Vec<f64>,
    /// Contact number at each grid point (same layout).
    pub contacts: Vec<u32>,
    /// Largest p0 (Pa) at each grid point (same layout).
    pub p_max: Vec<f64>,
}

impl Landscape {
    /// The shift (m) of grid point `(i, j)`.
    pub fn shift(&self, i: usize, j: usize) -> [f64; 2] {
        let d = (self.n - 1) as f64;
        self.cell.point(i as f64 / d, j as f64 / d)
    }
    /// Height z (m) at grid point `(i, j)`.
    pub fn z_at(&self, i: usize, j: usize) -> f64 {
        self.z[j * self.n + i]
    }
    /// min z over the grid (m).
    pub fn z_min(&self) -> f64 {
        self.z.iter().copied().fold(f64::INFINITY, f64::min)
    }
    /// Δz = z − min z (m) at grid point `(i, j)`.
    pub fn dz_at(&self, i: usize, j: usize) -> f64 {
        self.z_at(i, j) - self.z_min()
    }
    /// Peak-to-peak height over the cell, max z − min z (m).
    pub fn range(&self) -> f64 {
        let max = self.z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        max - self.z_min()
    }
    /// Largest mismatch (m) between opposite cell edges, `max |z(0, j) − z(N−1, j)|` and
    /// `max |z(i, 0) − z(i, N−1)|`: zero for an exactly periodic landscape.
    pub fn edge_mismatch(&self) -> f64 {
        let n = self.n;
        let mut m: f64 = 0.0;
        for k in 0..n {
            m = m.max((self.z_at(0, k) - self.z_at(n - 1, k)).abs());
            m = m.max((self.z_at(k, 0) - self.z_at(k, n - 1)).abs());
        }
        m
    }

    /// Height z (m) at an arbitrary shift `p` (m), by periodic bicubic (Catmull–Rom)
    /// interpolation of the N−1 distinct samples per side in cell coordinates. Exact at grid
    /// points; the error elsewhere is O(h⁴·z'''') for grid spacing h (measured against direct
    /// solves in the corrugation tests and docs/validation/maps.md). Cost O(16).
    pub fn interpolate(&self, p: [f64; 2]) -> f64 {
        let m = (self.n - 1) as i64;
        let [u, v] = self.cell.coords(p);
        let tu = u.rem_euclid(1.0) * m as f64;
        let tv = v.rem_euclid(1.0) * m as f64;
        let (iu, fu) = (tu.floor() as i64, tu - tu.floor());
        let (iv, fv) = (tv.floor() as i64, tv - tv.floor());
        let at = |i: i64, j: i64| {
            self.z[(j.rem_euclid(m)) as usize * self.n + (i.rem_euclid(m)) as usize]
        };
        let wu = catmull_rom_weights(fu);
        let wv = catmull_rom_weights(fv);
        let mut s = 0.0;
        for (b, wb) in wv.iter().enumerate() {
            let mut row = 0.0;
            for (a, wa) in wu.iter().enumerate() {
                row += wa * at(iu + a as i64 - 1, iv + b as i64 - 1);
            }
            s += wb * row;
        }
        s
    }
}

/// (z, contact number, P_max) of one grid point.
type GridPoint = (f64, u32, f64);

fn catmull_rom_weights(t: f64) -> [f64; 4] {
    let t2 = t * t;
    let t3 = t2 * t;
    [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ]
}

/// Computes the [`Landscape`] of `solver`'s scene at rotation `theta` (rad) and load `load` (N)
/// on a `params.grid`² grid over the substrate's [`RepeatCell`] (rectangular cell, or the
/// primitive parallelogram for oblique substrates). Solves with [`Model::Auto`].
///
/// Parallel over grid rows and segments of them (rayon; each row is a straight path along the
/// edge a, [`Solver::solve_along`], one candidate search per `params.segment`); the result does
/// not depend on the number of threads. `progress` is called once per finished grid point.
/// Cost: N² solves.
///
/// Errors: `grid` < 2 (field `grid`), the slider leaving the substrate somewhere over the cell
/// (field `offset_um`), or a failed solve.
pub fn compute_landscape(
    solver: &Solver,
    theta: f64,
    load: f64,
    params: &MapParams,
    progress: &(dyn Fn() + Sync),
) -> Result<Landscape, SceneError> {
    let n = params.grid;
    if n < 2 {
        return Err(SceneError::invalid(
            "grid",
            n,
            "needs at least 2 points per side (both cell edges are included)",
        ));
    }
    if !theta.is_finite() {
        return Err(SceneError::invalid(
            "theta_deg",
            theta.to_degrees(),
            "must be finite",
        ));
    }
    let scene = solver.scene();
    let cell = RepeatCell::for_lattice(&scene.substrate.lattice, params.max_cell_mult);
    check_slider_stays_on_substrate(scene, cell.bounding_box(), "offset_um")?;
    let mut out = Landscape {
        cell,
        n,
        theta,
        load,
        z: Vec::new(),
        contacts: Vec::new(),
        p_max: Vec::new(),
    };
    // Each grid row (fixed j) is the straight path origin + s·â along the cell edge a, solved
    // with one candidate search per `params.segment` of it (Solver::solve_along).
    let alen = cell.a[0].hypot(cell.a[1]);
    let e = [cell.a[0] / alen, cell.a[1] / alen];
    let s: Vec<f64> = (0..n).map(|i| alen * i as f64 / (n - 1) as f64).collect();
    let res: Result<Vec<Vec<GridPoint>>, SceneError> = (0..n)
        .into_par_iter()
        .map(|j| {
            let path = StraightPath {
                theta,
                origin: out.shift(0, j),
                e,
                s: &s,
                segment: params.segment,
            };
            solver.solve_along(path, load, Model::Auto, |_, eq| {
                progress();
                (eq.z, eq.contact_count() as u32, eq.p_max)
            })
        })
        .collect();
    for (z, c, p) in res?.into_iter().flatten() {
        out.z.push(z);
        out.contacts.push(c);
        out.p_max.push(p);
    }
    Ok(out)
}
