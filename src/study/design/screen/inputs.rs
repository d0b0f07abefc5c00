//! The screen's parameters and recorded inputs (the same as `superlube screen` records).

use crate::runs::meta::Inputs;
use crate::study::design::model::DesignScene;
use crate::study::record;
use crate::study::screen::ScreenParams;
use surrogate::solver::{Model, SearchKind};
use surrogate::units::deg_to_rad;

/// The screen's parameters for θ (degrees): every θ × every load `loads` (N).
pub fn screen_params(thetas_deg: &[f64], loads: &[f64]) -> ScreenParams {
    ScreenParams {
        thetas: thetas_deg.iter().map(|&t| deg_to_rad(t)).collect(),
        loads: loads.to_vec(),
        model: Model::Auto,
        search: SearchKind::Grid,
    }
}

/// The inputs of a pattern's screen (the same as `superlube screen` records).
pub fn screen_inputs(ds: &DesignScene, sp: &ScreenParams) -> Inputs {
    Inputs {
        workflow: "screen".into(),
        scene: Some(ds.record()),
        params: record::screen(sp),
    }
}
