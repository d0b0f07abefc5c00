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
        let (zeta, iters) = self.zr.solve(ctx, load)?;
        Ok(self.assemble(ctx, ps, load, zeta, iters))
    }

    /// The contact moment about the disc centre `M_c = [Σ F_z·(y − y_c), −Σ F_z·(x − x_c)]`
    /// (N·m) at ζ (m), zero tilt: the [`Equilibrium::moment_residual`] its assembly would give,
    /// bit for bit (same terms, same order). O(P).
    pub fn moment(&self, ctx: &Ctx, ps: &PairSet, zeta: f64) -> [f64; 2] {
        let (k, two_r) = (ctx.hertz.k(), ctx.two_r);
        let mut mom = [0.0; 2];
        for (p, b) in ps.pairs.iter().zip(&self.bp) {
            // a pair at or below ζ does not touch (skipped before its response: same sums)
            if b.c <= zeta {
                continue;
            }
            let r = b.response(k, two_r, zeta - b.c);
            if r.fz <= 0.0 {
                continue;
            }
            let arm = ps.arm(p.slider);
            mom[0] += r.fz * arm[1];
            mom[1] -= r.fz * arm[0];
        }
        // the residual subtracts the mount's moment at zero tilt: K_t·0 = 0
        let km = ctx.mount_moment([0.0, 0.0]);
        [mom[0] - km[0], mom[1] - km[1]]
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
            zeta,
        )
    }
}
