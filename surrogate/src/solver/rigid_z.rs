//! Rigid slider, height only: the safeguarded 1-D Newton root find of ΣF_z(z) = W
//! (see [`super::z_root::ZRoot`]), exact for flat, inversion-symmetric scenes.

use super::assemble::assemble;
use super::ctx::Ctx;
use super::law::{body_pairs, BodyPair, Law};
use super::z_root::ZRoot;
use super::{Equilibrium, Model, PairSet};
use crate::error::SceneError;

/// The 1-D problem of a pair set at zero tilt. Build once per θ, solve for every load.
/// O(P log P).
pub(crate) struct RigidZ<L> {
    pub bp: Vec<BodyPair<L>>,
    pub zref: f64,
    pub zr: ZRoot,
}

impl<L: Law> RigidZ<L> {
    /// Prepares the pairs of `ps`.
    pub fn new(ctx: &Ctx, ps: &PairSet) -> RigidZ<L> {
        let (bp, zref) = body_pairs::<L>(ctx, ps);
        let zr = ZRoot::new(&bp, [0.0, 0.0], ctx.two_r, ctx.hertz.k());
        RigidZ { bp, zref, zr }
    }

    /// Rigid-z equilibrium for `load` W (N). For a pair at lateral distance r, with vertical
    /// centre gap u, `D = √(r² + u²)`, `δ = 2R − D`: `F_z = (4/3)E*√R_eff δ^{3/2} · u/D`;
    /// solves `Σ F_z(z) = W`. O(active pairs) per iteration, typically < 15 iterations.
    pub fn solve(&self, ctx: &Ctx, ps: &PairSet, load: f64) -> Result<Equilibrium, SceneError> {
        let (zeta, iters) = self.zr.solve(load, ctx.hertz, ctx.params)?;
        Ok(self.assemble(ctx, ps, load, zeta, iters))
    }

    /// The rigid-z [`Equilibrium`] at the converged ζ (m).
    pub fn assemble(
        &self,
        ctx: &Ctx,
        ps: &PairSet,
        load: f64,
        zeta: f64,
        iters: usize,
    ) -> Equilibrium {
        assemble(
            ctx,
            ps,
            &self.bp,
            self.zref,
            Model::RigidZ,
            load,
            [zeta, 0.0, 0.0],
            |_| 0.0,
            iters,
        )
    }
}
