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

use super::ctx::{Ctx, Watch};
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
/// moment, then its assembly where that moment is negligible; where it escalates, plus one O(P)
/// pass selecting the pairs near contact, the tilt Newton on them (typically 3–5 iterations of
/// O(few hundred)) and a second assembly.
///
/// On a path ([`Ctx::watch`]) whose previous sample escalated, the rigid-z solve is skipped: the
/// tilt Newton starts from the previous tilted states, extrapolated ([`Watch::tilt_guess`]), so
/// the sample costs the tilt Newton and one assembly. Its answer is the tilt model's equilibrium to the
/// solver's tolerances, which is the rigid-z answer (to the same tolerances) wherever that one
/// balances the moments (`docs/validation/path-solve.md`).
pub(crate) fn solve_auto<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    rz: &RigidZ<L>,
    load: f64,
) -> Result<Equilibrium, SceneError> {
    if let Some((w, start, z0)) = continued_tilt(ctx) {
        // the working set around the untilted root's estimate: the previous sample's, moved
        // as the tilted height moves
        let near = NearSet::new(ctx, &rz.bp, z0, ctx.lever_bound(ps));
        let (q, it) = tilt_from(ctx, &rz.bp, &near, load, z0, Some(start))?;
        w.root.set(z0 + (q[0] - start[0]));
        w.tilt_root.set(q);
        return Ok(assemble_tilt(ctx, ps, &rz.bp, rz.zref, load, q, it));
    }
    let (zeta, iters) = rz.zr.solve(ctx, load)?;
    // the rigid-z moment, summed as the assembly sums it (same bits), without building contacts
    if !ctx.tilts || moment_negligible(ctx, load, rz.moment(ctx, ps, zeta)) {
        return Ok(rz.assemble(ctx, ps, load, zeta, iters));
    }
    let near = NearSet::new(ctx, &rz.bp, zeta, ctx.lever_bound(ps));
    let (q, it) = tilt_from(ctx, &rz.bp, &near, load, zeta, None)?;
    if let Some(w) = ctx.watch {
        w.tilt_root.set(q);
    }
    Ok(assemble_tilt(ctx, ps, &rz.bp, rz.zref, load, q, iters + it))
}

/// The watch, the previous sample's tilted state `[ζ, L·t_x, L·t_y]` and its untilted root (m,
/// heights relative to this sample's z_ref) where a path's previous sample escalated to the
/// tilt model; `None` else.
fn continued_tilt<'a>(ctx: &Ctx<'a>) -> Option<(&'a Watch, [f64; 3], f64)> {
    let w = ctx.watch?;
    let (g, z0) = (w.tilt_guess.get(), w.guess.get());
    (ctx.tilts && g.iter().all(|v| v.is_finite()) && z0.is_finite() && z0 < 0.0)
        .then_some((w, g, z0))
}
