//! The row of a friction estimate: [`FrictionRow`].

use super::format::{clean, label};
use super::verdict::Verdict;
use serde::{Deserialize, Serialize};
use surrogate::units::{j_to_pj, m_to_um, n_to_mn, pa_to_gpa, rad_to_deg};

/// The surrogate friction estimate of one (θ, α, W) (`surrogate::friction`). The leading seven
/// columns are the answer; units in the names. A configuration without an estimate (a failed
/// solve along its path) has empty numbers and the reason in `error`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct FrictionRow {
    /// Pattern pair name (as in [`ScreenRow::pattern`](super::ScreenRow::pattern)).
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Normal load W (mN).
    pub load_mN: f64,
    /// Estimated friction coefficient μ_est in the DEM protocol: the inertial model's mean
    /// spring force / W (`surrogate::friction`).
    pub mu_est: Option<f64>,
    /// Largest P_max along the path (GPa): the coating is intact on the whole path iff
    /// ≤ P_crit.
    pub p_max_GPa: Option<f64>,
    /// Path average of the fraction of W carried by contacts above P_crit, in [0, 1].
    pub failed_fraction: Option<f64>,
    /// Coating term ⟨Σ μ(p0_i) F_n,i |e_t,i|⟩ / W.
    pub mu_coating: Option<f64>,
    /// Corrugation (Prandtl–Tomlinson) term: dissipation per unit length / W (overdamped).
    pub mu_corrugation: Option<f64>,
    /// Quasi-static (overdamped) estimate μ_coating + μ_corrugation: ≥ μ_est in stick-slip,
    /// equal in steady sliding.
    pub mu_quasi_static: Option<f64>,
    /// Standard deviation of μ over the inertial model's runs (the scatter of one DEM run).
    pub mu_est_spread: Option<f64>,
    /// Stick-slip parameter η = max(−V'')/K (> 1: stick-slip).
    pub eta: Option<f64>,
    /// Enthalpy barrier U0 = max V − min V along the path (pJ).
    pub barrier_pJ: Option<f64>,
    /// Largest quasi-static pulling force along the path (mN).
    pub max_lateral_force_mN: Option<f64>,
    /// Path average of P_max (GPa).
    pub p_max_mean_GPa: Option<f64>,
    /// Path average of the contact number.
    pub contacts_mean: Option<f64>,
    /// Prandtl–Tomlinson spring K: K0 in series with the contacts' lateral stiffness (N/m).
    pub k_spring_N_m: Option<f64>,
    /// Contact-line angle from the substrate x axis (degrees) that α is measured from.
    pub line_deg: f64,
    /// Pulling direction from the substrate x axis = line + α (degrees).
    pub direction_deg: f64,
    /// Path length (µm): one substrate period along a lattice direction, else the fixed length.
    pub path_length_um: Option<f64>,
    /// Sample spacing along the path (µm).
    pub path_step_um: Option<f64>,
    /// Solved samples along the path.
    pub samples: Option<usize>,
    /// Whether the path is one exact lattice period (periodic landscape).
    pub periodic: Option<bool>,
    /// Stick-slip jumps in the Prandtl–Tomlinson measuring window.
    pub slips: Option<usize>,
    /// Start of the path across the pull (µm, along the pull direction rotated by +90°): the
    /// groove the slider drifts into off the placement's crest while it slides (0: it stays).
    pub transverse_offset_um: Option<f64>,
    /// ω_t/ω_p: the spring mount's tilt frequency over the lateral frequency of a stuck
    /// slider–substrate pair (`surrogate::friction::TiltResonance`); empty without springs.
    pub tilt_pair_ratio: Option<f64>,
    /// `true` where the ratio lies in the measured resonance band (0.6–1.15) and contacts fail
    /// along the path: μ_est may be an upper bound there (the DEM measured up to 2.8× lower).
    pub mount_resonance: Option<bool>,
    /// The verdict at this row's own (θ, α, W) ([`Verdict::of_row`]:
    /// `superlubric`, `borderline` or `not`), set where the row is written
    /// ([`FrictionRow::judged`]); absent (no column) in the stage files.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verdict: Option<Verdict>,
    /// Empty, or why this configuration has no estimate.
    pub error: String,
}

