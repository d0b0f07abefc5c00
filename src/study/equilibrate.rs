//! The equilibrate workflow: the DEM slider under load for the equilibration time (the
//! orientation study's protocol), compared with the surrogate's quasi-static answer.

use super::dem_run::{run_dem, DemOutcome, DemParams};
use super::rows::EquilibrateReport;
use crate::runs::progress::Progress;
use anyhow::Result;
use dem::protocol::{equilibrate_summary, RunKind};
use surrogate::units::{m_to_nm, n_to_mn, um_to_m};
use surrogate::Scene;

/// Runs the equilibration of `scene` with `p` (its relax and slide times are not used). Returns
/// the run (time series, facts, error if it stopped early) and, if it completed, the summary.
pub fn equilibrate(
    scene: &Scene,
    p: &DemParams,
    progress: &dyn Progress,
) -> Result<(DemOutcome, Option<EquilibrateReport>)> {
    let out = run_dem(scene, p, RunKind::Equilibrate, progress)?;
    if out.error.is_some() {
        return Ok((out, None));
    }
    let result = equilibrate_summary(
        &out.samples,
        n_to_mn(out.prepared.sim.params.protocol.load),
        out.prepared.sim.state.step,
        out.wall_s,
        &out.prepared.start,
    );
    let report = EquilibrateReport {
        case: out.case.clone(),
        contacts_diff: result.contacts as i64 - result.surrogate_contacts as i64,
        p_max_rel_diff: result.p_max_gpa / result.surrogate_p_max_gpa - 1.0,
        z_diff_nm: m_to_nm(um_to_m(result.z_um - result.surrogate_z_um)),
        result,
        run: out.info.clone(),
    };
    progress.note(&format!(
        "equilibrate: {} contacts, P_max {:.4} GPa, z {:.6} µm (surrogate: {} contacts, {:.4} GPa, {:.6} µm); {} steps in {:.1} s",
        report.result.contacts,
        report.result.p_max_gpa,
        report.result.z_um,
        report.result.surrogate_contacts,
        report.result.surrogate_p_max_gpa,
        report.result.surrogate_z_um,
        out.steps_this_process,
        out.wall_s
    ));
    Ok((out, Some(report)))
}
