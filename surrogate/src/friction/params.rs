//! [`FrictionParams`]: every knob of the surrogate friction estimate.

use crate::error::SceneError;
use serde::{Deserialize, Serialize};

/// Knobs of [`super::estimate_friction`] (SI). Defaults: the study's stiffnesses and a path that
/// resolves the 3 µm-lattice landscape (see the module documentation for the error of these
/// choices against finer and longer paths).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FrictionParams {
    /// Path length (m) along a pulling direction that is not a substrate lattice direction
    /// (quasi-periodic landscape). Default 12 µm: four spacings of the study's 3 µm lattice.
    pub length: f64,
    /// Longest substrate lattice period (m) along the pulling direction that is used as a
    /// periodic path (one period, exactly); longer periods use `length` instead. Default 12 µm.
    pub max_period: f64,
    /// Largest sample spacing along the path (m). Default 0.05 µm (60 samples per 3 µm).
    pub step: f64,
    /// Length (m) of the start of a quasi-periodic path that the Prandtl–Tomlinson term skips
    /// (the spring loading up from rest). Default 3 µm (one lattice spacing).
    pub transient: f64,
    /// Pulling spring K0 (N/m). Study: 50.
    pub k0: f64,
    /// Lateral tie stiffness of each slider sphere to the control layer (N/m). Study: 1e3.
    pub k_slider_xy: f64,
    /// Lateral tether stiffness of each substrate sphere (N/m). Study: 1e3.
    pub k_substrate_xy: f64,
    /// Angle (rad) within which the pulling direction counts as a substrate lattice direction.
    /// Default 1e-6 (a path of 12 µm then ends within 12 pm of the lattice line).
    pub direction_tol: f64,
    /// Length (m) of path that shares one candidate-pair search (a speed knob; results are
    /// identical for any value > 0). Default 0.5 µm.
    pub segment: f64,
}

impl Default for FrictionParams {
    fn default() -> Self {
        FrictionParams {
            length: 12e-6,
            max_period: 12e-6,
            step: 0.05e-6,
            transient: 3e-6,
            k0: 50.0,
            k_slider_xy: 1e3,
            k_substrate_xy: 1e3,
            direction_tol: 1e-6,
            segment: 0.5e-6,
        }
    }
}

impl FrictionParams {
    /// Checks every knob; errors name the field in user units.
    pub fn validate(&self) -> Result<(), SceneError> {
        let pos_um = |field: &str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(SceneError::invalid(
                    field,
                    v * 1e6,
                    "must be a positive length in µm",
                ))
            }
        };
        pos_um("friction.length_um", self.length)?;
        pos_um("friction.max_period_um", self.max_period)?;
        pos_um("friction.step_um", self.step)?;
        pos_um("friction.segment_um", self.segment)?;
        if self.step > self.length.min(self.max_period) {
            return Err(SceneError::invalid(
                "friction.step_um",
                self.step * 1e6,
                "must not exceed the path length or the longest period",
            ));
        }
        if !(self.transient.is_finite() && self.transient >= 0.0 && self.transient < self.length) {
            return Err(SceneError::invalid(
                "friction.transient_um",
                self.transient * 1e6,
                "must be ≥ 0 and shorter than the path length",
            ));
        }
        for (f, v) in [
            ("friction.k0_N_m", self.k0),
            ("friction.k_slider_xy_N_m", self.k_slider_xy),
            ("friction.k_substrate_xy_N_m", self.k_substrate_xy),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(SceneError::invalid(
                    f,
                    v,
                    "must be a positive stiffness in N/m",
                ));
            }
        }
        if !(self.direction_tol.is_finite() && self.direction_tol >= 0.0) {
            return Err(SceneError::invalid(
                "friction.direction_tol",
                self.direction_tol,
                "must be a non-negative angle in rad",
            ));
        }
        Ok(())
    }
}
