//! [`Solver`]: a scene prepared for many quasi-static solves (different θ, shifts and loads).
//! Its candidate-pair searches are in `search.rs`, its solves in `solve.rs`.

use super::ctx::{Ctx, Sizes};
use super::{Model, SolverParams};
use crate::contact::{BvhSearch, CandidateSearch, GridSearch, Hertz};
use crate::error::SceneError;
use crate::scene::{rotate_tilt_stiffness, Scene};
use crate::solver::ContactInfo;
use std::sync::OnceLock;

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

/// A scene prepared for repeated solves: substrate spheres indexed once in a grid (and in a
/// parry3d BVH on the first [`SearchKind::Bvh`] search), slider sites generated once, Hertz law
/// cached. `Sync`: share one `Solver` across rayon threads.
pub struct Solver {
    pub(super) scene: Scene,
    hertz: Hertz,
    pub(super) substrate: Vec<[f64; 3]>,
    pub(super) grid: GridSearch,
    /// The parry3d BVH over the substrate spheres, built on first use by
    /// [`Solver::candidate_search`] with [`SearchKind::Bvh`] (O(N log N) once; the grid path
    /// never pays for it).
    bvh: OnceLock<BvhSearch>,
    pub(super) local: Vec<[f64; 2]>,
    /// Per-sphere radii when the scene has per-site sizes (`None`: one size per body, the fast
    /// path: one Hertz law and one contact distance for every pair).
    pub(super) sizes: Option<Sizes>,
    /// Lateral reach (m) of the candidate search: the largest pair's contact distance.
    pub(super) reach: f64,
    /// The highest substrate sphere centre plus the largest slider drop (m): no pair's
    /// `h + drop` lies above it.
    pub(super) top_base: f64,
    /// Principal rotational stiffnesses of the mount about the slider's own axes (N·m/rad).
    mount_k: [f64; 2],
    /// Numerical knobs.
    pub params: SolverParams,
    /// Candidate search used by [`Solver::pairs_at`].
    pub search: SearchKind,
    /// A number no other `Solver` of this process has: names its searches kept for reuse
    /// (`path_pairs.rs`).
    pub(super) id: u64,
}

/// The next [`Solver::id`].
static NEXT_ID: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

impl Solver {
    /// Validates `scene`, indexes its substrate spheres in a grid (O(N); the BVH is built only
    /// when first searched, see [`Solver::candidate_search`]) and generates the slider's sites
    /// (and, with per-site sizes, every sphere's radius).
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
            bvh: OnceLock::new(),
            substrate: spheres,
            local,
            params: SolverParams::default(),
            search: SearchKind::default(),
            id: NEXT_ID.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
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

    /// The candidate search selected by [`Solver::search`]. O(1), except the first call with
    /// [`SearchKind::Bvh`], which builds the BVH over the substrate spheres (leaf radius half
    /// the reach; O(N log N), thread-safe: one build however many threads ask).
    pub fn candidate_search(&self) -> &dyn CandidateSearch {
        match self.search {
            SearchKind::Grid => &self.grid,
            SearchKind::Bvh => self
                .bvh
                .get_or_init(|| BvhSearch::new(&self.substrate, 0.5 * self.reach)),
        }
    }

    /// The richest model [`Model::Auto`] may use for this scene: rigid-z under a `locked` mount,
    /// rigid-tilt under `free`/`springs` (Auto escalates to it only at poses where the rigid-z
    /// answer leaves a moment; [`Equilibrium::model`](super::Equilibrium::model) says which one
    /// a solve used).
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

    /// Elastic energy Φ = 0.4 k δ^{5/2} (J) stored in contact `c` (k of its pair). O(1).
    pub fn contact_energy(&self, c: &ContactInfo) -> f64 {
        let k = match &self.sizes {
            None => self.hertz.k(),
            Some(s) => s.hertz(c.slider, c.substrate).k(),
        };
        0.4 * k * c.overlap * c.overlap * c.overlap.sqrt()
    }

    /// The mount's rotational stiffness tensor K_t (N·m/rad, lab frame) at rotation `theta`
    /// (rad); equals [`Scene::tilt_stiffness_at`] (cached principal values, O(1)).
    pub fn tilt_stiffness_at(&self, theta: f64) -> [[f64; 2]; 2] {
        rotate_tilt_stiffness(self.mount_k, theta)
    }

    pub(super) fn ctx(&self, theta: f64) -> Ctx<'_> {
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
}

impl Solver {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_sync<T: Sync>() {}
    fn assert_send<T: Send>() {}

    #[test]
    fn solver_is_sync() {
        assert_sync::<Solver>();
        assert_send::<Solver>();
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
