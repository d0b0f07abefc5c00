//! Each workflow's parameters in user units, as recorded in the sidecars (`params`) and hashed
//! into `input_hash` ([`crate::runs::meta`]).

use super::contacts::ContactsParams;
use super::corrugation::CorrugationParams;
use super::dem_run::DemParams;
use super::friction::FrictionSweepParams;
use super::landscape::LandscapeParams;
use super::rows::{clean, label};
use super::screen::ScreenParams;
use serde_json::{json, Value};
use sha2::{Digest, Sha256};
use surrogate::units::{m_to_um, n_to_mn, pa_to_gpa, rad_to_deg, s_to_us};

/// Longest axis written out value by value; longer ones are recorded as count, first, last and
/// the sha256 of their values (still exact for the hash, without a 100 MB sidecar).
pub const MAX_LISTED: usize = 1000;

/// A sweep axis in user units.
pub fn axis(values: &[f64]) -> Value {
    if values.len() <= MAX_LISTED {
        return json!(values);
    }
    let mut h = Sha256::new();
    for v in values {
        h.update(v.to_le_bytes());
    }
    let hex: String = h.finalize().iter().map(|b| format!("{b:02x}")).collect();
    json!({
        "count": values.len(),
        "first": values[0],
        "last": values[values.len() - 1],
        "values_sha256": hex,
    })
}

fn search_name(s: surrogate::solver::SearchKind) -> &'static str {
    match s {
        surrogate::solver::SearchKind::Grid => "grid",
        surrogate::solver::SearchKind::Bvh => "bvh",
    }
}

/// `screen`: θ (degrees) and W (mN) axes, model, search.
pub fn screen(p: &ScreenParams) -> Value {
    let t: Vec<f64> = p.thetas.iter().map(|&t| label(rad_to_deg(t))).collect();
    let w: Vec<f64> = p.loads.iter().map(|&w| label(n_to_mn(w))).collect();
    json!({
        "theta_deg": axis(&t),
        "load_mN": axis(&w),
        "model": p.model.name(),
        "search": search_name(p.search),
    })
}

/// One configuration's contact list: θ, W, model, search.
pub fn contacts(p: &ContactsParams) -> Value {
    json!({
        "theta_deg": label(rad_to_deg(p.theta)),
        "load_mN": label(n_to_mn(p.load)),
        "model": p.model.name(),
        "search": search_name(p.search),
    })
}

/// `landscape`: W and the grid (θ is in the scene).
pub fn landscape(p: &LandscapeParams) -> Value {
    json!({
        "load_mN": label(n_to_mn(p.load)),
        "grid": p.grid,
    })
}

/// `corrugation`: W, α axis (degrees), contact line, path, method (θ is in the scene).
pub fn corrugation(p: &CorrugationParams) -> Value {
    let a: Vec<f64> = p.alphas.iter().map(|&a| clean(rad_to_deg(a))).collect();
    json!({
        "load_mN": label(n_to_mn(p.load)),
        "alpha_deg": axis(&a),
        "line_deg": p.line.map(rad_to_deg),
        "distance_um": label(m_to_um(p.distance)),
        "step_um": label(m_to_um(p.step)),
        "method": p.method,
        "grid": p.grid,
    })
}

/// The friction estimate's knobs (user units).
pub fn friction_knobs(k: &surrogate::friction::FrictionParams) -> Value {
    json!({
        "length_um": label(m_to_um(k.length)),
        "max_period_um": label(m_to_um(k.max_period)),
        "step_um": label(m_to_um(k.step)),
        "transient_um": label(m_to_um(k.transient)),
        "k0_N_m": k.k0,
        "transverse_um": label(m_to_um(k.transverse)),
        "k_slider_xy_N_m": k.k_slider_xy,
        "k_substrate_xy_N_m": k.k_substrate_xy,
        "direction_tol_rad": k.direction_tol,
        "segment_um": label(m_to_um(k.segment)),
        // which rows `mount_resonance` flags: since this key, not on a substrate rough enough to
        // detune the resonance, so a stored estimate of an older build is never mixed with new ones
        "mount_resonance_rule": "band, failed contacts, sigma_h below max(5 nm, delta_crit/2)",
    })
}

