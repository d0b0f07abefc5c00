//! The row types of the design's own CSVs (`shortlist_<p>.csv`, `dem.csv`) and the DEM rows
//! built from the outcome: each DEM run next to the surrogate estimate at the same (θ, α, W).

use crate::study::design::rank::Candidate;
use crate::study::design::{DesignOutcome, DesignParams};
use crate::study::load::LoadKey;
use crate::study::rows::{label, FrictionRow};
use crate::study::verdict::dem_superlubric;
use serde::{Deserialize, Serialize};
use surrogate::units::n_to_mn;

/// One screened orientation of `shortlist_<p>.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ShortlistRow {
    /// θ (degrees).
    pub theta_deg: f64,
    /// Highest load up to which the coating is intact at every load (mN; 0: none).
    pub coating_intact_to_mN: f64,
    /// P_max there (GPa; at the lowest load when none).
    pub p_max_GPa: f64,
    /// Contacts there.
    pub contacts: usize,
    /// Kept on the shortlist of its level.
    pub shortlisted: bool,
    /// Evaluated (α scan and friction estimate).
    pub evaluated: bool,
}

pub use crate::study::design::confirm::DemProtocol;

/// How a DEM run of `dem.csv` ended (`status`: `ok`, `locked-in` or `failed`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DemStatus {
    /// Finished, sliding.
    Ok,
    /// Finished, locked in (stick).
    LockedIn,
    /// Stopped early; the reason is in `error`.
    Failed,
}

impl std::fmt::Display for DemStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            DemStatus::Ok => "ok",
            DemStatus::LockedIn => "locked-in",
            DemStatus::Failed => "failed",
        })
    }
}

/// One DEM run of `dem.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct DemRow {
    /// Pattern.
    pub pattern: String,
    /// Rank of the design in its pattern.
    pub rank: usize,
    /// θ (degrees).
    pub theta_deg: f64,
    /// α (degrees from the contact line).
    pub alpha_deg: f64,
    /// θ offset (degrees) from the design of its rank for a tolerance-corner run (0: the
    /// design itself).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees, substrate frame) for a tolerance-corner run.
    pub direction_offset_deg: f64,
    /// Load (mN).
    pub load_mN: f64,
    /// `design` (the design's confirmation protocol) or `study` (10 + 10 + 300 µs).
    pub protocol: DemProtocol,
    /// `ok`, `locked-in` or `failed`.
    pub status: DemStatus,
    /// Friction coefficient of the DEM run.
    pub mu_dem: Option<f64>,
    /// The surrogate estimate at the same (θ, α, W); for a tolerance-corner run, the estimate
    /// its design's robust search made at that corner and load, empty where the search did not
    /// estimate it there (it stops at the first sample that fails a load: the next load above
    /// the robust limit may be unestimated at some corners).
    pub mu_est: Option<f64>,
    /// μ_est / μ_DEM.
    pub ratio_est_dem: Option<f64>,
    /// DEM verdict: μ_DEM < the superlubric limit, no contact above P_crit, not locked in.
    pub superlubric_dem: Option<bool>,
    /// Surrogate verdict at this load (coating intact on the path, μ_est < the limit; empty
    /// with `mu_est`'s estimate missing).
    pub superlubric_est: Option<bool>,
    /// Both verdicts agree (empty where either is).
    pub verdicts_agree: Option<bool>,
    /// Mean spring force (mN).
    pub friction_mN: Option<f64>,
    /// Its standard deviation (mN).
    pub friction_std_mN: Option<f64>,
    /// Mean contacts over the window.
    pub mean_contacts: Option<f64>,
    /// Largest P_max over the window (GPa).
    pub max_p_max_GPa: Option<f64>,
    /// Slider advance / support advance.
    pub advance_ratio: Option<f64>,
    /// Wall time of the run (s).
    pub wall_s: Option<f64>,
    /// Run directory (relative to the design's directory).
    pub run_dir: String,
    /// Why the run failed.
    pub error: String,
}

/// The friction row of a candidate at load `w_mn` (mN), matched by [`LoadKey`].
pub fn row_at(c: &Candidate, w_mn: f64) -> Option<&FrictionRow> {
    let w = LoadKey::of_mn(w_mn);
    c.friction.iter().find(|r| LoadKey::of_mn(r.load_mN) == w)
}

/// The DEM rows of the outcome.
pub fn dem_rows(o: &DesignOutcome, p: &DesignParams) -> Vec<DemRow> {
    o.dem
        .iter()
        .map(|e| {
            let pr = o.patterns.iter().find(|pr| pr.scene.name == e.run.pattern);
            let w = label(n_to_mn(e.run.load));
            let corner = e.run.theta_offset_deg != 0.0 || e.run.direction_offset_deg != 0.0;
            // a corner run: the estimate its design's robust search made at that corner and
            // load (none where the search did not estimate it there); else the design's own
            let fr = pr.and_then(|pr| {
                if corner {
                    pr.ranking
                        .get(e.run.rank.wrapping_sub(1))
                        .filter(|c| e.run.theta_deg == label(c.theta_deg + e.run.theta_offset_deg))
                        .and_then(|c| {
                            c.corner_row(e.run.theta_offset_deg, e.run.direction_offset_deg, w)
                        })
                } else {
                    pr.ranking
                        .iter()
                        .find(|c| c.theta_deg == e.run.theta_deg && c.alpha_deg == e.run.alpha_deg)
                        .and_then(|c| row_at(c, w))
                }
            });
            let p_crit = pr.map(|pr| pr.scene.scene.coating.p_crit);
            let r = e.outcome.result.as_ref();
            let mu_est = fr.and_then(|f| f.mu_est);
            // the answer's rule (no verdict for a run of a pattern the outcome lacks)
            let sl_dem = r
                .zip(p_crit)
                .map(|(r, pc)| dem_superlubric(Some(r), None, w, pc, p.mu_superlubric).is_ok());
            let sl_est = fr
                .zip(p_crit)
                .map(|(f, pc)| crate::study::verdict::superlubric(f, pc, p.mu_superlubric));
            DemRow {
                pattern: e.run.pattern.clone(),
                rank: e.run.rank,
                theta_deg: e.run.theta_deg,
                alpha_deg: e.run.alpha_deg,
                theta_offset_deg: e.run.theta_offset_deg,
                direction_offset_deg: e.run.direction_offset_deg,
                load_mN: w,
                protocol: e.run.protocol,
                status: match (r, &e.outcome.error) {
                    (Some(r), _) if r.locked_in => DemStatus::LockedIn,
                    (Some(_), _) => DemStatus::Ok,
                    _ => DemStatus::Failed,
                },
                mu_dem: r.map(|r| r.mu),
                mu_est,
                ratio_est_dem: match (mu_est, r) {
                    (Some(m), Some(r)) if r.mu != 0.0 => Some(m / r.mu),
                    _ => None,
                },
                superlubric_dem: sl_dem,
                superlubric_est: sl_est,
                verdicts_agree: match (sl_dem, sl_est) {
                    (Some(a), Some(b)) => Some(a == b),
                    _ => None,
                },
                friction_mN: r.map(|r| r.friction_mN),
                friction_std_mN: r.map(|r| r.friction_std_mN),
                mean_contacts: r.map(|r| r.mean_contacts),
                max_p_max_GPa: r.map(|r| r.max_p_max_GPa),
                advance_ratio: r.and_then(|r| r.advance_ratio),
                wall_s: r.map(|r| r.wall_s),
                run_dir: format!("dem/{}", e.outcome.name),
                error: e.outcome.error.clone().unwrap_or_default(),
            }
        })
        .collect()
}
