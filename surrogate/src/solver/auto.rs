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

use super::ctx::Ctx;
use super::law::Law;
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

/// [`Model::Auto`](super::Model::Auto) for `load` W (N) on the prepared rigid-z problem `rz` of
/// `ps` (shared across loads). Cost: one rigid-z solve and an O(P) pass summing its contact
/// moment, then its assembly where that moment is negligible; where it escalates, plus one O(P) pass selecting the pairs near contact, the
/// tilt Newton on them (typically 3–5 iterations of O(few hundred)) and a second assembly.
pub(crate) fn solve_auto<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    rz: &RigidZ<L>,
    load: f64,
) -> Result<Equilibrium, SceneError> {
    let (zeta, iters) = rz.zr.solve(ctx, load)?;
    // the rigid-z moment, summed as the assembly sums it (same bits), without building contacts
    if !ctx.tilts || moment_negligible(ctx, load, rz.moment(ctx, ps, zeta)) {
        return Ok(rz.assemble(ctx, ps, load, zeta, iters));
    }
    let near = NearSet::new(ctx, &rz.bp, zeta, ctx.lever_bound(ps));
    let (q, it) = tilt_from(ctx, &rz.bp, &near, load, zeta)?;
    Ok(assemble_tilt(ctx, ps, &rz.bp, rz.zref, load, q, iters + it))
}
