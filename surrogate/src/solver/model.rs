//! Which load-sharing model a solve uses.

use crate::error::SceneError;
use serde::{Deserialize, Serialize};

/// Load-sharing model, from cheapest to richest.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Model {
    /// Pick the cheapest model that is exact for the scene (rigid-z for a flat perfect scene).
    Auto,
    /// Rigid slider, height z only (exact for flat, unperturbed scenes: 1-D root find).
    RigidZ,
    /// Rigid slider with height and two tilts (needed with height perturbations).
    RigidTilt,
    /// Rigid slider body plus per-sphere compliance of the slider springs and substrate tethers.
    Compliant,
}

impl Model {
    /// Parses `auto | rigid-z | rigid-tilt | compliant`; errors name the field `model`.
    pub fn parse(s: &str) -> Result<Model, SceneError> {
        Ok(match s {
            "auto" => Model::Auto,
            "rigid-z" => Model::RigidZ,
            "rigid-tilt" => Model::RigidTilt,
            "compliant" => Model::Compliant,
            _ => {
                return Err(SceneError::Unknown {
                    field: "model".into(),
                    what: "model".into(),
                    name: s.into(),
                    expected: "auto, rigid-z, rigid-tilt, compliant".into(),
                })
            }
        })
    }
    /// The kebab-case name.
    pub fn name(&self) -> &'static str {
        match self {
            Model::Auto => "auto",
            Model::RigidZ => "rigid-z",
            Model::RigidTilt => "rigid-tilt",
            Model::Compliant => "compliant",
        }
    }
}
