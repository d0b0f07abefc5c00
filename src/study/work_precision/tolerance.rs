//! The tolerance search: the θ and direction sampling steps of the tolerance box (±0.1° ×
//! ±0.5°, the defaults of `design`), each against a 4× finer sampling of its axis (the other
//! axis at its default step). Error: the robust superlubric limit and the two windows (relative
//! to the tolerance half-widths), on the superlubric scene (the two others have no superlubric
//! load, so the search has nothing to sample).

use super::cost::measure;
use super::row::{compare, Measured, Setting, Values};
use super::{scenes, Knob, Tier, WorkPrecisionRow};
use crate::runs::progress::Progress;
use crate::study::campaign::STUDY_LOADS_MN;
use crate::study::tolerance::{
    placement_intact, rows_upto, LimitParams, RobustSearch, ToleranceBox,
};
use anyhow::Result;
use surrogate::friction::FrictionParams;
use surrogate::solver::Solver;
use surrogate::units::{mn_to_n, rad_to_deg};

/// Tolerance half-widths (degrees): θ, direction (`design`'s defaults).
pub const TOL_DEG: [f64; 2] = [0.1, 0.5];
/// Default sampling steps (degrees): θ, direction (`design`'s defaults).
pub const STEP_DEG: [f64; 2] = [0.02, 0.25];

/// Runs the tier (see the module docs).
pub fn run(quick: bool, progress: &dyn Progress) -> Result<Vec<WorkPrecisionRow>> {
    let small = quick.then_some((10.0, 60.0));
    let all = scenes(small)?;
    let s = &all[0];
    let n_study = surrogate::Scene::preset("square-tri")?
        .slider_sites_local()
        .len() as f64;
    let scale = s.scene.slider_sites_local().len() as f64 / n_study;
    let lp = LimitParams {
        loads: STUDY_LOADS_MN.iter().map(|&w| mn_to_n(w) * scale).collect(),
        mu_superlubric: 0.02,
        line: None,
        friction: FrictionParams::default(),
    };
    let solver = Solver::new(&s.scene)?;
    let theta = s.scene.slider.theta;
    let (theta_deg, direction_deg) = (rad_to_deg(theta), rad_to_deg(s.direction));
    let cap = placement_intact(&solver, theta, &lp.loads);
    let (nominal, _) = rows_upto(&solver, theta_deg, direction_deg, cap, 0, &lp)?;
    let solvers = [solver];
    let axes: [(Knob, Vec<f64>); 2] = if quick {
        [
            (Knob::ThetaStepDeg, vec![0.1, 0.05, 0.02, 0.005]),
            (Knob::DirectionStepDeg, vec![0.5, 0.25, 0.0625]),
        ]
    } else {
        [
            (Knob::ThetaStepDeg, vec![0.1, 0.05, 0.02, 0.01, 0.005]),
            (Knob::DirectionStepDeg, vec![0.5, 0.25, 0.125, 0.0625]),
        ]
    };
    let mut rows = Vec::new();
    progress.stage("work-precision: tolerance search", 2, "knobs");
    for (axis, (knob, steps)) in axes.iter().enumerate() {
        let reference = STEP_DEG[axis] / 4.0;
        let ms: Vec<Measured> = steps
            .iter()
            .map(|&st| -> Result<Measured> {
                let mut step = STEP_DEG;
                step[axis] = st;
                let bx = ToleranceBox::new(TOL_DEG[0], TOL_DEG[1], step[0], step[1]);
                let (r, cost) = measure(|| -> Result<_> {
                    let mut rs =
                        RobustSearch::new(&solvers, theta_deg, direction_deg, &nominal, &bx, &lp);
                    rs.run_above(0)?;
                    rs.windows()?;
                    Ok(rs.result())
                });
                let r = r?;
                let limit = match r.superlubric_to {
                    0 => 0.0,
                    k => lp.loads[k - 1],
                };
                Ok(Measured {
                    setting: Setting::num(st, STEP_DEG[axis], reference),
                    cost,
                    values: Values {
                        limit: Some(limit),
                        windows_deg: Some([
                            r.theta_window_deg.unwrap_or(0.0),
                            r.direction_window_deg.unwrap_or(0.0),
                        ]),
                        window_scale_deg: TOL_DEG,
                        verdict: Some(r.verdict),
                        note: format!(
                            "{} samples, {} friction paths{}",
                            bx.theta_offsets_deg.len() * bx.direction_offsets_deg.len(),
                            r.paths,
                            if r.exact { "" } else { "; limit not exact" }
                        ),
                        ..Values::default()
                    },
                })
            })
            .collect::<Result<_>>()?;
        rows.extend(compare(Tier::Tolerance, &s.name, *knob, &ms));
        progress.advance(1);
    }
    progress.finish();
    Ok(rows)
}
