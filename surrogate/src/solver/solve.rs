//! The solves of a [`Solver`]: one load or several at a pose or on a prepared [`PairSet`], and
//! several loads on a partial pair list (the path solve's), with the pair law chosen by the
//! scene's sphere sizes.

use super::auto::solve_auto;
use super::compliant::solve_compliant;
use super::ctx::{Ctx, Watch};
use super::law::{Law, Own, Shared};
use super::rigid_tilt::{assemble_tilt, solve_rigid_tilt, tilt_from, NearSet};
use super::rigid_z::RigidZ;
use super::{Equilibrium, Model, PairSet, Pose, Solver};
use crate::error::SceneError;

impl Solver {
    /// Equilibrium of the slider at `pose` under `load` W (N) with `model`.
    /// Errors: non-positive/NaN load (field `load_mN`), `rigid-tilt` under a locked mount (field
    /// `model`, see [`Solver::check_model`]), no substrate under the slider, a slider that tips
    /// over the substrate edge (tilt models, free mount).
    pub fn solve(&self, pose: Pose, load: f64, model: Model) -> Result<Equilibrium, SceneError> {
        check_load(load)?;
        let ps = self.pairs_at(pose);
        self.solve_pairs(&ps, load, model)
    }

    /// Equilibrium for one load W (N) from a prepared [`PairSet`].
    pub fn solve_pairs(
        &self,
        ps: &PairSet,
        load: f64,
        model: Model,
    ) -> Result<Equilibrium, SceneError> {
        check_load(load)?;
        self.check_model(model)?;
        let ctx = self.ctx(ps.theta);
        match ctx.sizes {
            None => solve_one::<Shared>(&ctx, ps, load, model),
            Some(_) => solve_one::<Own>(&ctx, ps, load, model),
        }
    }

    /// Equilibria for several loads (N) at one pose, sharing the candidate search and, for
    /// auto, rigid-z and rigid-tilt, the prepared pair list (body pairs, touch heights).
    /// Results in the order of `loads`.
    pub fn solve_loads(
        &self,
        pose: Pose,
        loads: &[f64],
        model: Model,
    ) -> Vec<Result<Equilibrium, SceneError>> {
        let ps = self.pairs_at(pose);
        self.solve_loads_pairs(&ps, loads, model)
    }

    /// [`Solver::solve_loads`] on a prepared [`PairSet`].
    pub fn solve_loads_pairs(
        &self,
        ps: &PairSet,
        loads: &[f64],
        model: Model,
    ) -> Vec<Result<Equilibrium, SceneError>> {
        if let Err(e) = self.check_model(model) {
            return loads.iter().map(|_| Err(e.clone())).collect();
        }
        let ctx = self.ctx(ps.theta);
        match model {
            Model::Auto | Model::RigidZ | Model::RigidTilt => match ctx.sizes {
                None => solve_many::<Shared>(&ctx, ps, loads, model),
                Some(_) => solve_many::<Own>(&ctx, ps, loads, model),
            },
            Model::Compliant => loads
                .iter()
                .map(|&w| self.solve_pairs(ps, w, model))
                .collect(),
        }
    }

    /// [`Solver::solve_loads_pairs`] (auto, rigid-z or rigid-tilt) on a partial list `ps` that
    /// holds every pair touching above the height `floor` (m, absolute): per load, the
    /// equilibrium bit-identical to the one on every pair, or `None` where the solve would have
    /// needed a pair below the floor (or failed): solve that load on every pair.
    /// `gmax` bounds every slider sphere's lever `|arm|/L` ([`Solver::lever_bound`]).
    ///
    /// `warm`, one per load: the previous sample's z root as the warm start of the z root
    /// (NaN: a cold start, the same bracket as [`Solver::solve_loads_pairs`], so that a full
    /// list with `floor` = −∞ and no warm start gives its bit-identical answer); updated with
    /// this sample's (NaN where `None`).
    pub(crate) fn solve_loads_partial(
        &self,
        ps: &PairSet,
        loads: &[f64],
        model: Model,
        floor: f64,
        gmax: f64,
        warm: &mut [Warm],
    ) -> Vec<Option<Equilibrium>> {
        debug_assert!(model != Model::Compliant);
        if self.check_model(model).is_err() {
            return vec![None; loads.len()];
        }
        let watch = Watch::new(gmax);
        let mut ctx = self.ctx(ps.theta);
        ctx.watch = Some(&watch);
        match ctx.sizes {
            None => solve_many_partial::<Shared>(&ctx, ps, loads, model, floor, warm),
            Some(_) => solve_many_partial::<Own>(&ctx, ps, loads, model, floor, warm),
        }
    }
}

/// One load with the pair law `L` (see [`Solver::solve_pairs`]).
fn solve_one<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    load: f64,
    model: Model,
) -> Result<Equilibrium, SceneError> {
    match model {
        Model::Auto => solve_auto(ctx, ps, &RigidZ::<L>::new(ctx, ps), load),
        Model::RigidZ => RigidZ::<L>::new(ctx, ps).solve(ctx, ps, load),
        Model::RigidTilt => solve_rigid_tilt::<L>(ctx, ps, load),
        Model::Compliant => solve_compliant::<L>(ctx, ps, load),
    }
}

