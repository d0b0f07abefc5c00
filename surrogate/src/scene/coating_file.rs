//! [`CoatingFile`]: the `[coating]` table of a scene file, in user units.

use serde::{Deserialize, Serialize};

/// Coating overrides (user units).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CoatingFile {
    /// Critical pressure (GPa).
    #[serde(rename = "p_crit_GPa")]
    pub p_crit_gpa: Option<f64>,
    /// Friction coefficient of intact contacts.
    pub mu1: Option<f64>,
    /// Friction coefficient of failed contacts.
    pub mu2: Option<f64>,
}
