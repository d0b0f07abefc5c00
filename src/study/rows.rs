//! The output row types: ONE struct and ONE CSV/JSON schema per kind of row, used by every
//! command that writes that kind of row. Columns and keys are in user units and say so in their
//! names; the values are converted from SI with `surrogate::units` here and nowhere else.
//!
//! | row | written by | columns |
//! |---|---|---|
//! | [`ScreenRow`] | `screen --out`, `figures` (sweep_*.csv) | `pattern,theta_deg,load_mN,contacts,p_max_GPa,z_um,coating_failed,failed_contacts,tilt_x_urad,tilt_y_urad,model,residual_rel,iterations,error` |
//! | [`ContactRow`] | `screen --contacts-out`, `landscape --contacts-out`, `figures` (contact_map_*.csv) | `slider_index,substrate_index,x_um,y_um,z_um,overlap_nm,force_uN,p0_GPa,failed` |
//! | [`LandscapeRow`] | `landscape --out`, `figures` (landscape_*.csv) | `x_um,y_um,dz_nm` |
//! | [`LandscapeZRow`] | `landscape --shard i/n --out` (a shard, merged by `superlube merge`), the landscape's spill file | `x_um,y_um,z_um` (z exact, see [`exact_um`]) |
//! | [`CorrugationRow`] | `corrugation --out`, `figures` (corrugation_square-tri.csv) | `theta_deg,load_mN,line_deg,alpha_deg,direction_deg,corrugation_nm,max_lateral_force_mN` |
//! | [`FrictionRow`] | `friction --out`, `design` (`friction_<pattern>.csv`) | `pattern,theta_deg,alpha_deg,load_mN,mu_est,p_max_GPa,failed_fraction,mu_coating,mu_corrugation,mu_quasi_static,mu_est_spread,eta,barrier_pJ,max_lateral_force_mN,p_max_mean_GPa,contacts_mean,k_spring_N_m,line_deg,direction_deg,path_length_um,path_step_um,samples,periodic,slips,transverse_offset_um,tilt_pair_ratio,mount_resonance,verdict,error` (`verdict`: `friction`, `design`) |
//! | [`DemSample`] | `equilibrate --out`, `slide --out` | `t_us,support_x_um,spring_force_mN,z_um,contacts,p_max_GPa,failed_contacts,p_max_peak_GPa` |
//! | [`EquilibrateReport`], [`SlideReport`] | `equilibrate --json`, `slide --json` | JSON objects (keys documented on the fields) |
//! | [`BatchRow`] | `slide --out-dir DIR` (`DIR/runs.csv`), `figures --friction` (`runs.csv`) | `name,pattern,theta_deg,alpha_deg,load_mN,sigma_h_um,seed,E_GPa,p_crit_GPa,mu1,mu2,mu_constant,mount,model_requested,model,rigid_z,equilibrate_us,relax_us,slide_us,speed_m_s,dt_us,friction_mN,friction_std_mN,mu,mean_contacts,max_p_max_GPa,mean_failed_contacts,locked_in,advance_ratio,steps,wall_s,status,error` |
//! | [`ConfigStatsRow`] | `slide --out-dir DIR --seeds …` (`DIR/seeds.csv`), `figures --friction` (`friction_fig*.csv`) | `series,pattern,theta_deg,alpha_deg,sigma_h_um,E_GPa,load_mN,n,n_ok,friction_mean_mN,friction_std_mN,friction_min_mN,friction_max_mN,mu_mean,mu_std,mu_min,mu_max,max_p_max_GPa,mean_failed_contacts,locked_in_runs` |

use serde::{Deserialize, Deserializer, Serialize, Serializer};
use surrogate::solver::{ContactInfo, Equilibrium, Model};
use surrogate::units::{
    j_to_pj, m_to_nm, m_to_um, n_to_mn, pa_to_gpa, rad_to_deg, rad_to_urad, UN,
};

