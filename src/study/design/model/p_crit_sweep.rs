//! [`PCritSweep`]: the best recipe's robust limit at each coating strength (the report data's
//! P_crit sweep, [`super::super::report_data::p_crit`]).

use crate::study::verdict::Verdict;
use serde::{Deserialize, Serialize};

/// The coating strengths (GPa) of the sweep: the study's 4 GPa and ±10 %.
pub const P_CRIT_SWEEP_GPA: [f64; 3] = [3.6, 4.0, 4.4];

/// The robust limit of one design at one P_crit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PCritLimit {
    /// The coating's strength (Pa).
    pub p_crit: f64,
    /// The robust limit (mN; 0: superlubric at no load of the list).
    pub superlubric_to_mn: f64,
    /// The worst verdict up to it (the band is relative to this P_crit).
    pub verdict: Verdict,
    /// The design's own score (the scene's P_crit), not a new search.
    pub own: bool,
}

/// The sweep of one design: which, and its limit at each P_crit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PCritSweep {
    /// The pattern (recipe) name.
    pub pattern: String,
    /// θ of the design (degrees).
    pub theta_deg: f64,
    /// Its pull direction from the substrate x axis (degrees).
    pub direction_deg: f64,
    /// Its limit at each value of [`P_CRIT_SWEEP_GPA`], in that order.
    pub limits: Vec<PCritLimit>,
}
