//! The friction estimates the DEM confirmation compares its runs with, at the confirmation
//! loads the evaluation did not estimate ([`confirm_estimates`]): run per pattern before its
//! files are written, so μ_est stands next to μ_DEM for every run.

use super::jobs::loads_to_confirm;
use super::params::ConfirmParams;
use crate::runs::meta::{scene_file, Inputs};
use crate::study::design::limit::{solver_of, LimitKnobs};
use crate::study::design::model::PatternResult;
use crate::study::design::store::{tag, Store};
use crate::study::load::Load;
use crate::study::record;
use anyhow::Result;
use serde_json::json;
use surrogate::solver::Solver;
use surrogate::units::{deg_to_rad, rad_to_deg};

/// The friction estimate of the designs to confirm at the confirmation loads that the
/// evaluation did not estimate (above the screen's coating-intact load, or above the lowest
/// load of a candidate not superlubric there): one stage file per (θ, α, W), added to the
/// candidate's rows for the comparison with the DEM (the score is not changed).
/// `cp`, `limit`: the confirmation's and the shared knobs. Cost: one friction estimate per
/// missing (θ, α, W), or reading its stage file.
pub fn confirm_estimates(
    pr: &mut PatternResult,
    (cp, limit): (&ConfirmParams, &LimitKnobs),
    store: &Store,
) -> Result<()> {
    let mut solver: Option<Solver> = None;
    let ds = &pr.scene;
    for c in pr.ranking.iter_mut().take(cp.designs) {
        for w in loads_to_confirm(c, &cp.loads, &limit.loads) {
            let wm = Load::from_n(w).mn();
            if c.friction.iter().any(|r| Load::from_n(w).is(r.load_mN)) {
                continue;
            }
            let theta = deg_to_rad(c.theta_deg);
            let inputs = Inputs {
                workflow: "design/estimate".into(),
                scene: Some(scene_file(&ds.scene.with_theta(theta))),
                params: json!({
                    "theta_deg": c.theta_deg,
                    "alpha_deg": c.alpha_deg,
                    "load_mN": wm,
                    "line_deg": limit.line.map(rad_to_deg),
                    "friction": record::friction_knobs(&limit.friction),
                }),
            };
            let rel = format!(
                "stages/{}/estimate_theta{}_alpha{}_W{}.json",
                ds.name,
                tag(c.theta_deg),
                tag(c.alpha_deg),
                tag(wm)
            );
            let row = match store.load_json::<crate::study::rows::FrictionRow>(&rel, &inputs)? {
                Some(r) => r,
                None => {
                    let s = solver_of(&mut solver, ds)?;
                    let line = crate::study::corrugation::contact_line(
                        &ds.scene.with_theta(theta),
                        limit.line,
                    );
                    let alpha = deg_to_rad(c.alpha_deg);
                    let est = surrogate::friction::estimate_friction_loads(
                        s,
                        theta,
                        line.angle + alpha,
                        &[w],
                        &limit.friction,
                    )?;
                    let mut r = crate::study::rows::FrictionRow::new(
                        &ds.scene.pattern,
                        theta,
                        alpha,
                        line.angle,
                        w,
                        &est[0],
                    );
                    r.alpha_deg = c.alpha_deg;
                    store.save_json(&rel, &inputs, &r)?;
                    r
                }
            };
            c.friction.push(row);
            c.friction.sort_by(|a, b| a.load_mN.total_cmp(&b.load_mN));
        }
    }
    Ok(())
}
