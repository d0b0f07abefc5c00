//! Turns a converged state (z, tilts, deflections) into an [`Equilibrium`] with its contact list.

use super::law::pair_response;
use super::{ContactInfo, Equilibrium, Model, PairSet, SolverParams};
use crate::contact::Hertz;
use crate::scene::Coating;

/// Everything a model needs besides the pairs: the contact law, the substrate, the knobs.
pub(crate) struct Ctx<'a> {
    pub hertz: &'a Hertz,
    /// Contact distance 2R (m).
    pub two_r: f64,
    pub coating: &'a Coating,
    /// Substrate sphere centres `[x, y, h]` (m).
    pub substrate: &'a [[f64; 3]],
    pub params: &'a SolverParams,
    /// Length scale (m) of the tilt unknowns: the slider radius (≥ sphere radius).
    pub scale: f64,
}

/// Height (m) of slider sphere `arm` (m, about the disc centre) for body height `z` (m) and tilts
/// `[about x, about y]` (rad): `z + t_x·y − t_y·x`.
#[inline]
pub(crate) fn body_height(z: f64, tilt: [f64; 2], arm: [f64; 2]) -> f64 {
    z + tilt[0] * arm[1] - tilt[1] * arm[0]
}

/// Builds the [`Equilibrium`]: every pair with δ > 0 becomes a [`ContactInfo`] whose point is the
/// midpoint of the two sphere centres; the residuals are recomputed from the contact forces.
/// `defl(i)` is the upward deflection (m) of slider sphere i relative to the rigid body.
#[allow(clippy::too_many_arguments)]
pub(crate) fn assemble(
    ctx: &Ctx,
    ps: &PairSet,
    model: Model,
    load: f64,
    z: f64,
    tilt: [f64; 2],
    defl: &dyn Fn(u32) -> f64,
    iterations: usize,
) -> Equilibrium {
    let k = ctx.hertz.k();
    let mut contacts = Vec::new();
    let mut p_max: f64 = 0.0;
    let mut fsum = 0.0;
    let mut mom = [0.0; 2];
    for p in &ps.pairs {
        let arm = ps.arm(p.slider);
        let w = defl(p.slider);
        let zs = body_height(z, tilt, arm) + w;
        let u = zs - p.h;
        let r = pair_response(k, ctx.two_r, p.r2, u);
        if r.fz <= 0.0 {
            continue;
        }
        let dd = (p.r2 + u * u).sqrt();
        let delta = ctx.two_r - dd;
        let fnorm = ctx.hertz.force(delta);
        let p0 = ctx.hertz.p0(delta);
        p_max = p_max.max(p0);
        fsum += r.fz;
        mom[0] += r.fz * arm[1];
        mom[1] += r.fz * arm[0];
        let s = ps.slider_xy[p.slider as usize];
        let b = ctx.substrate[p.substrate as usize];
        contacts.push(ContactInfo {
            slider: p.slider,
            substrate: p.substrate,
            point: [0.5 * (s[0] + b[0]), 0.5 * (s[1] + b[1]), 0.5 * (zs + p.h)],
            overlap: delta,
            force_n: fnorm,
            force_z: r.fz,
            p0,
            failed: ctx.coating.failed(p0),
            deflection: w,
        });
    }
    Equilibrium {
        model,
        load,
        z,
        tilt,
        contacts,
        p_max,
        residual: fsum - load,
        iterations,
        moment_residual: mom,
    }
}
