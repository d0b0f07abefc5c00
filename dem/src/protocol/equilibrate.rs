//! Summary of an equilibration run.

use super::Sample;
use serde::Serialize;

/// JSON summary of `superlube equilibrate` (user units in the names).
#[derive(Debug, Clone, Serialize)]
pub struct EquilibrateSummary {
    /// Contacts at the end.
    pub contacts: usize,
    /// P_max at the end (GPa).
    #[serde(rename = "p_max_GPa")]
    pub p_max_gpa: f64,
    /// Mean slider sphere height at the end (µm).
    pub z_um: f64,
    /// Failed contacts at the end.
    pub failed_contacts: usize,
    /// Σ vertical contact force / W at the end (–), 1 at equilibrium.
    pub force_balance: f64,
    /// Time after which |ΣF_z − W| ≤ 2 % W for the rest of the run (µs); null if never.
    pub settle_us: Option<f64>,
    /// Steps taken.
    pub steps: u64,
    /// Wall time (s).
    pub wall_s: f64,
    /// Surrogate (quasi-static, rigid slider) contact number for the same scene and load.
    pub surrogate_contacts: usize,
    /// Surrogate P_max (GPa).
    #[serde(rename = "surrogate_p_max_GPa")]
    pub surrogate_p_max_gpa: f64,
    /// Surrogate height z (µm).
    pub surrogate_z_um: f64,
}

/// First sample time (µs) after which `|contact_fz − W| ≤ tol·W` holds for every later sample.
pub fn settle_time(samples: &[Sample], load_mn: f64, tol: f64) -> Option<f64> {
    let ok = |s: &Sample| (s.contact_fz_mn - load_mn).abs() <= tol * load_mn;
    let mut t = None;
    for s in samples.iter().rev() {
        if ok(s) {
            t = Some(s.t_us);
        } else {
            break;
        }
    }
    t
}

/// Builds the summary from the samples (last = final state).
#[allow(clippy::too_many_arguments)]
pub fn equilibrate_summary(
    samples: &[Sample],
    load_mn: f64,
    steps: u64,
    wall_s: f64,
    surrogate: &crate::system::StartInfo,
) -> EquilibrateSummary {
    let last = samples.last().copied().unwrap_or_default();
    EquilibrateSummary {
        contacts: last.contacts,
        p_max_gpa: last.p_max_gpa,
        z_um: last.z_um,
        failed_contacts: last.failed_contacts,
        force_balance: last.contact_fz_mn / load_mn,
        settle_us: settle_time(samples, load_mn, 0.02),
        steps,
        wall_s,
        surrogate_contacts: surrogate.contacts,
        surrogate_p_max_gpa: surrogate.p_max * 1e-9,
        surrogate_z_um: surrogate.z * 1e6,
    }
}
