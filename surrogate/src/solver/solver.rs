//! [`Solver`]: a scene prepared for many quasi-static solves (different θ, shifts and loads).

use super::auto::solve_auto;
use super::compliant::solve_compliant;
use super::ctx::{Ctx, Sizes, Watch};
use super::law::{Law, Own, Shared};
use super::rigid_tilt::{assemble_tilt, solve_rigid_tilt, tilt_from, NearSet};
use super::rigid_z::RigidZ;
use super::{Equilibrium, Model, PairSet, SolverParams};
use crate::contact::{
    swept_distance2, BvhSearch, CandidatePair, CandidateSearch, GridSearch, Hertz,
};
use crate::error::SceneError;
use crate::scene::{place, rotate_tilt_stiffness, Scene};
use crate::solver::ContactInfo;

/// Lateral pose of the slider: rotation θ (rad) and in-plane shift (m) of its centre from the
/// scene's offset.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    /// Rotation θ of the slider lattice (rad).
    pub theta: f64,
    /// In-plane shift `[dx, dy]` (m) added to the scene's slider offset.
    pub shift: [f64; 2],
}

/// Which candidate search finds the slider–substrate pairs. Both return identical pair lists
/// (tested on perturbed scenes and random poses).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SearchKind {
    /// Uniform bucket grid ([`GridSearch`]): the fast path (see benches/screen.rs).
    #[default]
    Grid,
    /// parry3d bounding-volume hierarchy ([`BvhSearch`]).
    Bvh,
}

/// A scene prepared for repeated solves: substrate spheres indexed once (grid and parry3d BVH),
/// slider sites generated once, Hertz law cached. `Sync`: share one `Solver` across rayon threads.
pub struct Solver {
    scene: Scene,
    hertz: Hertz,
    substrate: Vec<[f64; 3]>,
    grid: GridSearch,
    bvh: BvhSearch,
    local: Vec<[f64; 2]>,
    /// Per-sphere radii when the scene has per-site sizes (`None`: one size per body, the fast
    /// path: one Hertz law and one contact distance for every pair).
    sizes: Option<Sizes>,
    /// Lateral reach (m) of the candidate search: the largest pair's contact distance.
    reach: f64,
    /// The highest substrate sphere centre plus the largest slider drop (m): no pair's
    /// `h + drop` lies above it.
    top_base: f64,
    /// Principal rotational stiffnesses of the mount about the slider's own axes (N·m/rad).
    mount_k: [f64; 2],
    /// Numerical knobs.
    pub params: SolverParams,
    /// Candidate search used by [`Solver::pairs_at`].
    pub search: SearchKind,
}

