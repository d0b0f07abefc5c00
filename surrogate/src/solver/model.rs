//! Which load-sharing model a solve uses.

use crate::error::SceneError;
use serde::{Deserialize, Serialize};

/// Load-sharing model, from cheapest to richest.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Model {
    /// The cheapest rigid model that is exact for the scene's mount *and* pose: rigid-z under a
    /// `locked` mount; under `free`/`springs`, rigid-z when its contact moment is within the tilt
    /// solver's tolerance (`moment_rtol`·W·L: symmetric poses on flat substrates), else rigid-tilt
    /// warm-started from the rigid-z state. [`super::Equilibrium::model`] reports which.
    Auto,
    /// Rigid slider, height z only (1-D root find): exact under a `locked` mount, and under a
    /// tilting mount wherever the contact moments vanish (inversion-symmetric poses).
    RigidZ,
    /// Rigid slider with height and the two tilts of its mount: moment balance `M_c = K_t·t`
    /// (`K_t` = 0 for `free`, the K1 springs' rotational stiffness for `springs`). Refused under
    /// a `locked` mount (error naming `model` and `slider.tilt`): there it has no tilt and
    /// rigid-z is the model.
    RigidTilt,
    /// Rigid slider body (height, and the tilts of its mount) plus per-sphere vertical
    /// compliance k_z of the slider springs. Under a `locked` mount the tilts stay 0.
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