pub use dem::protocol::Sample as DemSample;
pub use dem::protocol::{EquilibrateSummary, SlideSummary};

/// Rounds a grid or range coordinate to 1e-9 of its unit, removing the binary noise of
/// `start + k·step` (0.06000000000000001 → 0.06). Used for the landscape grid (µm) and the
/// pulling angles α and directions (degrees): 1e-9 µm and 1e-9° are far below any physical
/// resolution.
pub fn clean(v: f64) -> f64 {
    (v * 1e9).round() / 1e9
}

/// A value converted to user units for a row label (θ in degrees, W in mN), rounded to 12
/// significant digits: removes the noise of the SI round trip (10.200000000000001 → 10.2) at
/// any magnitude, so a load of 1e-20 mN prints as `1e-20`, never `0.0`.
pub fn label(v: f64) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    format!("{v:.11e}").parse().unwrap_or(v)
}

/// One configuration (θ, W) of an orientation × load screen. The leading seven columns are the
/// screening answer; units in the names.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ScreenRow {
    /// Pattern pair name (`slider-substrate`; `*` = a preset whose lattices a scene file changed,
    /// `custom` = lattices from a scene file without preset).
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Normal load W (mN).
    pub load_mN: f64,
    /// Contact number (pairs with overlap > 0).
    pub contacts: Option<usize>,
    /// Largest Hertz pressure p0 (GPa).
    pub p_max_GPa: Option<f64>,
    /// Slider sphere-centre plane height at the disc centre (µm), 3 µm at first on-top touch.
    pub z_um: Option<f64>,
    /// Whether P_max exceeds P_crit.
    pub coating_failed: Option<bool>,
    /// Number of contacts with p0 > P_crit.
    pub failed_contacts: Option<usize>,
    /// Tilt about x (µrad).
    pub tilt_x_urad: Option<f64>,
    /// Tilt about y (µrad).
    pub tilt_y_urad: Option<f64>,
    /// Model used.
    pub model: String,
    /// |ΣF_z − W| / W.
    pub residual_rel: Option<f64>,
    /// Solver iterations.
    pub iterations: Option<usize>,
    /// Empty, or why this configuration has no equilibrium (the other columns are then empty).
    pub error: String,
}

impl ScreenRow {
    /// The row of configuration (θ rad, W N) from the solver's answer; `model` is the model
    /// asked for (reported when the solve failed).
    pub fn new(
        pattern: &str,
        theta: f64,
        load: f64,
        r: &Result<Equilibrium, surrogate::SceneError>,
        model: Model,
    ) -> ScreenRow {
        let mut row = ScreenRow {
            pattern: pattern.to_string(),
            theta_deg: label(rad_to_deg(theta)),
            load_mN: label(n_to_mn(load)),
            contacts: None,
            p_max_GPa: None,
            z_um: None,
            coating_failed: None,
            failed_contacts: None,
            tilt_x_urad: None,
            tilt_y_urad: None,
            model: model.name().to_string(),
            residual_rel: None,
            iterations: None,
            error: String::new(),
        };
        match r {
            Ok(e) => {
                row.contacts = Some(e.contact_count());
                row.p_max_GPa = Some(pa_to_gpa(e.p_max));
                row.z_um = Some(m_to_um(e.z));
                row.coating_failed = Some(e.coating_failed());
                row.failed_contacts = Some(e.failed_count());
                row.tilt_x_urad = Some(rad_to_urad(e.tilt[0]));
                row.tilt_y_urad = Some(rad_to_urad(e.tilt[1]));
                row.model = e.model.name().to_string();
                row.residual_rel = Some(e.residual_rel());
                row.iterations = Some(e.iterations);
            }
            Err(err) => row.error = err.to_string(),
        }
        row
    }
}