impl Solver {
    /// Validates `scene`, indexes its substrate spheres (grid O(N), BVH O(N log N)) and
    /// generates the slider's sites (and, with per-site sizes, every sphere's radius).
    pub fn new(scene: &Scene) -> Result<Solver, SceneError> {
        scene.validate()?;
        let spheres = scene.substrate_spheres();
        let reach = scene.max_contact_distance();
        let local = scene.slider_sites_local();
        let sizes = Sizes::of(scene, local.len(), spheres.len());
        let drop_max = sizes.as_ref().map_or(0.0, |s| {
            s.slider
                .iter()
                .map(|r| r - s.r_sl)
                .fold(f64::NEG_INFINITY, f64::max)
        });
        let top_base = spheres
            .iter()
            .map(|q| q[2])
            .fold(f64::NEG_INFINITY, f64::max)
            + drop_max;
        Ok(Solver {
            sizes,
            reach,
            top_base,
            mount_k: scene.slider.mount.principal_tilt_stiffness(&local),
            scene: scene.clone(),
            hertz: scene.hertz(),
            grid: GridSearch::new(&spheres, reach),
            bvh: BvhSearch::new(&spheres, 0.5 * reach),
            substrate: spheres,
            local,
            params: SolverParams::default(),
            search: SearchKind::default(),
        })
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Substrate sphere centres `[x, y, h]` (m).
    pub fn substrate(&self) -> &[[f64; 3]] {
        &self.substrate
    }

    /// Number of slider spheres.
    pub fn slider_count(&self) -> usize {
        self.local.len()
    }

    /// The candidate search selected by [`Solver::search`].
    pub fn candidate_search(&self) -> &dyn CandidateSearch {
        match self.search {
            SearchKind::Grid => &self.grid,
            SearchKind::Bvh => &self.bvh,
        }
    }

    /// The richest model [`Model::Auto`] may use for this scene: rigid-z under a `locked` mount,
    /// rigid-tilt under `free`/`springs` (Auto escalates to it only at poses where the rigid-z
    /// answer leaves a moment; [`Equilibrium::model`] says which one a solve used).
    pub fn auto_model(&self) -> Model {
        if self.scene.slider.mount.tilts() {
            Model::RigidTilt
        } else {
            Model::RigidZ
        }
    }

    /// Checks that `model` can be used with the scene's mount: `rigid-tilt` under a `locked`
    /// mount is refused (it would have no tilt; rigid-z is the exact model there). The error
    /// names the field `model` and the scene's `slider.tilt`. Call before starting work.
    pub fn check_model(&self, model: Model) -> Result<(), SceneError> {
        if model == Model::RigidTilt && !self.scene.slider.mount.tilts() {
            return Err(SceneError::invalid(
                "model",
                "rigid-tilt",
                "the slider mount is locked (slider.tilt = \"locked\"): it has no tilt; use \
                 model rigid-z (the exact model for a locked mount) or auto, or a tilting mount \
                 (slider.tilt = \"free\" or \"springs\")",
            ));
        }
        Ok(())
    }

    /// Slider sphere centres `[x, y]` (m) and the disc centre at `pose`. O(N_slider).
    fn slider_xy_at(&self, pose: Pose) -> (Vec<[f64; 2]>, [f64; 2]) {
        let mut slider_xy = Vec::with_capacity(self.local.len());
        let centre = self.fill_slider_xy(pose, &mut slider_xy);
        (slider_xy, centre)
    }

    /// Replaces `out` with the slider sphere centres `[x, y]` (m) at `pose` ([`place`] of each
    /// site) and returns the disc centre. O(N_slider), no allocation once `out` has grown.
    fn fill_slider_xy(&self, pose: Pose, out: &mut Vec<[f64; 2]>) -> [f64; 2] {
        let centre = self.centre_at(pose);
        let sc = pose.theta.sin_cos();
        out.clear();
        out.extend(self.local.iter().map(|&p| place(centre, sc, p)));
        centre
    }

    /// The disc centre `[x, y]` (m) at `pose`: the scene's offset plus the pose's shift. O(1).
    #[inline]
    pub(crate) fn centre_at(&self, pose: Pose) -> [f64; 2] {
        [
            self.scene.slider.offset[0] + pose.shift[0],
            self.scene.slider.offset[1] + pose.shift[1],
        ]
    }

    /// Candidate pairs (lateral distance < 2R) of the slider at `pose`. O(N_slider) with the
    /// grid, O(N_slider log N_substrate) with the BVH. Load-independent: reuse for every load.
    pub fn pairs_at(&self, pose: Pose) -> PairSet {
        self.pairs_within(pose, 0.0)
    }

    /// Elastic energy Φ = 0.4 k δ^{5/2} (J) stored in contact `c` (k of its pair). O(1).
    pub fn contact_energy(&self, c: &ContactInfo) -> f64 {
        let k = match &self.sizes {
            None => self.hertz.k(),
            Some(s) => s.hertz(c.slider, c.substrate).k(),
        };
        0.4 * k * c.overlap * c.overlap * c.overlap.sqrt()
    }

    /// Candidate pairs of the slider at `pose` with lateral distance < 2R + `extra` (m): a
    /// superset of the pairs of every pose with the same θ whose shift lies within `extra` of
    /// `pose.shift`. Turn it into the pairs of such a pose with [`Solver::pairs_from`] (a path
    /// then searches once per segment instead of once per sample).
    pub fn pairs_within(&self, pose: Pose, extra: f64) -> PairSet {
        let (slider_xy, centre) = self.slider_xy_at(pose);
        let mut pairs = Vec::with_capacity(slider_xy.len() * 3);
        let extra = extra.max(0.0);
        self.candidate_search()
            .pairs(&slider_xy, self.reach + extra, &mut pairs);
        if let Some(s) = &self.sizes {
            // each pair's own reach r_i + r_j (+ extra)
            pairs.retain(|c| {
                let d = s.distance(c.slider, c.substrate) + extra;
                c.r2 < d * d
            });
        }
        PairSet {
            slider_xy,
            centre,
            theta: pose.theta,
            pairs,
        }
    }

    /// The pairs that come within contact distance (plus a round-off margin) of each other
    /// somewhere on the straight stretch of poses `pose.shift ± half` (m) at `pose.theta`: a
    /// superset of every such pose's pairs, for [`Solver::pairs_from`], from one grid scan of
    /// each sphere's swept capsule ([`GridSearch::pairs_swept`]). O(N_slider).
    ///
    /// Fills `out` (its buffers reused: no allocation once they have grown).
    ///
    /// `floor` (m, absolute; −∞: every pair): only the pairs whose touch height
    /// `h + drop + √(d² − r²)` can rise above it are needed, so the capsules shrink to the
    /// lateral distance `ρ = √(d² − (floor − h_max − drop_max)²)` below which any pair can
    /// (with a margin); a superset of the pairs a floor at or above `floor` keeps.
    pub(crate) fn pairs_swept_into(
        &self,
        pose: Pose,
        half: [f64; 2],
        floor: f64,
        out: &mut PairSet,
    ) {
        out.centre = self.fill_slider_xy(pose, &mut out.slider_xy);
        out.theta = pose.theta;
        out.pairs.clear();
        let slider_xy = &out.slider_xy;
        let pairs = &mut out.pairs;
        let margin = 1e-9 * self.reach + 1e-15;
        let rise = floor - self.top_base;
        let reach = if rise > 0.0 {
            ((self.reach * self.reach - rise * rise).max(0.0).sqrt() * (1.0 + 1e-8)).min(self.reach)
        } else {
            self.reach
        };
        self.grid
            .pairs_swept(slider_xy, half, reach + margin, pairs);
        if let Some(s) = &self.sizes {
            // each pair's own reach r_i + r_j, swept
            let h2 = half[0] * half[0] + half[1] * half[1];
            pairs.retain(|c| {
                let p = slider_xy[c.slider as usize];
                let q = self.substrate[c.substrate as usize];
                let v = [q[0] - p[0], q[1] - p[1]];
                let d = s.distance(c.slider, c.substrate) + margin;
                swept_distance2(v, half, h2) < d * d
            });
        }
    }

    /// The pairs of `pose` (lateral distance < 2R) taken from `near`, a [`Solver::pairs_within`]
    /// set of the same θ built with `extra` ≥ the distance between the two shifts: identical to
    /// [`Solver::pairs_at`]`(pose)` (same order, same r² arithmetic), without a candidate search.
    /// O(pairs of `near`).
    pub fn pairs_from(&self, near: &PairSet, pose: Pose) -> PairSet {
        let (slider_xy, centre) = self.slider_xy_at(pose);
        let reach = self.reach;
        let r2max = reach * reach;
        let pairs = near
            .pairs
            .iter()
            .filter_map(|c| {
                let p = slider_xy[c.slider as usize];
                let q = self.substrate[c.substrate as usize];
                let dx = q[0] - p[0];
                let dy = q[1] - p[1];
                let r2 = dx * dx + dy * dy;
                let max = match &self.sizes {
                    None => r2max,
                    Some(s) => s.distance(c.slider, c.substrate).powi(2),
                };
                (r2 < max).then_some(CandidatePair { r2, ..*c })
            })
            .collect();
        PairSet {
            slider_xy,
            centre,
            theta: pose.theta,
            pairs,
        }
    }

    /// The mount's rotational stiffness tensor K_t (N·m/rad, lab frame) at rotation `theta`
    /// (rad); equals [`Scene::tilt_stiffness_at`] (cached principal values, O(1)).
    pub fn tilt_stiffness_at(&self, theta: f64) -> [[f64; 2]; 2] {
        rotate_tilt_stiffness(self.mount_k, theta)
    }

    fn ctx(&self, theta: f64) -> Ctx<'_> {
        Ctx {
            hertz: &self.hertz,
            two_r: self.reach,
            sizes: self.sizes.as_ref(),
            coating: &self.scene.coating,
            substrate: &self.substrate,
            params: &self.params,
            scale: self
                .scene
                .slider
                .radius
                .max(self.scene.max_slider_sphere_radius()),
            tilts: self.scene.slider.mount.tilts(),
            kt: self.tilt_stiffness_at(theta),
            watch: None,
        }
    }

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
}

