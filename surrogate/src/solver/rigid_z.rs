//! Rigid slider, height only: the safeguarded 1-D Newton root find of ΣF_z(z) = W
//! (see [`super::z_root::ZRoot`]), exact for flat, inversion-symmetric scenes.

use super::assemble::{assemble, Ctx};
use super::z_root::ZRoot;
use super::{Equilibrium, Model, PairSet};
use crate::error::SceneError;

/// The 1-D problem of a pair set at zero tilt: `u = z − h` for every pair. Build once per θ,
/// solve for every load. O(P log P).
pub(crate) fn rigid_z_problem(ctx: &Ctx, ps: &PairSet) -> ZRoot {
    ZRoot::new(ps.pairs.iter().map(|p| (p.r2, p.h)), ctx.two_r, ctx.hertz)
}

/// Rigid-z equilibrium for `load` W (N) from a prepared problem. For a pair at lateral distance
/// r and substrate height h, with `u = z − h`, `D = √(r² + u²)`, `δ = 2R − D`:
/// `F_z = (4/3)E*√R_eff δ^{3/2} · u/D`; solves `Σ F_z(z) = W`. O(active pairs) per iteration,
/// typically < 15 iterations.
pub(crate) fn solve_rigid_z(
    ctx: &Ctx,
    ps: &PairSet,
    zr: &ZRoot,
    load: f64,
) -> Result<Equilibrium, SceneError> {
    let (z, iters) = zr.solve(load, ctx.hertz, ctx.params)?;
    Ok(assemble(
        ctx,
        ps,
        Model::RigidZ,
        load,
        z,
        [0.0, 0.0],
        &|_| 0.0,
        iters,
    ))
}