/// One slider–substrate contact of an equilibrium (the per-contact list behind contact maps).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[allow(non_snake_case)]
pub struct ContactRow {
    /// Index of the slider sphere (order of `Scene::slider_sites_local`).
    pub slider_index: u32,
    /// Index of the substrate sphere (order of `Scene::substrate_spheres`).
    pub substrate_index: u32,
    /// Contact point x (µm, substrate frame).
    pub x_um: f64,
    /// Contact point y (µm).
    pub y_um: f64,
    /// Contact point z (µm).
    pub z_um: f64,
    /// Overlap δ (nm).
    pub overlap_nm: f64,
    /// Normal force F_n (µN).
    pub force_uN: f64,
    /// Hertz pressure p0 (GPa).
    pub p0_GPa: f64,
    /// Whether p0 > P_crit (coating failed at this contact).
    pub failed: bool,
}

impl ContactRow {
    /// The row of one contact.
    pub fn new(c: &ContactInfo) -> ContactRow {
        ContactRow {
            slider_index: c.slider,
            substrate_index: c.substrate,
            x_um: m_to_um(c.point[0]),
            y_um: m_to_um(c.point[1]),
            z_um: m_to_um(c.point[2]),
            overlap_nm: m_to_nm(c.overlap),
            force_uN: c.force_n / UN,
            p0_GPa: pa_to_gpa(c.p0),
            failed: c.failed,
        }
    }

    /// Every contact of an equilibrium, in the solver's order.
    pub fn all(eq: &Equilibrium) -> Vec<ContactRow> {
        eq.contacts.iter().map(ContactRow::new).collect()
    }
}

/// One grid point of a Δz landscape.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LandscapeRow {
    /// Shift x of the slider centre from its default placement (µm).
    pub x_um: f64,
    /// Shift y (µm).
    pub y_um: f64,
    /// Δz = z − min z over the grid (nm).
    pub dz_nm: f64,
}

impl LandscapeRow {
    /// The row of shift `shift` (m) with `dz` (m).
    pub fn new(shift: [f64; 2], dz: f64) -> LandscapeRow {
        LandscapeRow {
            x_um: clean(m_to_um(shift[0])),
            y_um: clean(m_to_um(shift[1])),
            dz_nm: m_to_nm(dz),
        }
    }
}

/// The exact decimal text of a length `v` (m) in µm: the shortest decimal that reads back as
/// exactly `v` in metres (Rust's round-trip `{:e}`), with its decimal point moved six places
/// (plain notation while the exponent is in −7..21, else `d.ddde±N`). So the text is `v` in µm
/// to ≤ 1 ulp for any reader, and [`parse_exact_um`] gives back `v` bit for bit — which
/// `m_to_um`/`um_to_m` do not guarantee (×10⁶ then ×10⁻⁶ is not an identity on doubles).
pub fn exact_um(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return format!("{v}"); // NaN, inf, 0, -0
    }
    let s = format!("{v:e}");
    let (mant, exp) = s.split_once('e').unwrap_or((&s, "0"));
    let exp = exp.parse::<i32>().unwrap_or(0) + 6;
    let (sign, mant) = match mant.strip_prefix('-') {
        Some(m) => ("-", m),
        None => ("", mant),
    };
    // value = d0.d1d2… × 10^exp
    let digits: String = mant.chars().filter(|c| *c != '.').collect();
    if !(-7..21).contains(&exp) {
        return format!("{sign}{mant}e{exp}");
    }
    if exp < 0 {
        let zeros = "0".repeat((-exp - 1) as usize);
        return format!("{sign}0.{zeros}{digits}");
    }
    let int_len = exp as usize + 1;
    if digits.len() <= int_len {
        format!("{sign}{digits}{}", "0".repeat(int_len - digits.len()))
    } else {
        format!("{sign}{}.{}", &digits[..int_len], &digits[int_len..])
    }
}

