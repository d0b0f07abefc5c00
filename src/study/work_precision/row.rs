//! [`WorkPrecisionRow`]: one point of a work-precision diagram (one setting of one knob on one
//! scene), and [`compare`], which turns the measured settings of a knob into rows with their
//! errors against the knob's reference setting.

use super::cost::Cost;
use super::{Knob, Tier};
use crate::study::verdict::Verdict;
use serde::{Deserialize, Serialize};
use surrogate::units::{m_to_nm, m_to_um, n_to_mn, pa_to_gpa};

/// What one setting gave (SI; `None`: not measured by this tier or this knob).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Values {
    /// Friction coefficient (μ_est, or the DEM's μ).
    pub mu: Option<f64>,
    /// Standard error of `mu` (the DEM's window; the inertial model's spread / √starts).
    pub mu_se: f64,
    /// Peak contact pressure P_max (Pa): the screen's at the placement, the path's largest, the
    /// landscape's largest, the DEM window's largest.
    pub p_max: Option<f64>,
    /// Contact number (at the placement, mean over the path / grid / window).
    pub contacts: Option<f64>,
    /// Standard error of `contacts` (the DEM's window).
    pub contacts_se: f64,
    /// Corrugation: peak-to-peak height along the path (m).
    pub corrugation: Option<f64>,
    /// Largest quasi-static pulling force along the path (N).
    pub max_pull: Option<f64>,
    /// Height range Δz of the landscape over its repeat cell (m).
    pub landscape_range: Option<f64>,
    /// Robust superlubric limit load (N).
    pub limit: Option<f64>,
    /// θ and direction windows (degrees) of the tolerance search.
    pub windows_deg: Option<[f64; 2]>,
    /// Scales (degrees) the window errors are relative to: the tolerance half-widths.
    pub window_scale_deg: [f64; 2],
    /// The verdict this setting gives (the estimate's band rule, or the DEM's rule).
    pub verdict: Option<Verdict>,
    /// Free text: why a value is missing, what the setting could not change.
    pub note: String,
}

/// One setting of a knob: its text, its value in the knob's unit, and its role.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// As written in the CSV (`0.05`, `rigid-tilt`, `on`).
    pub text: String,
    /// The value in the unit of the knob's name (`None`: a categorical setting).
    pub value: Option<f64>,
    /// Whether this is the code's default.
    pub is_default: bool,
    /// Whether this is the reference the others' errors are measured against.
    pub is_reference: bool,
}

impl Setting {
    /// A numeric setting `v` (knob's unit).
    pub fn num(v: f64, default: f64, reference: f64) -> Setting {
        Setting {
            text: format!("{}", crate::study::rows::label(v)),
            value: Some(crate::study::rows::label(v)),
            is_default: (v - default).abs() <= 1e-9 * default.abs().max(1e-300),
            is_reference: (v - reference).abs() <= 1e-9 * reference.abs().max(1e-300),
        }
    }

    /// A categorical setting.
    pub fn cat(text: &str, is_default: bool, is_reference: bool) -> Setting {
        Setting {
            text: text.into(),
            value: None,
            is_default,
            is_reference,
        }
    }
}

/// One measured setting before comparison.
#[derive(Debug, Clone)]
pub struct Measured {
    /// The setting.
    pub setting: Setting,
    /// Its cost.
    pub cost: Cost,
    /// What it gave.
    pub values: Values,
}

/// One point of a work-precision diagram: a setting of a knob on a scene, its cost and its
/// error against the knob's reference setting on the same scene. Errors are relative
/// (`|x − x_ref| / |x_ref|`; the windows relative to the tolerance half-width); `error_rel` is
/// the largest of them (the friction estimate's: of μ_est and P_max), the y of the diagram; `noise_rel` the noise of that comparison (the
/// standard errors of both points, in quadrature), below which an error is not resolved.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct WorkPrecisionRow {
    /// Tier (`screen-map`, `friction`, `tolerance`, `dem`, `tiers`).
    pub tier: Tier,
    /// Scene (`superlubric`, `coating-failure`, `stick-slip`; `small-…`: 30 µm slider).
    pub scene: String,
    /// Knob, written with the unit of its settings in the name (`grid_points`, `step_um`,
    /// `model`).
    pub knob: Knob,
    /// The setting as text.
    pub setting: String,
    /// The setting's value in the knob's unit (empty for a categorical knob).
    pub setting_value: Option<f64>,
    /// CPU seconds of the work of this setting (process user + system, every thread).
    pub cost_cpu_s: f64,
    /// Wall seconds of it (noisy on a shared machine).
    pub cost_wall_s: f64,
    /// Largest relative error against the reference (the diagram's y).
    pub error_rel: f64,
    /// Relative noise of that error (standard errors in quadrature; 0 for deterministic tiers).
    pub noise_rel: f64,
    /// μ (μ_est or the DEM's).
    pub mu: Option<f64>,
    /// Relative error of μ.
    pub err_mu_rel: Option<f64>,
    /// P_max (GPa).
    pub p_max_GPa: Option<f64>,
    /// Relative error of P_max.
    pub err_p_max_rel: Option<f64>,
    /// Contacts.
    pub contacts: Option<f64>,
    /// Relative error of the contacts.
    pub err_contacts_rel: Option<f64>,
    /// Corrugation (nm).
    pub corrugation_nm: Option<f64>,
    /// Relative error of the corrugation.
    pub err_corrugation_rel: Option<f64>,
    /// Largest pulling force along the corrugation path (mN).
    pub max_pull_mN: Option<f64>,
    /// Relative error of it.
    pub err_max_pull_rel: Option<f64>,
    /// Landscape height range (nm).
    pub landscape_range_nm: Option<f64>,
    /// Relative error of it.
    pub err_landscape_range_rel: Option<f64>,
    /// Robust superlubric limit (mN).
    pub limit_mN: Option<f64>,
    /// Relative error of it.
    pub err_limit_rel: Option<f64>,
    /// θ window (degrees).
    pub theta_window_deg: Option<f64>,
    /// Direction window (degrees).
    pub direction_window_deg: Option<f64>,
    /// Largest window error relative to the tolerance half-width.
    pub err_window_rel: Option<f64>,
    /// Verdict of this setting (empty where none).
    pub verdict: String,
    /// Whether it differs from the reference's verdict.
    pub verdict_changed: bool,
    /// Whether this setting is the code's default.
    pub is_default: bool,
    /// Whether it is the reference.
    pub is_reference: bool,
    /// Notes.
    pub note: String,
}

