//! [`FrictionParams`]: every knob of the surrogate friction estimate.

use crate::error::SceneError;
use crate::units::{m_to_um, s_to_us};
use serde::{Deserialize, Serialize};

/// Knobs of [`super::estimate_friction`] (SI). Defaults: the study's stiffnesses and a path that
/// resolves the 3 µm-lattice landscape (see the module documentation for the error of these
/// choices against finer and longer paths). Each field names the section of
/// `docs/validation/friction.md` that measured it or says where its value comes from: the
/// path's knobs were measured ("Measured", "Error of the defaults"); the DEM's knobs are the
/// study protocol's, not fitted ("The estimate", "Inertial model").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FrictionParams {
    /// Path length (m) along a pulling direction that is not a substrate lattice direction
    /// (quasi-periodic landscape). Default 12 µm: four spacings of the study's 3 µm lattice.
    /// Measured: 12 → 24 / 36 µm moves μ_qs by ≤ 0.9 % (validation/friction.md, "Measured",
    /// "Error of the defaults"); the DEM's 30 µm is a check, not a default ("The drift across
    /// the pull").
    pub length: f64,
    /// Longest substrate lattice period (m) along the pulling direction that is used as a
    /// periodic path (one period, exactly); longer periods use `length` instead. Default 12 µm
    /// (validation/friction.md, "The estimate", "Path").
    pub max_period: f64,
    /// Largest sample spacing along the path (m). Default 0.05 µm (60 samples per 3 µm).
    /// Measured: 0.05 → 0.0125 µm moves μ_qs by ≤ 5.7 % (validation/friction.md, "Measured",
    /// "Error of the defaults").
    pub step: f64,
    /// Length (m) of the start of a quasi-periodic path that the Prandtl–Tomlinson term skips
    /// (the spring loading up from rest). Default 3 µm (one lattice spacing)
    /// (validation/friction.md, "The estimate", "Path").
    pub transient: f64,
    /// Pulling spring K0 (N/m). Study: 50, the DEM's (validation/friction.md, "The estimate",
    /// "Corrugation term").
    pub k0: f64,
    /// Lateral tie stiffness of each slider sphere to the control layer (N/m). Study: 1e3, the
    /// DEM's (validation/friction.md, "The estimate", "Corrugation term").
    pub k_slider_xy: f64,
    /// Lateral tether stiffness of each substrate sphere (N/m). Study: 1e3, the DEM's
    /// (validation/friction.md, "The estimate", "Corrugation term").
    pub k_substrate_xy: f64,
    /// Angle (rad) within which the pulling direction counts as a substrate lattice direction.
    /// Default 1e-6 (a path of 12 µm then ends within 12 pm of the lattice line): a geometric
    /// tolerance, not measured (validation/friction.md, "The estimate", "Path").
    pub direction_tol: f64,
    /// Length (m) of path sharing one refresh of the pair list; twelve of them share one
    /// candidate-pair search and one thread (a speed knob: results agree to the solver's
    /// tolerance for any value > 0, and are identical for one value whatever the thread count).
    /// Default 0.5 µm (validation/path-solve.md; validation/friction.md, "The estimate", "Path").
    pub segment: f64,
    /// Support speed (m/s) of the inertial model (`friction/inertial.rs`), as in the DEM. Study:
    /// 0.1 (validation/friction.md, "The estimate", "Inertial model": not fitted).
    pub speed: f64,
    /// Sliding time (s) of the inertial model, as in the DEM protocol. Study: 300 µs
    /// (validation/friction.md, "The estimate", "Inertial model").
    pub slide_time: f64,
    /// Start (s) of the inertial model's measuring window, as in the DEM protocol (friction over
    /// the last 2/3 of the slide). Study: 100 µs (validation/friction.md, "The estimate",
    /// "Inertial model").
    pub window_start: f64,
    /// Damping time τ (s) of the DEM (control layer relative to the support). Study: 1 µs
    /// (validation/friction.md, "The estimate", "Inertial model": γ = m_control/τ).
    pub tau: f64,
    /// Radius (m) of the DEM's control-layer spheres (one per slider sphere; their mass adds to
    /// the slider's). Study: 0.5 µm (validation/friction.md, "The estimate", "Inertial model":
    /// the mass M).
    pub control_sphere_radius: f64,
    /// Half-width (m) of the search across the pull (`friction/transverse.rs`): where the slider
    /// drifts off the placement's crest while it slides, the path starts at the lowest
    /// `V + ½K0 y²` on that side within `transverse` of the placement. Default 1.5 µm (half the
    /// study's 3 µm spacing); 0 keeps the path through the placement. Measured against the DEM
    /// in validation/friction.md, "The drift across the pull" (the groove rule).
    pub transverse: f64,
    /// Runs of the inertial model averaged into μ_est, started evenly along the path (its
    /// stick-slip is chaotic: one run scatters by ±20–30 %). Default 8 (validation/friction.md,
    /// "The estimate", "Inertial model"; the spread against the DEM in "Against the DEM: 17
    /// configurations").
    pub starts: usize,
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
            speed: 0.1,
            slide_time: 300e-6,
            window_start: 100e-6,
            tau: 1e-6,
            control_sphere_radius: 0.5e-6,
            transverse: 1.5e-6,
            starts: 8,
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
                    m_to_um(v),
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
                m_to_um(self.step),
                "must not exceed the path length or the longest period",
            ));
        }
        if !(self.transient.is_finite() && self.transient >= 0.0 && self.transient < self.length) {
            return Err(SceneError::invalid(
                "friction.transient_um",
                m_to_um(self.transient),
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
        if !(self.speed.is_finite() && self.speed > 0.0) {
            return Err(SceneError::invalid(
                "friction.speed_m_s",
                self.speed,
                "must be a positive speed in m/s",
            ));
        }
        for (f, v) in [
            ("friction.slide_us", self.slide_time),
            ("friction.tau_us", self.tau),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(SceneError::invalid(
                    f,
                    s_to_us(v),
                    "must be a positive time in µs",
                ));
            }
        }
        if !(self.window_start.is_finite()
            && self.window_start >= 0.0
            && self.window_start < self.slide_time)
        {
            return Err(SceneError::invalid(
                "friction.window_start_us",
                s_to_us(self.window_start),
                "must be ≥ 0 and shorter than the sliding time",
            ));
        }
        pos_um(
            "friction.control_sphere_radius_um",
            self.control_sphere_radius,
        )?;
        if !(self.transverse.is_finite() && self.transverse >= 0.0) {
            return Err(SceneError::invalid(
                "friction.transverse_um",
                m_to_um(self.transverse),
                "must be a non-negative length in µm (0: the path runs through the placement)",
            ));
        }
        if self.starts == 0 {
            return Err(SceneError::invalid(
                "friction.starts",
                0.0,
                "must be at least 1 run of the inertial model",
            ));
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