/// Reads [`exact_um`]'s text (µm) back to the exact length in metres. Errors name `what`.
pub fn parse_exact_um(text: &str, what: &str) -> anyhow::Result<f64> {
    let t = text.trim();
    let bad = || anyhow::anyhow!("{what}: `{t}` is not a length in µm");
    // Move the decimal point back six places in the text, then parse once (correctly rounded):
    // the decimal read is the one written, so the double is the one written.
    let m_text = match t.split_once(['e', 'E']) {
        Some((m, e)) => format!("{m}e{}", e.parse::<i32>().map_err(|_| bad())? - 6),
        None if t.chars().any(|c| c.is_ascii_digit()) => format!("{t}e-6"),
        None => t.to_string(), // NaN, inf
    };
    m_text.parse::<f64>().map_err(|_| bad())
}

fn ser_exact_um<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&exact_um(*v))
}

fn de_exact_um<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    let t = String::deserialize(d)?;
    parse_exact_um(&t, "z_um").map_err(serde::de::Error::custom)
}

/// One grid point's equilibrium height z (not yet Δz): the row of a landscape shard and of the
/// landscape's spill file. Δz = z − min z needs the minimum over the whole grid, so a shard
/// writes z, exactly ([`exact_um`]), and `superlube merge` (or the landscape's second pass)
/// turns the z rows of the whole grid into [`LandscapeRow`]s.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LandscapeZRow {
    /// Shift x of the slider centre from its default placement (µm).
    pub x_um: f64,
    /// Shift y (µm).
    pub y_um: f64,
    /// Equilibrium height z (m), written in µm as the exact decimal of [`exact_um`].
    #[serde(
        rename = "z_um",
        serialize_with = "ser_exact_um",
        deserialize_with = "de_exact_um"
    )]
    pub z: f64,
}

impl LandscapeZRow {
    /// The row of shift `shift` (m) with height `z` (m).
    pub fn new(shift: [f64; 2], z: f64) -> LandscapeZRow {
        LandscapeZRow {
            x_um: clean(m_to_um(shift[0])),
            y_um: clean(m_to_um(shift[1])),
            z,
        }
    }

    /// The Δz row of this point, given the grid's min z (m).
    pub fn dz_row(&self, z_min: f64) -> LandscapeRow {
        LandscapeRow {
            x_um: self.x_um,
            y_um: self.y_um,
            dz_nm: m_to_nm(self.z - z_min),
        }
    }
}

/// Corrugation felt along one pulling direction α.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CorrugationRow {
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Normal load W (mN).
    #[serde(rename = "load_mN")]
    pub load_mn: f64,
    /// Contact-line angle from the substrate x axis (degrees) that α is measured from.
    pub line_deg: f64,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Path direction from the substrate x axis = line + α (degrees).
    pub direction_deg: f64,
    /// Peak-to-peak slider height along the path (nm).
    pub corrugation_nm: f64,
    /// Largest quasi-static pulling force along the path: the static-friction barrier (mN).
    #[serde(rename = "max_lateral_force_mN")]
    pub max_lateral_force_mn: f64,
}

impl CorrugationRow {
    /// The row of a corrugation point at θ (rad), W (N), contact line `line` (rad).
    pub fn new(
        theta: f64,
        load: f64,
        line: f64,
        p: &surrogate::map::CorrugationPoint,
    ) -> CorrugationRow {
        CorrugationRow {
            theta_deg: label(rad_to_deg(theta)),
            load_mn: label(n_to_mn(load)),
            line_deg: rad_to_deg(line),
            alpha_deg: clean(rad_to_deg(p.alpha)),
            direction_deg: clean(rad_to_deg(p.direction)),
            corrugation_nm: m_to_nm(p.corrugation),
            max_lateral_force_mn: n_to_mn(p.max_lateral_force),
        }
    }
}