fn rel(a: Option<f64>, b: Option<f64>, scale: Option<f64>) -> Option<f64> {
    let (a, b) = (a?, b?);
    let d = scale.unwrap_or(b.abs());
    Some(if a == b {
        0.0
    } else if d > 0.0 {
        (a - b).abs() / d
    } else {
        f64::INFINITY
    })
}

/// The rows of one knob on one scene: every measured setting against the reference (the
/// setting marked `is_reference`; the last one if none is). Order kept.
pub fn compare(tier: Tier, scene: &str, knob: Knob, ms: &[Measured]) -> Vec<WorkPrecisionRow> {
    let Some(r) = ms
        .iter()
        .find(|m| m.setting.is_reference)
        .or_else(|| ms.last())
    else {
        return Vec::new();
    };
    let rv = &r.values;
    ms.iter()
        .map(|m| {
            let v = &m.values;
            let err_mu = rel(v.mu, rv.mu, None);
            let err_p = rel(v.p_max, rv.p_max, None);
            let err_c = rel(v.contacts, rv.contacts, None);
            let err_corr = rel(v.corrugation, rv.corrugation, None);
            let err_pull = rel(v.max_pull, rv.max_pull, None);
            let err_land = rel(v.landscape_range, rv.landscape_range, None);
            let err_limit = rel(v.limit, rv.limit, None);
            let err_window = match (v.windows_deg, rv.windows_deg) {
                (Some(a), Some(b)) => Some(
                    (0..2)
                        .map(|i| {
                            rel(
                                Some(a[i]),
                                Some(b[i]),
                                Some(rv.window_scale_deg[i].max(1e-12)),
                            )
                            .unwrap_or(0.0)
                        })
                        .fold(0.0, f64::max),
                ),
                _ => None,
            };
            // the friction estimate's error is μ_est and the path's P_max (its mean contacts
            // are a path average of a small integer, reported but not judged)
            let err_c_judged = if tier == Tier::Friction { None } else { err_c };
            let errs = [
                err_mu,
                err_p,
                err_c_judged,
                err_corr,
                err_pull,
                err_land,
                err_limit,
                err_window,
            ];
            let error_rel = errs.iter().flatten().fold(0.0f64, |a, &b| a.max(b));
            let q = |x: f64, se: f64, rse: f64| (se * se + rse * rse).sqrt() / x.abs().max(1e-300);
            // a quantity this setting does not give adds no noise (the screen has no μ)
            let noise_mu = match (v.mu, rv.mu) {
                (Some(_), Some(x)) => q(x, v.mu_se, rv.mu_se),
                _ => 0.0,
            };
            let noise_c = match (v.contacts, rv.contacts) {
                (Some(_), Some(x)) => q(x, v.contacts_se, rv.contacts_se),
                _ => 0.0,
            };
            let verdict_changed = match (v.verdict, rv.verdict) {
                (Some(a), Some(b)) => a != b,
                _ => false,
            };
            WorkPrecisionRow {
                tier,
                scene: scene.into(),
                knob,
                setting: m.setting.text.clone(),
                setting_value: m.setting.value,
                cost_cpu_s: m.cost.cpu_s,
                cost_wall_s: m.cost.wall_s,
                error_rel,
                noise_rel: noise_mu.max(noise_c),
                mu: v.mu,
                err_mu_rel: err_mu,
                p_max_GPa: v.p_max.map(pa_to_gpa),
                err_p_max_rel: err_p,
                contacts: v.contacts,
                err_contacts_rel: err_c,
                corrugation_nm: v.corrugation.map(m_to_nm),
                err_corrugation_rel: err_corr,
                max_pull_mN: v.max_pull.map(n_to_mn),
                err_max_pull_rel: err_pull,
                landscape_range_nm: v.landscape_range.map(m_to_nm),
                err_landscape_range_rel: err_land,
                limit_mN: v.limit.map(n_to_mn),
                err_limit_rel: err_limit,
                theta_window_deg: v.windows_deg.map(|w| w[0]),
                direction_window_deg: v.windows_deg.map(|w| w[1]),
                err_window_rel: err_window,
                verdict: v.verdict.map_or(String::new(), |x| x.word().into()),
                verdict_changed,
                is_default: m.setting.is_default,
                is_reference: std::ptr::eq(m, r),
                note: v.note.clone(),
            }
        })
        .collect()
}

/// µm text of a length (m) for a setting (`0.05`).
pub fn um(v: f64) -> f64 {
    crate::study::rows::label(m_to_um(v))
}
