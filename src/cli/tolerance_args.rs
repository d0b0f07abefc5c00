//! The fabrication-tolerance flags shared by `design` and `tolerance`.

use super::checks;
use anyhow::Result;

/// `--theta-tol-deg` and `--direction-tol-deg` (degrees, ≥ 0; the old names `--theta-tol`,
/// `--direction-tol` are hidden aliases).
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct ToleranceArgs {
    /// Fabrication tolerance of the slider orientation θ in degrees (±): `design` ranks by the
    /// lowest superlubric limit over it, `tolerance` draws it as the box. A misaligned slider
    /// keeps the nominal pulling direction in the substrate frame (the tribometer's axis does
    /// not turn with the slider). 0 and --direction-tol-deg 0: the nominal answer.
    #[arg(
        long = "theta-tol-deg",
        alias = "theta-tol",
        value_name = "DEG",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    pub theta_tol: f64,
    /// Tolerance of the pulling direction in the substrate frame, in degrees (±).
    #[arg(
        long = "direction-tol-deg",
        alias = "direction-tol",
        value_name = "DEG",
        default_value_t = 0.5,
        allow_hyphen_values = true
    )]
    pub direction_tol: f64,
}

impl ToleranceArgs {
    /// (θ, direction) tolerances in degrees, checked: finite, ≥ 0, direction < 90°.
    pub fn checked(&self) -> Result<(f64, f64)> {
        let t = checks::non_negative(self.theta_tol, "--theta-tol-deg")?;
        let d = checks::non_negative(self.direction_tol, "--direction-tol-deg")?;
        if d >= 90.0 {
            anyhow::bail!("`--direction-tol-deg`: ±{d}° is not a tolerance; give less than 90°");
        }
        Ok((t, d))
    }
}
