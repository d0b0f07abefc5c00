//! [`ContactArgs`]: the contact law's flags (`--tangential`, `--mu`), the CLI's side of
//! [`dem::ContactParams`] and of the friction law.

use super::checks;
use anyhow::Result;
use dem::model::{Constant, Friction};
use dem::ContactParams;

/// The tangential history of the contacts' Mindlin spring (`--tangential`).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum TangentialArg {
    /// History = elastic displacement: a stuck contact's force follows its contact radius when
    /// the load changes (LAMMPS `mindlin`).
    Mindlin,
    /// History = elastic force (incremental stiffness): a stuck contact keeps its force when its
    /// load changes (LAMMPS `mindlin_force`).
    MindlinForce,
    /// History = elastic displacement, scaled down with the contact radius on unloading: a
    /// stuck contact sheds force as a² (LAMMPS `mindlin_rescale`).
    MindlinRescale,
}

impl TangentialArg {
    /// The engine's sub-model.
    pub fn engine(self) -> dem::Tangential {
        match self {
            TangentialArg::Mindlin => dem::Tangential::Mindlin,
            TangentialArg::MindlinForce => dem::Tangential::MindlinForce,
            TangentialArg::MindlinRescale => dem::Tangential::MindlinRescale,
        }
    }
}

/// The contact flags of `equilibrate` and `slide`.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct ContactArgs {
    /// Tangential history of the contacts' Mindlin spring: `mindlin` stores the elastic
    /// displacement (its force jumps with the contact radius when a stuck contact's load
    /// changes), `mindlin-force` stores the elastic force (incremental stiffness, kept until
    /// the contact slips), `mindlin-rescale` scales the displacement down with the contact
    /// radius on unloading; LAMMPS `pair granular` conventions. Measured in
    /// docs/validation/dem-integrator.md.
    #[arg(long, value_enum, default_value_t = TangentialArg::Mindlin)]
    pub tangential: TangentialArg,
    /// Constant friction coefficient (≥ 0) for every contact instead of the coating's
    /// pressure-switched μ1/μ2 (reference runs).
    #[arg(long, value_name = "MU", allow_hyphen_values = true)]
    pub mu: Option<f64>,
}

impl ContactArgs {
    /// The contact part of the run's params: the study's damping, `--tangential`'s history.
    pub fn params(&self) -> ContactParams {
        ContactParams {
            tangential: self.tangential.engine(),
            ..ContactParams::default()
        }
    }

    /// `--mu` as a constant friction law (checked ≥ 0, naming the flag); `None`: the coating's.
    pub fn friction(&self) -> Result<Option<Friction>> {
        Ok(self
            .mu
            .map(|mu| checks::non_negative(mu, "--mu"))
            .transpose()?
            .map(|mu| Friction::Constant(Constant { mu })))
    }
}
