//! The rows and the summary of a yield, in user units: [`YieldRow`] (`yield.csv`, one per
//! device), [`CurvePoint`] and [`YieldSummary`] (`summary.json`).

use super::critical::Limit;
use super::fabrication::FabricationRecord;
use serde::{Deserialize, Serialize};

/// Who decided whether a device holds at the quoted load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DecidedBy {
    /// The estimate: the quoted load lies outside the device's band bracket.
    Estimate,
    /// A DEM run at the quoted load (the bracket contained it).
    Dem,
}

/// One fabricated device of `yield.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct YieldRow {
    /// Index of the device (its sampling stream).
    pub sample: usize,
    /// θ offset from the nominal (degrees).
    pub theta_offset_deg: f64,
    /// Pull-direction offset from the nominal, substrate frame (degrees).
    pub direction_offset_deg: f64,
    /// Substrate seed of the device's height realisation.
    pub seed: u64,
    /// The device's coating strength P_crit (GPa).
    pub p_crit_GPa: f64,
    /// Smallest slider sphere diameter drawn (µm; empty without a diameter scatter).
    pub sphere_diameter_min_um: Option<f64>,
    /// Largest slider sphere diameter drawn (µm; empty without a diameter scatter).
    pub sphere_diameter_max_um: Option<f64>,
    /// Critical load W_c (mN): the highest load shown superlubric (the estimate's, moved to
    /// agree with the DEM's decision where there is one).
    pub critical_load_mN: f64,
    /// W_low (mN): where the estimate enters its verdict band.
    pub critical_load_low_mN: f64,
    /// W_high (mN): where it leaves the band.
    pub critical_load_high_mN: f64,
    /// W_c of the estimate alone (mN), before any DEM decision.
    pub critical_load_estimate_mN: f64,
    /// What ends superlubricity above the estimate's W_c: path, friction, error, none (above
    /// the ladder's top).
    pub limited_by: Limit,
    /// Who decided the device at the quoted load: estimate or dem.
    pub decided_by: DecidedBy,
    /// Loads (mN) of the device's DEM runs, `;`-separated (empty: none).
    pub dem_loads_mN: String,
    /// Their verdicts (`true`: superlubric), `;`-separated.
    pub dem_superlubric: String,
    /// Single loads estimated for the device.
    pub estimates: usize,
}

/// One point of the yield curve.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct CurvePoint {
    /// Load W (mN).
    pub load_mN: f64,
    /// Fraction of devices with W_c ≥ W.
    #[serde(rename = "yield")]
    pub fraction: f64,
    /// Clopper–Pearson lower end.
    pub low: f64,
    /// Clopper–Pearson upper end.
    pub high: f64,
}

/// The DEM check on fresh devices at the quoted load.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DemCheckRun {
    /// Index of the device (after the yield's own samples).
    pub sample: usize,
    /// θ offset (degrees).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees).
    pub direction_offset_deg: f64,
    /// Substrate seed.
    pub seed: u64,
    /// Whether the DEM found it superlubric.
    pub superlubric: bool,
    /// Why not, when not.
    pub why: String,
}

/// `summary.json`: the answer of a yield.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct YieldSummary {
    /// Pattern pair.
    pub pattern: String,
    /// Nominal θ (degrees).
    pub theta_deg: f64,
    /// Nominal pull direction from the substrate's x axis (degrees).
    pub direction_deg: f64,
    /// q: the fraction of devices the quoted load must hold.
    pub quantile: f64,
    /// γ: the confidence of the intervals and of the bound.
    pub confidence: f64,
    /// Devices sampled.
    pub samples: usize,
    /// Bisection resolution (fraction of the load).
    pub resolution: f64,
    /// The load held by a fraction q of the devices (mN; `null` without samples).
    pub load_at_quantile_mN: Option<f64>,
    /// Its one-sided lower bound at confidence γ (mN; Wilks: the `bound_rank`-th lowest
    /// critical load; `null` when the samples are too few, see `min_samples_for_bound`).
    pub load_at_quantile_bound_mN: Option<f64>,
    /// Rank of the order statistic of the bound.
    pub bound_rank: Option<usize>,
    /// Fewest samples for a bound at q and γ.
    pub min_samples_for_bound: usize,
    /// Fraction of devices holding the quoted load (estimate and DEM decisions).
    pub yield_at_quantile_load: Option<f64>,
    /// Its Clopper–Pearson interval [low, high].
    pub yield_at_quantile_load_interval: Option<[f64; 2]>,
    /// Devices whose band bracket contained the quoted load (decided by the DEM).
    pub dem_decided: usize,
    /// Of those, the devices the DEM held at the quoted load. The yield there is
    /// (`estimate_decided_holding` + this) / `samples`: the DEM's stratum is a census of the
    /// band (every device in it is run), so the pooled count is binomial and its
    /// Clopper–Pearson interval exact.
    pub dem_decided_holding: usize,
    /// Devices the estimate decided (outside the band at the quoted load) that hold there.
    pub estimate_decided_holding: usize,
    /// DEM runs made for the decisions (over every round).
    pub dem_runs: usize,
    /// Rounds of DEM decisions (the quoted load moves when the DEM overrules the estimate).
    pub dem_rounds: usize,
    /// Load of the DEM check (mN; the quoted load unless asked otherwise; `null`: no check).
    pub dem_check_load_mN: Option<f64>,
    /// Devices of the DEM check that held.
    pub dem_check_passed: usize,
    /// Devices in the DEM check.
    pub dem_check_total: usize,
    /// Clopper–Pearson interval of the check's fraction (`null` without a check).
    pub dem_check_interval: Option<[f64; 2]>,
    /// The check's runs.
    pub dem_check_runs: Vec<DemCheckRun>,
    /// Whether the DEM ran (`false` with no DEM asked).
    pub dem: bool,
    /// Devices superlubric at every rung of the ladder (their W_c is its top: a lower bound).
    pub censored: usize,
    /// The fabrication model.
    pub fabrication: FabricationRecord,
    /// The yield curve at each distinct critical load and at the quoted load.
    pub curve: Vec<CurvePoint>,
}