/// `friction`: θ, α (degrees) and W (mN) axes, contact line, the estimate's knobs, and the
/// rule of the rows' `verdict` against the scene's P_crit `p_crit` (Pa): μ_sl and the band.
pub fn friction(p: &FrictionSweepParams, p_crit: f64) -> Value {
    let t: Vec<f64> = p.thetas.iter().map(|&t| label(rad_to_deg(t))).collect();
    let a: Vec<f64> = p.alphas.iter().map(|&a| clean(rad_to_deg(a))).collect();
    let w: Vec<f64> = p.loads.iter().map(|&w| label(n_to_mn(w))).collect();
    json!({
        "theta_deg": axis(&t),
        "alpha_deg": axis(&a),
        "load_mN": axis(&w),
        "line_deg": p.line.map(rad_to_deg),
        "friction": friction_knobs(&p.knobs),
        "verdict": verdict_rule(p.mu_superlubric, p_crit),
    })
}

/// The verdict rule of a row's `verdict` column (`src/study/verdict.rs`): μ_sl, P_crit (GPa),
/// the measured ratios that widen each threshold into the borderline band, and the band in
/// words.
pub fn verdict_rule(mu_sl: f64, p_crit: f64) -> Value {
    use super::rows::verdict::{band_words, MU_RATIO, P_RATIO};
    json!({
        "mu_superlubric": mu_sl,
        "p_crit_GPa": label(pa_to_gpa(p_crit)),
        "mu_est_over_mu_dem": [MU_RATIO.0, MU_RATIO.1],
        "dem_over_estimate_p_max": [P_RATIO.0, P_RATIO.1],
        "band": band_words(mu_sl, p_crit),
    })
}

/// `equilibrate` / `slide`: load, α, line, protocol times, start, reductions, friction, every
/// engine knob (θ is in the scene).
pub fn dem(scene: &surrogate::Scene, p: &DemParams) -> Value {
    let mut engine = p.sim.clone();
    engine.protocol.alpha = super::dem_run::direction(scene, p).1;
    let s = &engine;
    let mut v = json!({
        "load_mN": label(n_to_mn(s.protocol.load)),
        "alpha_deg": label(rad_to_deg(p.alpha)),
        "line_deg": p.line.map(rad_to_deg),
        "equilibrate_us": label(s_to_us(s.protocol.equilibrate_time)),
        "relax_us": label(s_to_us(s.protocol.relax_time)),
        "slide_us": label(s_to_us(s.protocol.slide_time)),
        "speed_m_s": s.protocol.support_speed,
        "dt_us": s.numerics.dt.map(|d| label(s_to_us(d))),
        "sample_us": label(s_to_us(s.protocol.sample_interval)),
        // what `max_p_max_GPa` is: since this key, the largest p0 at any step (before it, at
        // the samples only), so a stored run of an older build is never mixed with new ones
        "p_max_observed": "every step",
        "start": match p.start {
            dem::Start::Surrogate => json!("surrogate"),
            dem::Start::Gap(g) => json!({"gap_nm": label(surrogate::units::m_to_nm(g))}),
        },
        "model": p.model.request.name(),
        "force_rigid_z": p.model.force_rigid_z,
        "active_set": p.model.active_set,
        "friction": match &p.friction {
            None => json!("coating (pressure-switched mu1/mu2)"),
            Some(dem::model::Friction::Constant(c)) => json!({"constant_mu": c.mu}),
            Some(f) => json!(format!("{f:?}")),
        },
        "engine_si": s,
    });
    // runs that may use the full model integrate it with the implicit mount since this key
    // (`--model full-explicit`: velocity-Verlet, as every full run before it); absent
    // otherwise, so stored runs of the other models still match
    let may_be_full = !matches!(
        p.model.request,
        dem::ModelRequest::FullExplicit | dem::ModelRequest::Reduced
    ) && !p.model.force_rigid_z;
    if may_be_full {
        if let Some(o) = v.as_object_mut() {
            o.insert("full_model_integrator".into(), json!("implicit-mount"));
        }
    }
    v
}
