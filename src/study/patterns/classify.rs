//! The contact type of a slider on a substrate from the two lattices' reciprocal-space
//! geometry (see the module docs of [`super`]).

use super::contact_type::ContactType;
use super::tidy::tidy;
use std::f64::consts::PI;
use surrogate::scene::rebased;
use surrogate::Lattice;

/// Reciprocal vectors `m b1 + n b2` (1/m) of `l` with |G| ≤ `gmax`, the origin excluded.
fn reciprocal(l: &Lattice, gmax: f64) -> Vec<[f64; 2]> {
    let det = l.cell_area();
    let b1 = [2.0 * PI * l.a2[1] / det, -2.0 * PI * l.a2[0] / det];
    let b2 = [-2.0 * PI * l.a1[1] / det, 2.0 * PI * l.a1[0] / det];
    // |m| ≤ gmax·|a1|/2π bounds the coefficients
    let mmax = (gmax * l.a1[0].hypot(l.a1[1]) / (2.0 * PI)).ceil() as i64 + 1;
    let nmax = (gmax * l.a2[0].hypot(l.a2[1]) / (2.0 * PI)).ceil() as i64 + 1;
    let mut out = Vec::new();
    for m in -mmax..=mmax {
        for n in -nmax..=nmax {
            if m == 0 && n == 0 {
                continue;
            }
            let g = [
                m as f64 * b1[0] + n as f64 * b2[0],
                m as f64 * b1[1] + n as f64 * b2[1],
            ];
            if g[0].hypot(g[1]) <= gmax * (1.0 + 1e-9) {
                out.push(g);
            }
        }
    }
    out
}

/// Shortest reciprocal vector length (1/m) of `l`: 2π / (the largest row spacing).
fn g_min(l: &Lattice) -> f64 {
    let det = l.cell_area();
    let b1 = [2.0 * PI * l.a2[1] / det, -2.0 * PI * l.a2[0] / det];
    let b2 = [-2.0 * PI * l.a1[1] / det, 2.0 * PI * l.a1[0] / det];
    let mut best = f64::INFINITY;
    for m in -3i32..=3 {
        for n in -3i32..=3 {
            if m != 0 || n != 0 {
                let g = [
                    m as f64 * b1[0] + n as f64 * b2[0],
                    m as f64 * b1[1] + n as f64 * b2[1],
                ];
                best = best.min(g[0].hypot(g[1]));
            }
        }
    }
    best
}

/// Whether the basis' structure factor at G is non-zero (relative 1e-6).
fn structure_factor_nonzero(basis: &[[f64; 2]], g: [f64; 2]) -> bool {
    let (mut re, mut im) = (0.0, 0.0);
    for b in basis {
        let ph = g[0] * b[0] + g[1] * b[1];
        re += ph.cos();
        im += ph.sin();
    }
    re.hypot(im) > 1e-6 * basis.len() as f64
}

/// The contact type of a slider (lattice + basis, rotated by `theta` rad) on a substrate
/// (lattice + basis); see the module docs.
pub fn classify(
    slider: &Lattice,
    slider_basis: &[[f64; 2]],
    theta: f64,
    substrate: &Lattice,
    substrate_basis: &[[f64; 2]],
    max_order: f64,
) -> ContactType {
    let gmax = max_order * g_min(substrate);
    let (s, c) = theta.sin_cos();
    let (bs, bb) = (rebased(slider_basis), rebased(substrate_basis));
    let gb: Vec<[f64; 2]> = reciprocal(substrate, gmax)
        .into_iter()
        .filter(|g| structure_factor_nonzero(&bb, *g))
        .collect();
    let mut common: Vec<[f64; 2]> = Vec::new();
    for g in reciprocal(slider, gmax) {
        if !structure_factor_nonzero(&bs, g) {
            continue;
        }
        let gr = [c * g[0] - s * g[1], s * g[0] + c * g[1]];
        let l = gr[0].hypot(gr[1]);
        if gb
            .iter()
            .any(|h| (h[0] - gr[0]).hypot(h[1] - gr[1]) <= 1e-6 * l)
        {
            common.push(gr);
        }
    }
    let Some(n) = common.first().copied() else {
        return ContactType::Lubric;
    };
    let ln = n[0].hypot(n[1]);
    if common
        .iter()
        .all(|g| (n[0] * g[1] - n[1] * g[0]).abs() <= 1e-6 * ln * g[0].hypot(g[1]))
    {
        let lubric = (n[1].atan2(n[0]) + 0.5 * PI).to_degrees().rem_euclid(180.0);
        ContactType::Directional {
            lubric_deg: tidy(if (lubric - 180.0).abs() < 1e-9 {
                0.0
            } else {
                lubric
            }),
        }
    } else {
        ContactType::Interlocked
    }
}
