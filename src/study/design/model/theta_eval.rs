//! [`ThetaEval`]: one orientation's evaluation (α scan and friction estimate) as stored.

use crate::study::rows::{CorrugationRow, FrictionRow};
use serde::{Deserialize, Serialize};

/// The evaluation of one orientation (user units, as stored in the design's stage files).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ThetaEval {
    /// θ (degrees).
    pub theta_deg: f64,
    /// Load of the α scan (mN).
    pub scan_load_mN: f64,
    /// Contact line used (degrees from x).
    pub line_deg: f64,
    /// The α scan, in scan order (coarse grid, then each refinement).
    pub scan: Vec<CorrugationRow>,
    /// The best α's (degrees), best first.
    pub alphas_deg: Vec<f64>,
    /// The friction estimate along each best α (α outer, load inner): the loads up to `W_c`
    /// (ascending, up to the first whose coating fails on the path), or only the lowest when
    /// the candidate is not superlubric there.
    pub friction: Vec<FrictionRow>,
}