/// Several loads sharing one rigid-z problem with the pair law `L` (auto, rigid-z, rigid-tilt;
/// see [`Solver::solve_loads_pairs`]).
fn solve_many<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    loads: &[f64],
    model: Model,
) -> Vec<Result<Equilibrium, SceneError>> {
    let rz = RigidZ::<L>::new(ctx, ps);
    loads
        .iter()
        .map(|&w| solve_one_of_many(ctx, ps, &rz, w, model))
        .collect()
}

/// [`solve_many`] on a partial list whose left-out pairs all touch at or below the height
/// `floor` (m, absolute): per load, the equilibrium where the solve never relied on a pair below
/// the floor (then it is bit-identical to the solve on every pair), else `None` (also for any
/// error: the caller solves that load on every pair). `ctx.watch` must be set.
fn solve_many_partial<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    loads: &[f64],
    model: Model,
    floor: f64,
    warm: &mut [Warm],
) -> Vec<Option<Equilibrium>> {
    let watch = ctx.watch.expect("a partial list is watched");
    let rz = RigidZ::<L>::new(ctx, ps);
    // heights are compared relative to z_ref, with a margin far above their round-off
    let floor_rel = floor - rz.zref + 1e-12 * ctx.two_r;
    loads
        .iter()
        .zip(warm.iter_mut())
        .map(|(&w, warm)| {
            watch.lowest.set(f64::INFINITY);
            watch.guess.set(warm.z0 - rz.zref);
            watch.root.set(f64::NAN);
            // the previous tilted state, extrapolated linearly from the one before where known
            // (the untilted root's estimate moved with it)
            let (t, b) = (warm.tilt, warm.tilt_before);
            let t = if b.iter().all(|v| v.is_finite()) {
                watch.guess.set(watch.guess.get() + t[0] - b[0]);
                [2.0 * t[0] - b[0], 2.0 * t[1] - b[1], 2.0 * t[2] - b[2]]
            } else {
                t
            };
            watch.tilt_guess.set([t[0] - rz.zref, t[1], t[2]]);
            watch.tilt_root.set([f64::NAN; 3]);
            let eq = solve_one_of_many(ctx, ps, &rz, w, model);
            let ok = eq.is_ok() && watch.lowest.get() > floor_rel;
            *warm = if ok {
                Warm {
                    z0: rz.zref + watch.root.get(),
                    depth: -watch.root.get(),
                    need: rz.zref + watch.lowest.get(),
                    tilt: {
                        let t = watch.tilt_root.get();
                        [rz.zref + t[0], t[1], t[2]]
                    },
                    tilt_before: warm.tilt,
                }
            } else {
                Warm::default()
            };
            eq.ok().filter(|_| ok)
        })
        .collect()
}

/// What a path's previous sample knew of one load: the untilted z root (m, absolute; NaN: none),
/// its depth below the highest touch height (m) and the lowest height it relied on.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Warm {
    pub z0: f64,
    pub depth: f64,
    /// The lowest height (m, absolute) the solve relied on (NaN: none).
    pub need: f64,
    /// The tilted state `[ζ, L·t_x, L·t_y]` (m, ζ absolute; NaN: none, or the sample did not
    /// escalate): the next sample's start ([`super::ctx::Watch::tilt_guess`]).
    pub tilt: [f64; 3],
    /// The sample before's tilted state, likewise (the start extrapolates linearly from both).
    pub tilt_before: [f64; 3],
}

impl Default for Warm {
    fn default() -> Self {
        Warm {
            z0: f64::NAN,
            depth: f64::NAN,
            need: f64::NAN,
            tilt: [f64::NAN; 3],
            tilt_before: [f64::NAN; 3],
        }
    }
}

/// One load of [`solve_many`].
fn solve_one_of_many<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    rz: &RigidZ<L>,
    w: f64,
    model: Model,
) -> Result<Equilibrium, SceneError> {
    check_load(w)?;
    match model {
        Model::Auto => solve_auto(ctx, ps, rz, w),
        Model::RigidZ => rz.solve(ctx, ps, w),
        _ => {
            let (z0, it0) = rz.zr.solve(ctx, w)?;
            let near = NearSet::new(ctx, &rz.bp, z0, ctx.lever_bound(ps));
            let (q, it1) = tilt_from(ctx, &rz.bp, &near, w, z0, None)?;
            Ok(assemble_tilt(ctx, ps, &rz.bp, rz.zref, w, q, it0 + it1))
        }
    }
}

/// Refuses a load (N) that is not a positive finite number, naming `load_mN`.
pub(crate) fn check_load(load: f64) -> Result<(), SceneError> {
    if load.is_finite() && load > 0.0 {
        Ok(())
    } else {
        Err(SceneError::invalid(
            "load_mN",
            crate::units::n_to_mn(load),
            "must be a positive number",
        ))
    }
}
