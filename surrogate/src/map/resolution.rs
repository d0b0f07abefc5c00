//! The grid a landscape needs: from the finest feature of Δz over the repeat cell.
//!
//! Shifting the slider by `t` moves every slider site `r_j` over a substrate whose height
//! response is periodic in the substrate lattice, so `Δz(t) = Σ_G f_G S(G) e^{iG·t}` over the
//! substrate's reciprocal vectors G, with `S(G) = Σ_j e^{iG·r_j}` the slider's structure factor
//! (its sites at the scene's θ). `|S(G)|/N` is near 1 only where G coincides with a reciprocal
//! vector of the rotated slider lattice to within about 2π over the slider's diameter: the
//! moiré of the two lattices. The landscape's **fundamental** is the shortest such G
//! (`|S(G)|/N ≥` [`COINCIDENCE`]); along the cell's edges `a`, `b` it makes `p_a = |G·a|/2π`
//! and `p_b = |G·b|/2π` whole periods. Its shape is not a sine (a sphere changes the substrate
//! spheres it rests on: cusps), so its second harmonic, `2 max(p_a, p_b)` periods per edge,
//! is the finest feature drawn, and a grid resolves it with [`POINTS_PER_PERIOD`] points per
//! period: `N = 2 · POINTS_PER_PERIOD · max(p_a, p_b) + 1`.
//!
//! square-tri, θ = 0: G = (2, 0) periods per edge (the square rows at 3 µm over the triangular
//! rows), N = 17, the study's 51 suffices; θ = 10.2°: G = (5, 9), N = 73. docs/validation/maps.md.

use super::{MapParams, RepeatCell};
use crate::scene::Scene;
use std::f64::consts::PI;

/// `|S(G)|/N` at or above which G is a coincidence of the two lattices (the fundamental's is
/// 0.99 or more on the study's sliders; the next strongest reflection a third of that).
pub const COINCIDENCE: f64 = 0.5;

/// Grid points per period of the finest feature (the fundamental's second harmonic): twice
/// Nyquist, so the drawn map shows stripes as stripes, not a checkerboard.
pub const POINTS_PER_PERIOD: usize = 4;

/// Largest number of fundamental periods per cell edge searched (a coincidence finer than that
/// is not looked for: its grid would exceed 2·4·30 + 1 = 241 points per side).
pub const MAX_PERIODS: i64 = 30;

/// What the grid must resolve in the landscape of one scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridNeed {
    /// The fundamental's whole periods along the cell's edges a and b (`None`: no coincidence
    /// of the two lattices within [`MAX_PERIODS`], an incommensurate pair with no moiré to draw).
    pub periods: Option<[i64; 2]>,
    /// The fundamental's wavelength (m), `2π/|G|`.
    pub wavelength: f64,
    /// `|S(G)|/N` of the fundamental.
    pub coincidence: f64,
    /// Grid points per side that resolve it (2 when there is none).
    pub grid: usize,
}

/// The grid the landscape of `scene` (at its own θ) needs ([`GridNeed`], module docs). Cost:
/// O(N_slider · MAX_PERIODS²) phase sums, about 5 ms for the study's 3505-sphere slider.
pub fn grid_need(scene: &Scene) -> GridNeed {
    let cell =
        RepeatCell::for_lattice(&scene.substrate.lattice, MapParams::default().max_cell_mult);
    let l = &scene.substrate.lattice;
    // the substrate's reciprocal vectors b1, b2 (b_i · a_j = 2π δ_ij)
    let det = l.a1[0] * l.a2[1] - l.a1[1] * l.a2[0];
    let b1 = [2.0 * PI * l.a2[1] / det, -2.0 * PI * l.a2[0] / det];
    let b2 = [-2.0 * PI * l.a1[1] / det, 2.0 * PI * l.a1[0] / det];
    let sites = scene.slider_sites();
    let n = sites.len().max(1) as f64;
    let periods = |g: [f64; 2], e: [f64; 2]| ((g[0] * e[0] + g[1] * e[1]) / (2.0 * PI)).round();
    // every G with at most MAX_PERIODS periods along each cell edge, one of each ±G pair
    let mut gs: Vec<([f64; 2], [i64; 2])> = Vec::new();
    let k_max = 4 * MAX_PERIODS;
    for h in -k_max..=k_max {
        for k in -k_max..=k_max {
            if h < 0 || (h == 0 && k <= 0) {
                continue;
            }
            let g = [
                h as f64 * b1[0] + k as f64 * b2[0],
                h as f64 * b1[1] + k as f64 * b2[1],
            ];
            let p = [periods(g, cell.a) as i64, periods(g, cell.b) as i64];
            if p[0].abs() <= MAX_PERIODS && p[1].abs() <= MAX_PERIODS {
                gs.push((g, [p[0].abs(), p[1].abs()]));
            }
        }
    }
    gs.sort_by(|x, y| x.0[0].hypot(x.0[1]).total_cmp(&y.0[0].hypot(y.0[1])));
    for (g, p) in gs {
        let (mut re, mut im) = (0.0, 0.0);
        for s in &sites {
            let (sn, cs) = (g[0] * s[0] + g[1] * s[1]).sin_cos();
            re += cs;
            im += sn;
        }
        let c = re.hypot(im) / n;
        if c >= COINCIDENCE {
            let finest = 2 * p[0].max(p[1]) as usize;
            return GridNeed {
                periods: Some(p),
                wavelength: 2.0 * PI / g[0].hypot(g[1]),
                coincidence: c,
                grid: POINTS_PER_PERIOD * finest + 1,
            };
        }
    }
    GridNeed {
        periods: None,
        wavelength: f64::NAN,
        coincidence: 0.0,
        grid: 2,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The study's default: square-tri at θ = 0 needs fewer than 51 points; at θ = 10.2° the
    /// moiré's (5, 9) periods need more (the map drawn at 51 aliases into a checkerboard).
    #[test]
    fn fifty_one_suffices_at_zero_and_not_at_ten_point_two() {
        let s = Scene::preset("square-tri").unwrap();
        let at0 = grid_need(&s.with_theta(0.0));
        assert_eq!(at0.periods, Some([2, 0]));
        assert!(at0.grid <= 51, "{at0:?}");
        let at10 = grid_need(&s.with_theta(10.2f64.to_radians()));
        assert_eq!(at10.periods, Some([5, 9]), "{at10:?}");
        assert!(at10.grid > 51 && at10.grid <= 121, "{at10:?}");
        assert!(at10.coincidence > 0.9, "{at10:?}");
    }

    /// Commensurate tri-tri at 0° has its fundamental at the substrate's own first reflection;
    /// at 30° (incommensurate) there is none to draw.
    #[test]
    fn commensurate_and_incommensurate_tri_tri() {
        let s = Scene::preset("tri-tri").unwrap();
        let at0 = grid_need(&s.with_theta(0.0));
        assert!(at0.periods.is_some() && at0.grid <= 51, "{at0:?}");
        let at30 = grid_need(&s.with_theta(30f64.to_radians()));
        assert_eq!(at30.periods, None, "{at30:?}");
    }
}
