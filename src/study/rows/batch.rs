//! The rows of a DEM batch: [`BatchRow`] (one run, `runs.csv`) and [`ConfigStatsRow`] (the
//! runs of one configuration, `seeds.csv`).

use super::stats::stats;
use serde::{Deserialize, Serialize};

/// How a run of a DEM batch ended (`runs.csv`'s `status`: `ok`, `failed`, `missing`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RunStatus {
    /// The run finished.
    Ok,
    /// The run stopped early (e.g. blow-up); the reason is in the row's `error`.
    Failed,
    /// Not run yet (another shard's run, or an interrupted batch).
    Missing,
}

/// One run of a DEM batch (`runs.csv`): every input and the results, in user units. The row
/// of a run that failed (blow-up) or has not run yet has empty result columns, `status`
/// `failed`/`missing` and the reason in `error`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct BatchRow {
    /// Run name = its directory under `runs/`.
    pub name: String,
    /// Pattern pair name.
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Normal load W (mN).
    pub load_mN: f64,
    /// Substrate height amplitude σ_h (µm).
    pub sigma_h_um: f64,
    /// Seed of the substrate heights (matters only for σ_h > 0).
    pub seed: u64,
    /// Young's modulus E (GPa), as the scene file's `youngs_GPa` (read back from a file that
    /// names it `E_GPa` too).
    #[serde(alias = "E_GPa")]
    pub youngs_GPa: f64,
    /// Critical coating pressure P_crit (GPa).
    pub p_crit_GPa: f64,
    /// Coating friction coefficient below P_crit.
    pub mu1: f64,
    /// Coating friction coefficient above P_crit.
    pub mu2: f64,
    /// Constant μ replacing the coating's (`--mu`), empty if not used.
    pub mu_constant: Option<f64>,
    /// Slider mount: locked, free or springs.
    pub mount: String,
    /// `--model` asked for: auto, full or reduced.
    pub model_requested: String,
    /// Model used: full or reduced (empty when the run did not finish).
    pub model: String,
    /// Slider spheres rigid in z (empty when the run did not finish).
    pub rigid_z: Option<bool>,
    /// Equilibration time (µs).
    pub equilibrate_us: f64,
    /// Relaxation time (µs).
    pub relax_us: f64,
    /// Sliding time (µs).
    pub slide_us: f64,
    /// Support speed (m/s).
    pub speed_m_s: f64,
    /// Time step used (µs); the one asked for when the run did not finish, empty if default.
    pub dt_us: Option<f64>,
    /// Friction force = mean spring force over the last 2/3 of sliding (mN).
    pub friction_mN: Option<f64>,
    /// Its standard deviation over that window (mN).
    pub friction_std_mN: Option<f64>,
    /// Friction coefficient friction / W.
    pub mu: Option<f64>,
    /// Mean contact number over the window.
    pub mean_contacts: Option<f64>,
    /// Largest P_max over the window (GPa).
    pub max_p_max_GPa: Option<f64>,
    /// Mean number of contacts above P_crit over the window.
    pub mean_failed_contacts: Option<f64>,
    /// The slider locked in (no steady sliding).
    pub locked_in: Option<bool>,
    /// Slider advance / support advance over the window.
    pub advance_ratio: Option<f64>,
    /// Steps of the run.
    pub steps: Option<u64>,
    /// Wall time of the run (s).
    pub wall_s: Option<f64>,
    /// `ok`, `failed` (stopped early, e.g. blow-up) or `missing` (not run yet: another shard).
    pub status: RunStatus,
    /// Why the run failed or is missing; empty when ok.
    pub error: String,
}

/// Mean, spread and extremes of the runs of one configuration (several seeds, or one run),
/// in user units: `seeds.csv` of a slide batch, the CSV behind each friction-campaign figure.
/// Statistics over the runs that finished (`n_ok`); std is the sample standard deviation
/// (n − 1 in the denominator; 0 for one run); empty when no run finished.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ConfigStatsRow {
    /// Series label (campaign figure) or configuration label (slide batch).
    pub series: String,
    /// Pattern pair name.
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Substrate height amplitude σ_h (µm).
    pub sigma_h_um: f64,
    /// Young's modulus E (GPa), as the scene file's `youngs_GPa` (read back from a file that
    /// names it `E_GPa` too).
    #[serde(alias = "E_GPa")]
    pub youngs_GPa: f64,
    /// Normal load W (mN).
    pub load_mN: f64,
    /// Runs (seeds) of this configuration.
    pub n: usize,
    /// Runs that finished.
    pub n_ok: usize,
    /// Mean friction force (mN).
    pub friction_mean_mN: Option<f64>,
    /// Sample standard deviation of the friction force over the runs (mN).
    pub friction_std_mN: Option<f64>,
    /// Smallest friction force (mN).
    pub friction_min_mN: Option<f64>,
    /// Largest friction force (mN).
    pub friction_max_mN: Option<f64>,
    /// Mean friction coefficient.
    pub mu_mean: Option<f64>,
    /// Sample standard deviation of μ over the runs.
    pub mu_std: Option<f64>,
    /// Smallest μ.
    pub mu_min: Option<f64>,
    /// Largest μ.
    pub mu_max: Option<f64>,
    /// Largest P_max over the runs (GPa).
    pub max_p_max_GPa: Option<f64>,
    /// Mean over the runs of the mean number of failed contacts.
    pub mean_failed_contacts: Option<f64>,
    /// Runs that locked in.
    pub locked_in_runs: usize,
}

impl ConfigStatsRow {
    /// The statistics of `runs` (the rows of one configuration, every seed) under `series`.
    pub fn new(series: &str, runs: &[&BatchRow]) -> ConfigStatsRow {
        let first = runs.first();
        let ok: Vec<&&BatchRow> = runs.iter().filter(|r| r.status == RunStatus::Ok).collect();
        let f: Vec<f64> = ok.iter().filter_map(|r| r.friction_mN).collect();
        let m: Vec<f64> = ok.iter().filter_map(|r| r.mu).collect();
        let (fs, ms) = (stats(&f), stats(&m));
        let pmax = ok
            .iter()
            .filter_map(|r| r.max_p_max_GPa)
            .fold(None, |a: Option<f64>, x| Some(a.map_or(x, |a| a.max(x))));
        let failed: Vec<f64> = ok.iter().filter_map(|r| r.mean_failed_contacts).collect();
        ConfigStatsRow {
            series: series.to_string(),
            pattern: first.map(|r| r.pattern.clone()).unwrap_or_default(),
            theta_deg: first.map_or(0.0, |r| r.theta_deg),
            alpha_deg: first.map_or(0.0, |r| r.alpha_deg),
            sigma_h_um: first.map_or(0.0, |r| r.sigma_h_um),
            youngs_GPa: first.map_or(0.0, |r| r.youngs_GPa),
            load_mN: first.map_or(0.0, |r| r.load_mN),
            n: runs.len(),
            n_ok: ok.len(),
            friction_mean_mN: fs.map(|s| s.0),
            friction_std_mN: fs.map(|s| s.1),
            friction_min_mN: fs.map(|s| s.2),
            friction_max_mN: fs.map(|s| s.3),
            mu_mean: ms.map(|s| s.0),
            mu_std: ms.map(|s| s.1),
            mu_min: ms.map(|s| s.2),
            mu_max: ms.map(|s| s.3),
            max_p_max_GPa: pmax,
            mean_failed_contacts: stats(&failed).map(|s| s.0),
            locked_in_runs: ok.iter().filter(|r| r.locked_in == Some(true)).count(),
        }
    }
}
