//! The slide workflow: the full DEM protocol (equilibrate, attach the pulling spring and relax,
//! slide at constant support speed): friction force and coefficient, lock-in.

use super::dem_run::{run_dem, DemOutcome, DemParams};
use super::rows::SlideReport;
use crate::runs::progress::Progress;
use anyhow::Result;
use dem::protocol::{slide_summary, RunKind};
use surrogate::Scene;

/// The one line that explains a LOCKED IN result, from its advance ratio (slider advance /
/// support advance over the measuring window; `None`: not known): the slider did not follow
/// the pulling spring's support over the window, which is stick-slip or static friction above
/// the spring's force, or, on a protocol much shorter than the study's, a slider still catching
/// up with the spring (the support starts 120 µm ahead; the pulled slider's period is about
/// 10 µs).
pub fn locked_in_words(advance_ratio: Option<f64>) -> String {
    let moved = match advance_ratio.filter(|r| r.is_finite()) {
        Some(r) => format!(
            " (the slider advanced {:.0} % as far as the support over the measuring window)",
            100.0 * r
        ),
        None => String::new(),
    };
    format!(
        "LOCKED IN{moved}: it did not follow the pulling spring, so this run cannot call it superlubric; on a protocol much shorter than the study's 10 µs relax + 300 µs slide the slider may still be catching up with the spring: run a longer relax and slide before reading it as stuck"
    )
}

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
        if result.locked_in {
            format!("; {}", locked_in_words(Some(result.advance_ratio)))
        } else {
            String::new()
        },
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
