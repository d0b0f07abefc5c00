//! The rows and the summary of a yield, in user units: [`YieldRow`] (`yield.csv`, one per
//! device), [`CurvePoint`] and [`YieldSummary`] (`summary.json`).

use super::calibration::{Band, Pair};
use super::critical::Limit;
use super::fabrication::FabricationRecord;
use serde::{Deserialize, Serialize};

/// Who set a device's critical load as the yield counts it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DecidedBy {
    /// The estimate (its W_c, bias-corrected by the design's band): without the DEM, or where
    /// its band's lower edge lies above the loads that set the quote and its bound, so that it
    /// cannot set them.
    Estimate,
    /// A DEM run held it at or above the loads that set the quote and its bound (its value:
    /// the estimate's, kept inside what the DEM showed).
    Dem,
    /// The DEM located its critical load to the resolution (held at it, failed just above).
    Located,
    /// It could set the quote or its bound but the DEM runs allowed were spent: kept at the
    /// lower end of what is known (the design's band and its DEM runs; conservative).
    Undecided,
}

/// One fabricated device of `yield.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct YieldRow {
    /// Index of the device (its sampling stream).
    pub sample: usize,
    /// Whether it is a device of the DEM check (fresh, DEM-decided, pooled into the yield).
    pub check: bool,
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
    /// Who set its critical load: estimate, dem, located or undecided ([`DecidedBy`]).
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

/// The DEM check on fresh devices at the estimate's quote.
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

/// The device the DEM failed at the lowest load.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct DemFailure {
    /// Index of the device.
    pub sample: usize,
    /// Whether it is a device of the check.
    pub check: bool,
    /// The load it failed at (mN).
    pub load_mN: f64,
    /// θ offset (degrees).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees).
    pub direction_offset_deg: f64,
    /// Substrate seed.
    pub seed: u64,
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
    /// Devices sampled for the yield (the check's come on top, `dem_check_total`).
    pub samples: usize,
    /// Devices the quote and its bound are taken over: `samples` and the check's (pooled:
    /// the check's devices are fresh draws of the same model, decided by the DEM).
    pub pooled: usize,
    /// Bisection resolution (fraction of the load).
    pub resolution: f64,
    /// The load held by a fraction q of the devices (mN; `null` without samples).
    pub load_at_quantile_mN: Option<f64>,
    /// Its one-sided lower bound at confidence γ (mN; Wilks: the `bound_rank`-th lowest
    /// critical load; `null` when the samples are too few, see `min_samples_for_bound`).
    pub load_at_quantile_bound_mN: Option<f64>,
    /// How high more DEM runs could lift the quote and its bound (mN): both with every device
    /// still undecided at the upper end of what is known of it (equal to the quote and bound
    /// when none is undecided; `null` without the DEM).
    #[serde(default)]
    pub ceiling_mN: Option<[Option<f64>; 2]>,
    /// Rank of the order statistic of the bound.
    pub bound_rank: Option<usize>,
    /// Fewest samples for a bound at q and γ.
    pub min_samples_for_bound: usize,
    /// Fraction of the pooled devices holding the quoted load.
    pub yield_at_quantile_load: Option<f64>,
    /// Its Clopper–Pearson interval [low, high].
    pub yield_at_quantile_load_interval: Option<[f64; 2]>,
    /// The quote is the critical load of rank `pooled − ⌈q·pooled⌉ + 1` from the bottom and
    /// the bound that of `bound_rank`: only the lowest `setting_ranks` critical loads set them.
    pub setting_ranks: usize,
    /// The `setting_ranks`-th lowest upper end of what is known of the devices' DEM critical
    /// loads (mN; `null` without the DEM): a device whose lower end lies at or above it
    /// cannot be among the lowest `setting_ranks`, so it needs no DEM location.
    pub threshold_mN: Option<f64>,
    /// The devices whose DEM critical load the DEM located (sample indices): those that could
    /// set the quote or its bound.
    pub located: Vec<usize>,
    /// Devices with at least one DEM run.
    pub dem_decided: usize,
    /// Devices that could set the quote or its bound when the DEM runs allowed were spent
    /// (kept at the lower end of what is known: the quote is then conservative).
    pub undecided: usize,
    /// DEM runs made, the check's included.
    pub dem_runs: usize,
    /// Most DEM runs allowed, the check's included.
    pub dem_runs_allowed: usize,
    /// Rounds of DEM runs (each round's runs go side by side).
    pub dem_rounds: usize,
    /// The estimate's band for this design, calibrated on `pairs` ([`Band`]).
    pub band: Band,
    /// Every DEM run beside the estimate at the same device and load.
    pub pairs: Vec<Pair>,
    /// Load of the DEM check (mN; the estimate's quote of the yield's own devices, unless
    /// asked otherwise; `null`: no check).
    pub dem_check_load_mN: Option<f64>,
    /// Whether the check ran at a load asked for (`--dem-check-load-mn`), not at the quote.
    #[serde(default)]
    pub dem_check_load_given: bool,
    /// Devices of the DEM check that held.
    pub dem_check_passed: usize,
    /// Devices in the DEM check.
    pub dem_check_total: usize,
    /// Clopper–Pearson interval of the check's fraction (`null` without a check).
    pub dem_check_interval: Option<[f64; 2]>,
    /// Whether the check agrees with the final quote: the check's devices holding it are
    /// not too few for q at confidence γ (the upper end of their Clopper–Pearson interval
    /// is ≥ q); at a check load of its own, whether that interval holds the yield there
    /// (`null` without a check).
    pub dem_check_consistent: Option<bool>,
    /// Whether the quote was lowered until its check agreed with it.
    pub quote_lowered_by_check: bool,
    /// The check's runs.
    pub dem_check_runs: Vec<DemCheckRun>,
    /// The device the DEM failed at the lowest load (`null`: none failed).
    pub lowest_dem_failure: Option<DemFailure>,
    /// Whether the DEM ran (`false` with no DEM asked).
    pub dem: bool,
    /// Devices superlubric at every rung of the ladder (their W_c is its top: a lower bound).
    pub censored: usize,
    /// The fabrication model.
    pub fabrication: FabricationRecord,
    /// The yield curve at each distinct critical load and at the quoted load.
    pub curve: Vec<CurvePoint>,
}