impl FrictionRow {
    /// This row with its [`verdict`](FrictionRow::verdict) against μ_sl `mu_sl` and P_crit
    /// `p_crit` (Pa): the rule `design` and `tolerance` apply at each sample
    /// ([`Verdict::of_row`]). Cost: a few comparisons.
    pub fn judged(mut self, mu_sl: f64, p_crit: f64) -> FrictionRow {
        self.verdict = Some(Verdict::of_row(&self, mu_sl, p_crit));
        self
    }

    /// The row of (θ rad, α rad from the contact line `line` rad, W N) from the estimate.
    pub fn new(
        pattern: &str,
        theta: f64,
        alpha: f64,
        line: f64,
        load: f64,
        r: &Result<surrogate::friction::FrictionEstimate, surrogate::SceneError>,
    ) -> FrictionRow {
        let mut row = FrictionRow {
            pattern: pattern.to_string(),
            theta_deg: label(rad_to_deg(theta)),
            alpha_deg: clean(rad_to_deg(alpha)),
            load_mN: label(n_to_mn(load)),
            mu_est: None,
            p_max_GPa: None,
            failed_fraction: None,
            mu_coating: None,
            mu_corrugation: None,
            mu_quasi_static: None,
            mu_est_spread: None,
            eta: None,
            barrier_pJ: None,
            max_lateral_force_mN: None,
            p_max_mean_GPa: None,
            contacts_mean: None,
            k_spring_N_m: None,
            line_deg: rad_to_deg(line),
            direction_deg: clean(rad_to_deg(line + alpha)),
            path_length_um: None,
            path_step_um: None,
            samples: None,
            periodic: None,
            slips: None,
            transverse_offset_um: None,
            tilt_pair_ratio: None,
            mount_resonance: None,
            verdict: None,
            error: String::new(),
        };
        match r {
            Ok(e) => {
                row.mu_est = Some(e.mu_est);
                row.p_max_GPa = Some(pa_to_gpa(e.p_max_max));
                row.failed_fraction = Some(e.failed_fraction);
                row.mu_coating = Some(e.mu_coating);
                row.mu_corrugation = Some(e.mu_corrugation);
                row.mu_quasi_static = Some(e.mu_quasi_static);
                row.mu_est_spread = Some(e.mu_est_spread);
                row.eta = Some(e.eta);
                row.barrier_pJ = Some(j_to_pj(e.barrier));
                row.max_lateral_force_mN = Some(n_to_mn(e.max_lateral_force));
                row.p_max_mean_GPa = Some(pa_to_gpa(e.p_max_mean));
                row.contacts_mean = Some(e.contacts_mean);
                row.k_spring_N_m = Some(e.k_spring);
                row.path_length_um = Some(m_to_um(e.length));
                row.path_step_um = Some(m_to_um(e.step));
                row.samples = Some(e.samples);
                row.periodic = Some(e.periodic);
                row.slips = Some(e.slips);
                row.transverse_offset_um = Some(clean(m_to_um(e.transverse_offset)));
                row.tilt_pair_ratio = e.tilt_pair_ratio;
                row.mount_resonance = Some(e.mount_resonance);
            }
            Err(err) => row.error = err.to_string(),
        }
        row
    }
}

/// The verdict of friction rows (beside the row: [`super::verdict`] knows no row).
impl Verdict {
    /// The verdict of a friction row (`Not` where it has an error).
    pub fn of_row(r: &FrictionRow, mu_sl: f64, p_crit: f64) -> Verdict {
        if !r.error.is_empty() {
            return Verdict::Not;
        }
        Verdict::of(
            r.mu_est,
            r.p_max_GPa.map(surrogate::units::gpa_to_pa),
            mu_sl,
            p_crit,
        )
    }

    /// The worst verdict of `rows` (every load up to a limit, and every sample of a tolerance
    /// box): `Not` when there are none, so a row borderline at any load up to the limit makes
    /// the whole limit borderline.
    pub fn worst<'r>(
        rows: impl IntoIterator<Item = &'r FrictionRow>,
        mu_sl: f64,
        p_crit: f64,
    ) -> Verdict {
        rows.into_iter()
            .map(|r| Verdict::of_row(r, mu_sl, p_crit))
            .max()
            .unwrap_or(Verdict::Not)
    }
}
