//! Corrugation and static-friction barrier felt along a straight sliding path.
//!
//! ## Lateral force of a rigid slider under constant load
//! At lateral position s along the unit direction e the slider sits at the height z*(s) where the
//! vertical Hertz forces carry W. Each touching pair i pushes the slider along the line of centres,
//! so the lateral force of the contacts on the slider along e is
//! `F_c(s) = Σ_i F_n,i · (Δr_i·e) / D_i` (Δr_i the lateral slider-minus-substrate centre offset,
//! D_i = 2R − δ_i the centre distance). The quasi-static pulling force needed to hold the slider
//! at s is `F_pull(s) = −F_c(s)`; its maximum over the path is the static-friction barrier.
//! With the enthalpy `V(s) = U_Hertz(s, z*) + W·z*` (elastic energy plus the work against the
//! load), `∂V/∂z = 0` at equilibrium gives `F_pull = dV/ds = W·dz*/ds + dU/ds`. For stiff contacts
//! (δ ≪ R) the elastic term is small and `F_pull ≈ W·dz*/ds`: the rigid-slider
//! relation. (When the slider tilts against its mount, V also holds the mount energy ½tᵀK_t t;
//! the envelope theorem still gives `F_pull = dV/ds`.) The direct path reports the exact contact
//! sum (tested against the finite-difference dV/ds); the landscape fast path reports the
//! rigid-limit `W·dz/ds` of the interpolated landscape.

use super::{check_slider_stays_on_substrate, Landscape, MapParams};
use crate::error::SceneError;
use crate::scene::Scene;
use crate::solver::{Model, Solver, StraightPath};

/// Equilibrium along one straight path from the scene's offset (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct PathProfile {
    /// Direction of the path from the substrate x axis (rad).
    pub direction: f64,
    /// Distance along the path of each sample (m): `k·L/n`, k = 0..=n.
    pub s: Vec<f64>,
    /// Slider height z (m) at each sample.
    pub z: Vec<f64>,
    /// Quasi-static pulling force along the path, `F_pull = −Σ F_n (Δr·e)/D` (N), Δr the lateral
    /// slider-minus-substrate centre offset and D the centre distance of each contact.
    pub f_pull: Vec<f64>,
    /// Elastic (Hertz) energy `U = Σ (2/5) k δ^{5/2}` stored in the contacts (J).
    pub energy: Vec<f64>,
    /// Contact number at each sample.
    pub contacts: Vec<u32>,
}

