//! [`Solver`]: a scene prepared for many quasi-static solves (different θ, shifts and loads).

use super::{solve_rigid_z, Equilibrium, Model, SolverParams};
use crate::contact::{CandidateSearch, GridSearch, Hertz};
use crate::error::SceneError;
use crate::scene::Scene;

/// Lateral pose of the slider: rotation θ (rad) and in-plane shift (m) of its centre from the
/// scene's offset.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    /// Rotation θ of the slider lattice (rad).
    pub theta: f64,
    /// In-plane shift `[dx, dy]` (m) added to the scene's slider offset.
    pub shift: [f64; 2],
}

/// A scene prepared for repeated solves: substrate spheres indexed once, Hertz law cached.
/// `Sync`: share one `Solver` across rayon threads.
pub struct Solver {
    scene: Scene,
    hertz: Hertz,
    search: GridSearch,
    /// Numerical knobs.
    pub params: SolverParams,
}

impl Solver {
    /// Validates `scene` and indexes its substrate spheres. Cost O(N_substrate).
    pub fn new(scene: &Scene) -> Result<Solver, SceneError> {
        scene.validate()?;
        let spheres = scene.substrate_spheres();
        let reach = 2.0 * scene.sphere_radius;
        Ok(Solver {
            scene: scene.clone(),
            hertz: scene.hertz(),
            search: GridSearch::new(&spheres, reach),
            params: SolverParams::default(),
        })
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Substrate sphere centres `[x, y, h]` (m).
    pub fn substrate(&self) -> &[[f64; 3]] {
        self.search.spheres()
    }

    /// The model `Auto` resolves to for this scene: rigid-z when the substrate is flat
    /// (σ_h = 0), rigid-tilt otherwise.
    pub fn auto_model(&self) -> Model {
        if self.scene.substrate.sigma_h == 0.0 {
            Model::RigidZ
        } else {
            Model::RigidTilt
        }
    }

    /// Equilibrium of the slider at `pose` under `load` W (N) with `model`.
    /// Errors: non-positive/NaN load (field `load_mN`), no substrate under the slider.
    pub fn solve(&self, pose: Pose, load: f64, model: Model) -> Result<Equilibrium, SceneError> {
        if !(load.is_finite() && load > 0.0) {
            return Err(SceneError::invalid(
                "load_mN",
                load * 1e3,
                "must be a positive number",
            ));
        }
        let xy = self.scene.slider_sites_at(pose.theta, pose.shift);
        let reach = 2.0 * self.scene.sphere_radius;
        let mut pairs = Vec::new();
        self.search.pairs(&xy, reach, &mut pairs);
        let model = if model == Model::Auto {
            self.auto_model()
        } else {
            model
        };
        match model {
            Model::RigidZ | Model::Auto => solve_rigid_z(
                &xy,
                &pairs,
                reach,
                &self.hertz,
                &self.scene.coating,
                load,
                &self.params,
            ),
            other => Err(SceneError::invalid(
                "model",
                other.name(),
                "not implemented yet",
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
