//! [`Model::Auto`]: the cheapest model that is exact for the scene's mount *and* the pose.
//!
//! Rule: a `locked` mount has no tilt, so rigid-z is exact. For a `free` or `springs` mount the
//! rigid-z answer (t = 0) is the tilt model's answer exactly when its contact moment
//! `M_c = [Σ F_z·(y − y_c), −Σ F_z·(x − x_c)]` already balances the mount's `K_t·t = 0` to the
//! tilt solver's own convergence tolerance, `|M_c| ≤ moment_rtol·W·L` per component: the tilt
//! Newton started from that state would stop at its first check and return it. This holds on
//! inversion-symmetric poses (a flat substrate with the disc centre on a substrate site or midway
//! between two), where the moments cancel pairwise. Otherwise (an in-plane shift, the substrate
//! edge, σ_h > 0) auto escalates to rigid-tilt, warm-started from the rigid-z state, and reports
//! `RigidTilt` in [`Equilibrium::model`].

use super::assemble::Ctx;
use super::law::{pair_response, BodyPair};
use super::rigid_tilt::{assemble_tilt, tilt_from, NearSet};
use super::rigid_z::RigidZ;
use super::{Equilibrium, PairSet};
use crate::error::SceneError;

/// Whether every component of the moment residual `m` (N·m) is within the tilt solver's
/// convergence tolerance `moment_rtol·W·L` for `load` W (N).
pub(crate) fn moment_negligible(ctx: &Ctx, load: f64, m: [f64; 2]) -> bool {
    let tol = ctx.params.moment_rtol * load * ctx.scale;
    m[0].abs() <= tol && m[1].abs() <= tol
}

/// Contact moment `M_c = L·Σ F_z g` (N·m) of the rigid slider at height ζ (m), zero tilt, summed
/// over the pairs `touching` (indices into `bp`). O(touching).
fn contact_moment(ctx: &Ctx, bp: &[BodyPair], touching: &[u32], zeta: f64) -> [f64; 2] {
    let k = ctx.hertz.k();
    let mut m = [0.0; 2];
    for &j in touching {
        let p = &bp[j as usize];
        let r = pair_response(k, ctx.two_r, p.r2, p.ut, zeta - p.c);
        m[0] += r.fz * p.g[0];
        m[1] += r.fz * p.g[1];
    }
    [m[0] * ctx.scale, m[1] * ctx.scale]
}

/// [`Model::Auto`](super::Model::Auto) for `load` W (N) on the prepared rigid-z problem `rz` of
/// `ps` (shared across loads). Cost: one rigid-z solve, the moment check over its contacts
/// (O(contacts)) and one O(P) assembly; where it escalates, plus one O(P) pass selecting the
/// pairs near contact and the tilt Newton on them (typically 3–5 iterations of O(few hundred)).
pub(crate) fn solve_auto(
    ctx: &Ctx,
    ps: &PairSet,
    rz: &RigidZ,
    load: f64,
) -> Result<Equilibrium, SceneError> {
    let mut touching = Vec::new();
    let (zeta, iters) = rz
        .zr
        .solve_touching(load, ctx.hertz, ctx.params, &mut touching)?;
    if !ctx.tilts || moment_negligible(ctx, load, contact_moment(ctx, &rz.bp, &touching, zeta)) {
        return Ok(rz.assemble(ctx, ps, load, zeta, iters));
    }
    let near = NearSet::new(&rz.bp, zeta);
    let (q, it) = tilt_from(ctx, &rz.bp, &near, load, zeta)?;
    Ok(assemble_tilt(ctx, ps, &rz.bp, rz.zref, load, q, iters + it))
}
