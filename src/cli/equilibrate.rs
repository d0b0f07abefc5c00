//! `superlube equilibrate`: the DEM slider under load for `--equilibrate-us` (the orientation
//! study's protocol), compared with the surrogate's quasi-static answer for the same scene.

use super::dem_args::{DemArgs, RunInfo};
use anyhow::Result;
use dem::protocol::{equilibrate_summary, EquilibrateSummary, RunKind};
use serde::Serialize;
use surrogate::units::{m_to_nm, um_to_m};

/// Options of `superlube equilibrate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    dem: DemArgs,
}

/// JSON summary: the DEM state at the end, the surrogate's answer, and the run facts.
#[derive(Serialize)]
#[allow(non_snake_case)]
struct Summary {
    #[serde(flatten)]
    result: EquilibrateSummary,
    /// DEM contacts − surrogate contacts.
    contacts_diff: i64,
    /// DEM P_max / surrogate P_max − 1.
    p_max_rel_diff: f64,
    /// DEM z − surrogate z (nm); negative: the compliant DEM slider sits lower.
    z_diff_nm: f64,
    #[serde(flatten)]
    run: RunInfo,
}

/// Runs `superlube equilibrate`.
pub fn run(args: Args) -> Result<()> {
    let (scene, params) = args.dem.setup(0.0, 0.0, 0.0)?;
    let load_mn = params.load * 1e3;
    let f = args.dem.execute(&scene, params, RunKind::Equilibrate)?;
    let total_steps = f.prepared.sim.state.step;
    let result = equilibrate_summary(
        &f.samples,
        load_mn,
        total_steps,
        f.wall_s,
        &f.prepared.start,
    );
    let s = Summary {
        contacts_diff: result.contacts as i64 - result.surrogate_contacts as i64,
        p_max_rel_diff: result.p_max_gpa / result.surrogate_p_max_gpa - 1.0,
        z_diff_nm: m_to_nm(um_to_m(result.z_um - result.surrogate_z_um)),
        result,
        run: f.info,
    };
    eprintln!(
        "equilibrate: {} contacts, P_max {:.4} GPa, z {:.6} µm (surrogate: {} contacts, {:.4} GPa, {:.6} µm); {} steps in {:.1} s",
        s.result.contacts,
        s.result.p_max_gpa,
        s.result.z_um,
        s.result.surrogate_contacts,
        s.result.surrogate_p_max_gpa,
        s.result.surrogate_z_um,
        f.steps_this_process,
        f.wall_s
    );
    args.dem.write_summary(&s)
}
