//! One configuration in detail: the equilibrium at (θ, W) with its per-contact list (the data
//! behind contact maps and `--contacts-out`).

use surrogate::solver::{Equilibrium, Model, Pose, SearchKind, Solver};
use surrogate::Scene;

/// Parameters of one configuration (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactsParams {
    /// Slider orientation θ (rad).
    pub theta: f64,
    /// Normal load W (N).
    pub load: f64,
    /// Load-sharing model.
    pub model: Model,
    /// Candidate pair search.
    pub search: SearchKind,
}

/// The equilibrium of `scene` at θ, W (slider at its default placement), contacts included
/// (convert with [`super::rows::ContactRow::all`]).
pub fn contacts(scene: &Scene, p: &ContactsParams) -> anyhow::Result<Equilibrium> {
    let mut solver = Solver::new(scene)?;
    solver.search = p.search;
    let pose = Pose {
        theta: p.theta,
        shift: [0.0, 0.0],
    };
    Ok(solver.solve(pose, p.load, p.model)?)
}
