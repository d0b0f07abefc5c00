//! [`Nominal`]: the surrogate's quasi-static equilibrium of a run's scene at its load, solved
//! once per run and shared by the model choice ([`crate::choose_model_at`]) and the start state
//! ([`crate::prepare_at`]).

use crate::DemError;
use surrogate::solver::{Equilibrium, Model, Pose, Solver};
use surrogate::Scene;

/// The scene's solver and its equilibrium at the slider's own θ, no shift, load W (N),
/// `Model::Auto`: the reference pressure of the model choice and the start height of the DEM.
pub struct Nominal {
    /// The surrogate solver of the scene (the model choice also solves its path with it).
    pub solver: Solver,
    /// The equilibrium at the start pose.
    pub eq: Equilibrium,
}

impl Nominal {
    /// Builds the solver of `scene` and solves it at `load` (N). Cost: one contact search and
    /// one surrogate solve (milliseconds).
    pub fn solve(scene: &Scene, load: f64) -> Result<Nominal, DemError> {
        let solver = Solver::new(scene)?;
        let eq = solver.solve(
            Pose {
                theta: scene.slider.theta,
                shift: [0.0, 0.0],
            },
            load,
            Model::Auto,
        )?;
        Ok(Nominal { solver, eq })
    }
}
