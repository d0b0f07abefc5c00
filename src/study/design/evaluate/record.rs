//! The recorded inputs of an orientation's evaluation: the α scan's and estimate's knobs
//! ([`evaluation_record`], written into both the design's inputs and each stored evaluation's)
//! and one orientation's ([`eval_inputs`]). User units (mN, µm, degrees), as every sidecar.

use super::params::AlphaScanParams;
use crate::runs::meta::{scene_file, Inputs};
use crate::study::design::model::DesignScene;
use crate::study::design::symmetry_words::PairSymmetry;
use crate::study::record;
use crate::study::rows::label;
use serde_json::{json, Map, Value};
use surrogate::friction::FrictionParams;
use surrogate::units::{deg_to_rad, m_to_um, n_to_mn, rad_to_deg};

/// The knobs of an orientation's evaluation (α scan `a` and friction estimate `friction`), as
/// recorded both in the design's inputs and in each stored evaluation's.
pub fn evaluation_record(a: &AlphaScanParams, friction: &FrictionParams) -> Map<String, Value> {
    let v = json!({
        "alpha_step_deg": a.alpha_step_deg,
        "alpha_refine_deg": a.alpha_refine_deg,
        "line_deg": a.line.map(rad_to_deg),
        "scan_um": label(m_to_um(a.scan_length)),
        "scan_step_um": label(m_to_um(a.scan_step)),
        "alphas_per_theta": a.alphas_per_theta,
        "friction": record::friction_knobs(friction),
    });
    match v {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}

/// The inputs of one orientation's evaluation: θ (degrees), its scan load (N), the loads'
/// labels (mN) and the pair's α period, with the evaluation's knobs.
pub fn eval_inputs(
    ds: &DesignScene,
    (theta_deg, scan_load): (f64, f64),
    sym: &PairSymmetry,
    loads_mn: &[f64],
    knobs: Map<String, Value>,
) -> Inputs {
    let mut params = json!({
        "theta_deg": theta_deg,
        "scan_load_mN": label(n_to_mn(scan_load)),
        "load_mN": loads_mn,
        "alpha_period_deg": sym.alpha_period_deg,
    });
    if let Value::Object(m) = &mut params {
        m.extend(knobs);
    }
    Inputs {
        workflow: "design/orientation".into(),
        scene: Some(scene_file(&ds.scene.with_theta(deg_to_rad(theta_deg)))),
        params,
    }
}