impl Solver {
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

    /// A bound on `|arm|/L` of every slider sphere at any pose (its distance from the disc
    /// centre over the tilt scale L, plus a round-off margin). O(N_slider).
    pub(crate) fn lever_bound(&self) -> f64 {
        let r2 = self
            .local
            .iter()
            .map(|p| p[0] * p[0] + p[1] * p[1])
            .fold(0.0, f64::max);
        r2.sqrt() / self.ctx(0.0).scale * (1.0 + 1e-9)
    }

    /// Slider sphere `i`'s position `[x, y]` (m) in the slider's own frame (θ = 0, centred).
    #[inline]
    pub(crate) fn slider_local(&self, i: u32) -> [f64; 2] {
        self.local[i as usize]
    }

    /// The contact distance² (m²) of slider sphere `i` and substrate sphere `j`: the test
    /// [`Solver::pairs_from`] applies. O(1).
    #[inline]
    pub(crate) fn pair_reach2(&self, i: u32, j: u32) -> f64 {
        match &self.sizes {
            None => self.reach * self.reach,
            Some(s) => s.distance(i, j).powi(2),
        }
    }

    /// The drop (m) of slider sphere `i` below the slider's reference plane (`r_i − R_sl` with
    /// per-site sizes, else 0): its pair's touch height is `h + drop + √(d² − r²)`.
    #[inline]
    pub(crate) fn slider_drop(&self, i: u32) -> f64 {
        match &self.sizes {
            None => 0.0,
            Some(s) => s.slider[i as usize] - s.r_sl,
        }
    }