/// The surrogate friction estimate of one (θ, α, W) (`surrogate::friction`). The leading seven
/// columns are the answer; units in the names. A configuration without an estimate (a failed
/// solve along its path) has empty numbers and the reason in `error`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct FrictionRow {
    /// Pattern pair name (as in [`ScreenRow::pattern`]).
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
    /// The verdict at this row's own (θ, α, W) ([`crate::study::verdict::Verdict::of_row`]:
    /// `superlubric`, `borderline` or `not`), set where the row is written
    /// ([`FrictionRow::judged`]); absent (no column) in the stage files.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verdict: Option<crate::study::verdict::Verdict>,
    /// Empty, or why this configuration has no estimate.
    pub error: String,
}

impl FrictionRow {
    /// This row with its [`verdict`](FrictionRow::verdict) against μ_sl `mu_sl` and P_crit
    /// `p_crit` (Pa): the rule `design` and `tolerance` apply at each sample
    /// ([`crate::study::verdict::Verdict::of_row`]). Cost: a few comparisons.
    pub fn judged(mut self, mu_sl: f64, p_crit: f64) -> FrictionRow {
        self.verdict = Some(crate::study::verdict::Verdict::of_row(&self, mu_sl, p_crit));
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

/// Facts of a DEM run reported in every DEM summary (user units).
#[derive(Debug, Clone, Serialize)]
pub struct RunInfo {
    /// Time step used (µs).
    pub dt_us: f64,
    /// Estimated critical step (µs).
    pub dt_crit_us: f64,
    /// Mode that sets the critical step.
    pub dt_crit_mode: &'static str,
    /// Pulling angle α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Contact-line angle from the substrate x axis (degrees).
    pub line_deg: f64,
    /// Pulling direction from the substrate x axis = line + α (degrees).
    pub direction_deg: f64,
    /// Moving particles (substrate + slider + control body).
    pub particles: usize,
    /// Substrate spheres left out by `--prune`.
    pub pruned_substrate: usize,
    /// Particle-steps per wall second.
    pub particle_steps_per_s: f64,
    /// Slider spheres rigid in z (reduction).
    pub rigid_z: bool,
    /// Substrate pruning in use.
    pub prune: bool,
    /// Model in use: `full` or `reduced` (= rigid-z).
    pub model: &'static str,
    /// `--model` as given: `auto`, `full` or `reduced`.
    pub model_requested: &'static str,
    /// Why this model (κ = S_n/k_z, P_max, Prandtl–Tomlinson η; docs/validation/dem-engine.md "Model choice").
    pub model_reason: String,
    /// ω_t/ω_p of the `springs` mount (`surrogate::friction::TiltResonance`): in 0.6–1.15 the
    /// friction where contacts fail depends strongly on K1; `null` without springs.
    pub tilt_pair_ratio: Option<f64>,
    /// Active set in use.
    pub active_set: bool,
    /// Mean number of particles integrated per step (the active set; all particles without it).
    pub mean_active_particles: f64,
}

/// What a DEM summary says about its configuration (user units): enough to tell two summaries
/// apart without the sidecar.
#[derive(Debug, Clone, Serialize)]
pub struct DemCase {
    /// Pattern pair name.
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Normal load W (mN).
    #[serde(rename = "load_mN")]
    pub load_mn: f64,
}

/// JSON summary of `superlube equilibrate`: the case, the DEM state at the end, the surrogate's
/// answer, their differences and the run facts.
#[derive(Debug, Clone, Serialize)]
pub struct EquilibrateReport {
    /// Pattern, θ, W.
    #[serde(flatten)]
    pub case: DemCase,
    /// DEM state at the end and the surrogate's answer.
    #[serde(flatten)]
    pub result: EquilibrateSummary,
    /// DEM contacts − surrogate contacts.
    pub contacts_diff: i64,
    /// DEM P_max / surrogate P_max − 1.
    pub p_max_rel_diff: f64,
    /// DEM z − surrogate z (nm); negative: the compliant DEM slider sits lower.
    pub z_diff_nm: f64,
    /// Run facts.
    #[serde(flatten)]
    pub run: RunInfo,
}

/// JSON summary of `superlube slide`: the case, friction and lock-in, and the run facts.
#[derive(Debug, Clone, Serialize)]
pub struct SlideReport {
    /// Pattern, θ, W.
    #[serde(flatten)]
    pub case: DemCase,
    /// Friction, contacts, lock-in over the measuring window.
    #[serde(flatten)]
    pub result: SlideSummary,
    /// Run facts.
    #[serde(flatten)]
    pub run: RunInfo,
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
    /// Young's modulus E (GPa).
    pub E_GPa: f64,
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
    pub status: String,
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
    /// Young's modulus E (GPa).
    pub E_GPa: f64,
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

/// Mean, sample standard deviation (n − 1; 0 for one value), min and max of `v` (`None` if
/// empty).
pub fn stats(v: &[f64]) -> Option<(f64, f64, f64, f64)> {
    if v.is_empty() {
        return None;
    }
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let std = if v.len() > 1 {
        (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
    } else {
        0.0
    };
    let min = v.iter().copied().fold(f64::INFINITY, f64::min);
    let max = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Some((mean, std, min, max))
}

impl ConfigStatsRow {
    /// The statistics of `runs` (the rows of one configuration, every seed) under `series`.
    pub fn new(series: &str, runs: &[&BatchRow]) -> ConfigStatsRow {
        let first = runs.first();
        let ok: Vec<&&BatchRow> = runs.iter().filter(|r| r.status == "ok").collect();
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
            E_GPa: first.map_or(0.0, |r| r.E_GPa),
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_um_reads_back_bit_for_bit() {
        assert_eq!(exact_um(2.9996590468644904e-6), "2.9996590468644904");
        assert_eq!(exact_um(3e-6), "3");
        assert_eq!(exact_um(1.5e-4), "150");
        assert_eq!(exact_um(-2.5e-13), "-0.00000025");
        assert_eq!(exact_um(1e-20), "1e-14");
        assert_eq!(exact_um(0.0), "0");
        let mut x: u64 = 0x9e3779b97f4a7c15;
        let check = |v: f64| {
            let t = exact_um(v);
            let back = parse_exact_um(&t, "z").unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v:e} → {t} → {back:e}");
            // and the text is v in µm to 1 ulp (away from overflow and subnormals)
            let um: f64 = t.parse().unwrap();
            if (1e-290..1e290).contains(&v.abs()) {
                assert!(
                    (um - m_to_um(v)).abs() <= 2.0 * f64::EPSILON * um.abs(),
                    "{v:e} {t}"
                );
            }
        };
        for _ in 0..20000 {
            // xorshift: heights around 3 µm, and arbitrary doubles
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            check(3e-6 * (1.0 - (x >> 11) as f64 / (1u64 << 53) as f64 * 1e-3));
            let any = f64::from_bits(x);
            if any.is_finite() {
                check(any);
            }
        }
        // m_to_um/um_to_m alone would not do: some heights do not survive the round trip.
        let lossy = (0..20000)
            .map(|k| 2.99e-6 + k as f64 * 1.3e-17)
            .filter(|&z| surrogate::units::um_to_m(m_to_um(z)) != z)
            .count();
        assert!(lossy > 0);
        assert!(parse_exact_um("abc", "z_um")
            .unwrap_err()
            .to_string()
            .contains("z_um"));
    }

    #[test]
    fn labels_keep_tiny_values_and_drop_conversion_noise() {
        assert_eq!(label(1e-20), 1e-20);
        assert_eq!(label(10.200000000000001), 10.2);
        assert_eq!(label(0.30000000000000004), 0.3);
        assert_eq!(label(-3.0), -3.0);
        assert_eq!(label(0.0), 0.0);
        for v in [0.35, 1.4, 2.1, 3.86, 21.8, 1e-12, 123456.789] {
            let si = surrogate::units::mn_to_n(v);
            assert_eq!(label(n_to_mn(si)), v);
            assert_eq!(label(rad_to_deg(v.to_radians())), v);
        }
    }
}
