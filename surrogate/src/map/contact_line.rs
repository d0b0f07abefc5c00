//! The contact-line direction of a pattern pair, from the moiré of the two lattices.

use super::MapParams;
use crate::scene::{Lattice, Scene};
use std::f64::consts::PI;

/// Direction of the contact lines of a scene at a slider rotation θ (substrate frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLine {
    /// Angle of the contact lines from the substrate x axis (rad), in (−π/2, π/2].
    pub angle: f64,
    /// The moiré wave vector q = G_slider(θ) − G_substrate (1/m); zero when degenerate.
    pub q: [f64; 2],
    /// Spacing 2π/|q| (m) between neighbouring contact lines; infinite when degenerate.
    pub spacing: f64,
    /// True when the first reciprocal shells coincide (commensurate, e.g. tri-tri at θ = 0):
    /// there are no contact lines and `angle` falls back to the substrate row direction `a1`.
    pub degenerate: bool,
}

/// First reciprocal shell of `lattice`: the shortest non-zero G = m·b1 + n·b2 (1/m), with
/// `a_i·b_j = 2π δ_ij`, within a relative tolerance `rtol` of the shortest length.
fn first_shell(lattice: &Lattice, rtol: f64) -> Vec<[f64; 2]> {
    let [a1, a2] = [lattice.a1, lattice.a2];
    let det = lattice.cell_area();
    let b1 = [2.0 * PI * a2[1] / det, -2.0 * PI * a2[0] / det];
    let b2 = [-2.0 * PI * a1[1] / det, 2.0 * PI * a1[0] / det];
    let mut all = Vec::new();
    for m in -3i32..=3 {
        for n in -3i32..=3 {
            if m == 0 && n == 0 {
                continue;
            }
            let g = [
                m as f64 * b1[0] + n as f64 * b2[0],
                m as f64 * b1[1] + n as f64 * b2[1],
            ];
            all.push(g);
        }
    }
    let gmin = all
        .iter()
        .map(|g| g[0].hypot(g[1]))
        .fold(f64::INFINITY, f64::min);
    all.retain(|g| g[0].hypot(g[1]) <= gmin * (1.0 + rtol));
    all
}

fn wrap_half_turn(a: f64) -> f64 {
    // into (−π/2, π/2]
    let mut x = a.rem_euclid(PI);
    if x > 0.5 * PI + 1e-12 {
        x -= PI;
    }
    x
}

/// The contact-line direction of `scene` with the slider rotated by `theta` (rad).
///
/// Method (moiré of the first reciprocal shells): for every pair of first-shell reciprocal
/// vectors, G_s of the slider lattice rotated by θ and G_b of the substrate lattice, form the
/// beat vector q = G_s − G_b. The smallest non-zero |q| is the dominant long-wavelength
/// modulation of the sphere overlap; the places where slider and substrate spheres are in
/// register (the contact lines) are its wave fronts, which run **perpendicular to q**, spaced
/// 2π/|q| apart. Ties (e.g. the three equivalent directions of a triangular moiré) are broken
/// by the line closest to the substrate x axis, then the smallest positive angle. If the
/// smallest |q| vanishes (below `params.q_zero_rtol` of the shortest G: commensurate shells) the
/// result is flagged `degenerate` and the substrate row direction `a1` is returned.
///
/// Example: square slider (spacing s) on triangular substrate (spacing s) at θ = 0: G_s = 2π/s·(0, 1)
/// and G_b = 4π/(√3 s)·(0, 1) give q ∥ y with |q| = 0.155·2π/s (a line spacing of 19.4 µm for
/// s = 3 µm), so the contact lines run along x, the substrate rows. Cost: O(36) vector ops.
pub fn contact_line_direction(scene: &Scene, theta: f64, params: &MapParams) -> ContactLine {
    let gs = first_shell(&scene.slider.lattice, params.shell_rtol);
    let gb = first_shell(&scene.substrate.lattice, params.shell_rtol);
    let (s, c) = theta.sin_cos();
    let gmin = gs
        .iter()
        .chain(gb.iter())
        .map(|g| g[0].hypot(g[1]))
        .fold(f64::INFINITY, f64::min);
    let zero = params.q_zero_rtol * gmin;
    let mut best: Option<(f64, f64, [f64; 2])> = None; // (|q|, |angle|, q)
    let mut degenerate = false;
    for g in &gs {
        let gr = [c * g[0] - s * g[1], s * g[0] + c * g[1]];
        for h in &gb {
            let q = [gr[0] - h[0], gr[1] - h[1]];
            let ql = q[0].hypot(q[1]);
            if ql <= zero {
                degenerate = true;
                continue;
            }
            let ang = wrap_half_turn(q[1].atan2(q[0]) + 0.5 * PI);
            let key = (ql, ang.abs());
            let better = match best {
                None => true,
                Some((bl, ba, bq)) => {
                    if ql < bl * (1.0 - 1e-9) {
                        true
                    } else if ql <= bl * (1.0 + 1e-9) {
                        let bang = wrap_half_turn(bq[1].atan2(bq[0]) + 0.5 * PI);
                        key.1 < ba - 1e-9 || ((key.1 - ba).abs() <= 1e-9 && ang > bang)
                    } else {
                        false
                    }
                }
            };
            if better {
                best = Some((ql, ang.abs(), q));
            }
        }
    }
    let a1 = scene.substrate.lattice.a1;
    match (degenerate, best) {
        (false, Some((ql, _, q))) => ContactLine {
            angle: wrap_half_turn(q[1].atan2(q[0]) + 0.5 * PI),
            q,
            spacing: 2.0 * PI / ql,
            degenerate: false,
        },
        _ => ContactLine {
            angle: wrap_half_turn(a1[1].atan2(a1[0])),
            q: [0.0, 0.0],
            spacing: f64::INFINITY,
            degenerate: true,
        },
    }
}
