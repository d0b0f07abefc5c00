//! The row of a corrugation scan: [`CorrugationRow`].

use super::format::{clean, label};
use serde::{Deserialize, Serialize};
use surrogate::units::{m_to_nm, n_to_mn, rad_to_deg};

/// Corrugation felt along one pulling direction α.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CorrugationRow {
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Normal load W (mN).
    #[serde(rename = "load_mN")]
    pub load_mn: f64,
    /// Contact-line angle from the substrate x axis (degrees) that α is measured from.
    pub line_deg: f64,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Path direction from the substrate x axis = line + α (degrees).
    pub direction_deg: f64,
    /// Peak-to-peak slider height along the path (nm).
    pub corrugation_nm: f64,
    /// Largest quasi-static pulling force along the path: the static-friction barrier (mN).
    #[serde(rename = "max_lateral_force_mN")]
    pub max_lateral_force_mn: f64,
}

impl CorrugationRow {
    /// The row of a corrugation point at θ (rad), W (N), contact line `line` (rad).
    pub fn new(
        theta: f64,
        load: f64,
        line: f64,
        p: &surrogate::map::CorrugationPoint,
    ) -> CorrugationRow {
        CorrugationRow {
            theta_deg: label(rad_to_deg(theta)),
            load_mn: label(n_to_mn(load)),
            line_deg: rad_to_deg(line),
            alpha_deg: clean(rad_to_deg(p.alpha)),
            direction_deg: clean(rad_to_deg(p.direction)),
            corrugation_nm: m_to_nm(p.corrugation),
            max_lateral_force_mn: n_to_mn(p.max_lateral_force),
        }
    }
}
