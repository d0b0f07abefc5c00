//! [`ContactParams`]: the contact law's own knobs — normal and tangential damping and the
//! Mindlin spring's history (the law itself, Hertz + Mindlin + the coating's μ, comes from the
//! scene; `crate::model` composes it).

use serde::{Deserialize, Serialize};

/// Contact damping and tangential history (dimensionless). Composed with the scene's materials
/// into a [`crate::model::ContactModel`] by [`crate::contact_model`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ContactParams {
    /// Dimensionless normal damping γ_n: `F_d = −γ_n √(m_eff S_n) v_n`, `S_n = 2E*√(R_eff δ)`.
    /// Coefficient of restitution `e ≈ 1 − 1.7207 γ_n` for small γ_n (velocity independent).
    pub gamma_n: f64,
    /// Dimensionless tangential damping γ_t: `F_td = −γ_t √(m_eff k_t) v_t`.
    pub gamma_t: f64,
    /// Tangential history of the Mindlin spring. (Left out of the serialized form at its
    /// default, so checkpoints and stored runs made before it existed still match.)
    #[serde(default, skip_serializing_if = "Tangential::is_default")]
    pub tangential: Tangential,
}

impl Default for ContactParams {
    fn default() -> Self {
        ContactParams {
            gamma_n: 0.1,
            gamma_t: 0.1,
            tangential: Tangential::Mindlin,
        }
    }
}

/// The tangential history of the Mindlin spring (LAMMPS `pair granular` `tangential` names).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Tangential {
    /// History = elastic displacement ξ, force `−k_t(a)·ξ` at the current contact radius: a
    /// stuck contact's force follows a when its load changes (LAMMPS `mindlin`; default).
    #[default]
    Mindlin,
    /// History = elastic force, incremented by `−k_t(a)·v_t·dt`: a stuck contact keeps its force
    /// when its load changes (LAMMPS `mindlin_force`, `crate::model::MindlinForce`).
    MindlinForce,
    /// History = elastic displacement, scaled by a/a_prev when the contact radius falls: a
    /// stuck contact sheds force ∝ a² on unloading (LAMMPS `mindlin_rescale`,
    /// `crate::model::MindlinRescale`).
    MindlinRescale,
}

impl Tangential {
    /// Whether this is the default ([`Tangential::Mindlin`]).
    pub fn is_default(&self) -> bool {
        *self == Tangential::Mindlin
    }

    /// The kebab-case name (`mindlin`, `mindlin-force`, `mindlin-rescale`).
    pub fn name(self) -> &'static str {
        match self {
            Tangential::Mindlin => "mindlin",
            Tangential::MindlinForce => "mindlin-force",
            Tangential::MindlinRescale => "mindlin-rescale",
        }
    }
}