    /// The largest contact distance (m) of any pair: the candidate search's reach.
    #[inline]
    pub(crate) fn touch_reach(&self) -> f64 {
        self.reach
    }

    /// A bound (m, absolute) above every pair's touch height `h + drop + √(d² − r²)`: the
    /// highest substrate centre plus the largest slider drop plus the largest contact distance.
    #[inline]
    pub(crate) fn touch_ceiling(&self) -> f64 {
        self.top_base + self.reach
    }

    /// The Hertz law of the scene (its `overlap_for_force` sets the z root's first bracket).
    pub(crate) fn hertz(&self) -> &Hertz {
        &self.hertz
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
            let eq = solve_one_of_many(ctx, ps, &rz, w, model);
            let ok = eq.is_ok() && watch.lowest.get() > floor_rel;
            *warm = if ok {
                Warm {
                    z0: rz.zref + watch.root.get(),
                    depth: -watch.root.get(),
                    need: rz.zref + watch.lowest.get(),
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
}

impl Default for Warm {
    fn default() -> Self {
        Warm {
            z0: f64::NAN,
            depth: f64::NAN,
            need: f64::NAN,
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
    {
        {
            match model {
                Model::Auto => solve_auto(ctx, ps, rz, w),
                Model::RigidZ => rz.solve(ctx, ps, w),
                _ => {
                    let (z0, it0) = rz.zr.solve(ctx, w)?;
                    let near = NearSet::new(ctx, &rz.bp, z0, ctx.lever_bound(ps));
                    let (q, it1) = tilt_from(ctx, &rz.bp, &near, w, z0)?;
                    Ok(assemble_tilt(ctx, ps, &rz.bp, rz.zref, w, q, it0 + it1))
                }
            }
        }
    }
}

fn check_load(load: f64) -> Result<(), SceneError> {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_sync<T: Sync>() {}

    #[test]
    fn solver_is_sync() {
        assert_sync::<Solver>();
    }

    #[test]
    fn tri_tri_reference() {
        let s = Scene::preset("tri-tri").unwrap();
        let solver = Solver::new(&s).unwrap();
        let eq = solver.solve(Pose::default(), 3.86e-3, Model::Auto).unwrap();
        assert_eq!(eq.contact_count(), 3505);
        assert!((eq.p_max / 1e9 - 1.05).abs() < 0.02 * 1.05, "{}", eq.p_max);
        let fz: f64 = eq.contacts.iter().map(|c| c.force_z).sum();
        assert!((fz - 3.86e-3).abs() < 1e-9 * 3.86e-3);
    }
}
