//! The slide workflow: the full DEM protocol (equilibrate, attach the pulling spring and relax,
//! slide at constant support speed): friction force and coefficient, lock-in.

use super::dem_run::{run_dem, DemOutcome, DemParams};
use super::rows::SlideReport;
use crate::runs::progress::Progress;
use anyhow::Result;
use dem::protocol::{slide_summary, RunKind};
use surrogate::Scene;

/// Runs the sliding protocol of `scene` with `p`. Returns the run (time series, facts, error if
/// it stopped early) and, if it completed, the summary.
pub fn slide(
    scene: &Scene,
    p: &DemParams,
    progress: &dyn Progress,
) -> Result<(DemOutcome, Option<SlideReport>)> {
    let out = run_dem(scene, p, RunKind::Slide, progress)?;
    if out.error.is_some() {
        return Ok((out, None));
    }
    let result = slide_summary(
        &out.samples,
        &out.prepared.sim.params,
        out.prepared.sim.state.step,
        out.wall_s,
    );
    progress.note(&format!(
        "slide: friction {:.5} mN (μ = {:.5}), {:.1} contacts on average, max P_max {:.3} GPa{}; {} steps in {:.1} s",
        result.friction_mn,
        result.mu,
        result.mean_contacts,
        result.max_p_max_gpa,
        if result.locked_in { ", LOCKED IN" } else { "" },
        out.steps_this_process,
        out.wall_s
    ));
    let report = SlideReport {
        case: out.case.clone(),
        result,
        run: out.info.clone(),
    };
    Ok((out, Some(report)))
}
