//! The sliding path of the friction estimate: its length (one substrate period along lattice
//! directions, a fixed length otherwise), its samples, and the per-sample sums over the contacts.

use super::FrictionParams;
use crate::error::SceneError;
use crate::scene::Lattice;
use crate::solver::{Model, Solver, StraightPath};

/// The shortest substrate lattice vector `T = m·a1 + n·a2` along the unit direction `e` (within
/// the angle `tol`, rad, and pointing along +e) with `|T| ≤ max_len` (m): its length (m), the
/// period of the landscape along `e` (translating the slider by T maps the substrate onto
/// itself). `None` when the direction is not a lattice direction within that length. O(max_len²
/// / cell area).
pub fn lattice_period(lattice: &Lattice, e: [f64; 2], max_len: f64, tol: f64) -> Option<f64> {
    let s = lattice.min_spacing();
    let lim = (max_len / s * 2.0).ceil() as i64 + 1;
    let mut best: Option<f64> = None;
    for m in -lim..=lim {
        for n in -lim..=lim {
            if m == 0 && n == 0 {
                continue;
            }
            let t = lattice.point(m as f64, n as f64);
            let len = t[0].hypot(t[1]);
            if len > max_len * (1.0 + 1e-12) || t[0] * e[0] + t[1] * e[1] <= 0.0 {
                continue;
            }
            let sin = (t[0] * e[1] - t[1] * e[0]).abs() / len;
            if sin <= tol && best.is_none_or(|b| len < b) {
                best = Some(len);
            }
        }
    }
    best
}

/// Everything the estimate needs from one path sample (SI).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Sample {
    /// Enthalpy `V = Σ (2/5) k δ^{5/2} + W·z + ½ tᵀ K_t t` (J).
    pub v: f64,
    /// Quasi-static pulling force `F_pull = dV/ds = −Σ F_n n·e` (N).
    pub f_pull: f64,
    /// Force of the contacts on the slider across the path, along e⊥ = e rotated by +90°:
    /// `F_⊥ = Σ F_n n·e⊥ = −dV/dy` (N).
    pub f_perp: f64,
    /// Coating friction force `Σ μ(p0_i) F_n,i |e − (e·n_i) n_i|` (N).
    pub coating: f64,
    /// Vertical load carried by failed contacts `Σ_{p0 > P_crit} F_z` (N).
    pub failed_load: f64,
    /// Largest p0 (Pa).
    pub p_max: f64,
    /// Contact number.
    pub contacts: usize,
    /// Lateral stiffness of the contacting chains (N/m):
    /// `Σ_i (1/k_slider_xy + 1/(n_i k_substrate_xy))⁻¹` over the slider spheres in contact, n_i
    /// of them touching sphere i.
    pub k_lateral: f64,
}

/// Solves every sample `s` (m) of the path from the scene's placement shifted by `origin` (m)
/// along the unit direction `e` at rotation `theta` (rad) for each load of `loads` (N) with
/// [`Model::Auto`] ([`Solver::solve_along_loads`]: one candidate search per `params.segment` of path and one
/// pair list per sample serve every load; parallel, deterministic), and reduces each equilibrium
/// to a [`Sample`]. Per load (in order): its samples, or its first failed solve.
pub(crate) fn solve_samples(
    solver: &Solver,
    theta: f64,
    origin: [f64; 2],
    e: [f64; 2],
    loads: &[f64],
    s: &[f64],
    params: &FrictionParams,
) -> Vec<Result<Vec<Sample>, SceneError>> {
    let scene = solver.scene();
    let kt = solver.tilt_stiffness_at(theta);
    let coat = scene.coating;
    let sub = solver.substrate();
    let path = StraightPath {
        theta,
        origin,
        e,
        s,
        segment: params.segment,
    };
    solver.solve_along_loads(path, loads, Model::Auto, |_, j, eq| {
        let load = loads[j];
        let t = eq.tilt;
        let mut smp = Sample {
            v: load * eq.z
                + 0.5
                    * (t[0] * (kt[0][0] * t[0] + kt[0][1] * t[1])
                        + t[1] * (kt[1][0] * t[0] + kt[1][1] * t[1])),
            p_max: eq.p_max,
            contacts: eq.contact_count(),
            ..Sample::default()
        };
        let mut i = 0;
        while i < eq.contacts.len() {
            // contacts come grouped by slider sphere
            let sl = eq.contacts[i].slider;
            let mut n_i = 0.0;
            while i < eq.contacts.len() && eq.contacts[i].slider == sl {
                let c = &eq.contacts[i];
                let n = c.normal(sub[c.substrate as usize]);
                let en = n[0] * e[0] + n[1] * e[1];
                let mu = coat.mu(c.p0);
                smp.v += solver.contact_energy(c);
                smp.f_pull -= c.force_n * en;
                smp.f_perp += c.force_n * (n[1] * e[0] - n[0] * e[1]);
                smp.coating += mu * c.force_n * (1.0 - en * en).max(0.0).sqrt();
                if c.failed {
                    smp.failed_load += c.force_z;
                }
                n_i += 1.0;
                i += 1;
            }
            smp.k_lateral += 1.0 / (1.0 / params.k_slider_xy + 1.0 / (n_i * params.k_substrate_xy));
        }
        smp
    })
}