impl PathProfile {
    /// Peak-to-peak height max z − min z along the path (m).
    pub fn corrugation(&self) -> f64 {
        peak_to_peak(&self.z)
    }
    /// Largest pulling force along the path (N): the static-friction barrier.
    pub fn max_pull(&self) -> f64 {
        self.f_pull
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

/// Corrugation felt along one pulling direction (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CorrugationPoint {
    /// Pulling angle α from the contact line (rad).
    pub alpha: f64,
    /// Path direction in the substrate frame, contact-line angle + α (rad).
    pub direction: f64,
    /// Peak-to-peak slider height along the path (m).
    pub corrugation: f64,
    /// Largest quasi-static pulling force along the path (N): the static-friction barrier.
    pub max_lateral_force: f64,
}

fn peak_to_peak(v: &[f64]) -> f64 {
    let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    hi - lo
}

fn samples(params: &MapParams) -> Result<Vec<f64>, SceneError> {
    if !(params.distance.is_finite() && params.distance > 0.0) {
        return Err(SceneError::invalid(
            "distance_um",
            params.distance * 1e6,
            "must be a positive number",
        ));
    }
    if !(params.step.is_finite() && params.step > 0.0 && params.step <= params.distance) {
        return Err(SceneError::invalid(
            "step_um",
            params.step * 1e6,
            "must be positive and at most the distance",
        ));
    }
    let n = (params.distance / params.step - 1e-9).ceil().max(1.0) as usize;
    if n > 10_000_000 {
        return Err(SceneError::invalid(
            "step_um",
            params.step * 1e6,
            "gives more than 10⁷ samples",
        ));
    }
    Ok((0..=n)
        .map(|k| params.distance * k as f64 / n as f64)
        .collect())
}

/// Validates a pulling angle α (rad): finite and |α| ≤ 180°. Errors name the field `alpha_deg`.
pub fn check_alpha(alpha: f64) -> Result<(), SceneError> {
    if !(alpha.is_finite() && alpha.abs() <= std::f64::consts::PI * (1.0 + 1e-12)) {
        return Err(SceneError::invalid(
            "alpha_deg",
            alpha.to_degrees(),
            "must lie in [-180, 180] degrees",
        ));
    }
    Ok(())
}

/// Checks that the slider stays over the substrate along the straight path from its placement
/// to `distance` (m) along the direction `direction` (rad, substrate frame); the error names
/// the field `distance_um`. O(1).
pub fn check_path_stays_on_substrate(
    scene: &Scene,
    direction: f64,
    distance: f64,
) -> Result<(), SceneError> {
    let e = [direction.cos(), direction.sin()];
    let end = [distance * e[0], distance * e[1]];
    check_slider_stays_on_substrate(
        scene,
        [
            [end[0].min(0.0), end[1].min(0.0)],
            [end[0].max(0.0), end[1].max(0.0)],
        ],
        "distance_um",
    )
}

/// Solves the equilibrium along the straight path `shift = s·(cos φ, sin φ)`, s ∈ [0, L]
/// (`params.distance`, sampled every ≤ `params.step`), at rotation `theta` (rad) and load `load`
/// (N), with [`Model::Auto`] ([`Solver::solve_along`]: one candidate search per
/// `params.segment` of path, parallel over segments, deterministic). `progress` is called per
/// solved sample. Cost: L/step + 1 solves.
///
/// Errors: bad distance/step, the slider leaving the substrate along the path (field
/// `distance_um`), or a failed solve.
pub fn path_profile(
    solver: &Solver,
    theta: f64,
    load: f64,
    direction: f64,
    params: &MapParams,
    progress: &(dyn Fn() + Sync),
) -> Result<PathProfile, SceneError> {
    let s = samples(params)?;
    let scene = solver.scene();
    let e = [direction.cos(), direction.sin()];
    check_path_stays_on_substrate(scene, direction, params.distance)?;
    let sub = solver.substrate();
    let path = StraightPath {
        theta,
        origin: [0.0, 0.0],
        e,
        s: &s,
        segment: params.segment,
    };
    let rows = solver.solve_along(path, load, Model::Auto, |_, eq| {
        let mut f = 0.0;
        let mut u = 0.0;
        for c in &eq.contacts {
            let n = c.normal(sub[c.substrate as usize]);
            f -= c.force_n * (n[0] * e[0] + n[1] * e[1]);
            u += solver.contact_energy(c);
        }
        progress();
        (eq.z, f, u, eq.contact_count() as u32)
    })?;
    Ok(PathProfile {
        direction,
        s,
        z: rows.iter().map(|r| r.0).collect(),
        f_pull: rows.iter().map(|r| r.1).collect(),
        energy: rows.iter().map(|r| r.2).collect(),
        contacts: rows.iter().map(|r| r.3).collect(),
    })
}

/// Corrugation along each pulling angle in `alphas` (rad, from the contact line at angle
/// `line_angle`, rad, substrate frame) by direct solves along the path ([`path_profile`]).
/// Exact up to the sampling step. Cost: `alphas.len()·(L/step + 1)` solves.
pub fn corrugation_direct(
    solver: &Solver,
    theta: f64,
    load: f64,
    line_angle: f64,
    alphas: &[f64],
    params: &MapParams,
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<CorrugationPoint>, SceneError> {
    for &a in alphas {
        check_alpha(a)?;
    }
    alphas
        .iter()
        .map(|&alpha| {
            let direction = line_angle + alpha;
            let p = path_profile(solver, theta, load, direction, params, progress)?;
            Ok(CorrugationPoint {
                alpha,
                direction,
                corrugation: p.corrugation(),
                max_lateral_force: p.max_pull(),
            })
        })
        .collect()
}

/// Corrugation along each pulling angle in `alphas` (rad from `line_angle`, rad) from a periodic
/// [`Landscape`] by bicubic interpolation (fast path: no solves). The lateral force is the
/// rigid-limit `W·dz/ds` (central differences of the interpolated heights at the sample
/// spacing), so it omits the elastic term of the exact contact sum. Valid for flat substrates
/// (σ_h = 0), where the landscape is periodic. Cost: `alphas.len()·(L/step + 1)·16` flops.
pub fn corrugation_from_landscape(
    landscape: &Landscape,
    line_angle: f64,
    alphas: &[f64],
    params: &MapParams,
) -> Result<Vec<CorrugationPoint>, SceneError> {
    let s = samples(params)?;
    alphas
        .iter()
        .map(|&alpha| {
            check_alpha(alpha)?;
            let direction = line_angle + alpha;
            let e = [direction.cos(), direction.sin()];
            let z: Vec<f64> = s
                .iter()
                .map(|&si| landscape.interpolate([si * e[0], si * e[1]]))
                .collect();
            let mut fmax = f64::NEG_INFINITY;
            for k in 0..z.len() {
                let (a, b) = (k.saturating_sub(1), (k + 1).min(z.len() - 1));
                let f = landscape.load * (z[b] - z[a]) / (s[b] - s[a]);
                fmax = fmax.max(f);
            }
            Ok(CorrugationPoint {
                alpha,
                direction,
                corrugation: peak_to_peak(&z),
                max_lateral_force: fmax,
            })
        })
        .collect()
}
