//! The verdict of one friction estimate (θ, α, W) as a value: [`Verdict`] and the measured
//! bands it widens the thresholds by. Here, beside the row that carries it
//! ([`super::FrictionRow::judged`], which also holds [`Verdict::of_row`] and
//! [`Verdict::worst`]); the rule in words, the estimate's yes/no rule and the
//! DEM's verdict are in `crate::study::verdict`.

use serde::{Deserialize, Serialize};
use std::fmt;
use surrogate::units::pa_to_gpa;

/// Range of μ_est/μ_DEM measured off the mount resonance (lowest, highest).
pub const MU_RATIO: (f64, f64) = (0.83, 1.10);

/// Range of (DEM max P_max)/(estimate's path P_max) measured on smoothly sliding runs (lowest,
/// highest).
pub const P_RATIO: (f64, f64) = (0.962, 1.048);

/// The verdict of one estimate (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// Outside both uncertainty bands on the good side: the DEM is expected to agree.
    Superlubric,
    /// Within the measured uncertainty of the μ or the P_crit threshold.
    Borderline,
    /// Beyond a threshold by more than the uncertainty, or no estimate.
    Not,
}

impl Verdict {
    /// The verdict of μ_est and the path's P_max (Pa) against μ_sl and P_crit (Pa); `None`
    /// (no estimate) is `Not`.
    pub fn of(mu_est: Option<f64>, p_max: Option<f64>, mu_sl: f64, p_crit: f64) -> Verdict {
        let (Some(mu), Some(p)) = (mu_est, p_max) else {
            return Verdict::Not;
        };
        if mu / MU_RATIO.1 >= mu_sl || p * P_RATIO.0 > p_crit {
            Verdict::Not
        } else if mu / MU_RATIO.0 < mu_sl && p * P_RATIO.1 <= p_crit {
            Verdict::Superlubric
        } else {
            Verdict::Borderline
        }
    }

    /// The lowercase word (`superlubric`, `borderline`, `not`).
    pub fn word(self) -> &'static str {
        match self {
            Verdict::Superlubric => "superlubric",
            Verdict::Borderline => "borderline",
            Verdict::Not => "not",
        }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.word())
    }
}

/// The band in words, for reports and `--help`: the μ_est and P_max ranges that are borderline.
pub fn band_words(mu_sl: f64, p_crit: f64) -> String {
    format!(
        "borderline = μ_est in [{:.4}, {:.4}) or path P_max in ({:.2}, {:.2}] GPa (the estimate's measured error against the DEM: μ_est/μ_DEM {}–{}, DEM/estimate P_max {}–{})",
        mu_sl * MU_RATIO.0,
        mu_sl * MU_RATIO.1,
        pa_to_gpa(p_crit / P_RATIO.1),
        pa_to_gpa(p_crit / P_RATIO.0),
        MU_RATIO.0,
        MU_RATIO.1,
        P_RATIO.0,
        P_RATIO.1
    )
}
