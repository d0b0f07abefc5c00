//! # Work-precision diagrams: what each accuracy knob costs and how wrong it is
//!
//! For every tier (screen/map, friction estimate, tolerance search, DEM) and every accuracy knob
//! of it, each setting is run on the study's scenes ([`scenes`]) and its CPU cost
//! ([`cost`]: process CPU time, not wall) is put beside its error against the knob's
//! reference setting on the same scene (the finest setting, or the richest model): the
//! work-precision diagram of numerical ODE benchmarking (log cost against log error, one line
//! per knob, each point a setting). One tier per file: [`screen`], [`friction`], [`tolerance`],
//! [`dem`]; [`tiers`] puts the tiers themselves on one diagram against the best reference (with
//! [`lammps`]'s point where LAMMPS is installed); their rows are [`WorkPrecisionRow`]s ([`row::compare`] makes them). [`check`] holds
//! the convergence checks of the quick set (each knob's error falls as it is refined, within
//! noise; the DEM's default step is below the window's noise; no default has a coarser
//! neighbour of the same error) — asserted in CI by `tests/work_precision_cli.rs`.
//!
//! The full set (`superlube figures --work-precision`) runs the study scenes (DEM: a 30 µm
//! slider, scaled to the study's load per sphere, and the study scenes at the default step
//! only); the quick set ([`WorkPrecisionParams::quick`]) a 10 µm slider with shorter paths and
//! a 1 + 1 + 40 µs DEM protocol. Results and recommendations:
//! docs/validation/work-precision.md.

pub mod check;
pub mod cost;
pub mod dem;
pub mod friction;
mod knob;
pub mod lammps;
pub mod row;
pub mod screen;
mod study_scene;
mod tier;
pub mod tiers;
pub mod tolerance;

pub use knob::Knob;
pub use row::{Measured, Setting, Values, WorkPrecisionRow};
pub use study_scene::{scenes, StudyScene};
pub use tier::Tier;

use crate::runs::progress::Progress;
use anyhow::Result;

/// What to run (settings are fixed per set; see the tier files).
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPrecisionParams {
    /// The quick set (CI): small scenes, few settings.
    pub quick: bool,
    /// The tiers to run, in order.
    pub tiers: Vec<Tier>,
    /// Whether the tiers diagram runs LAMMPS where it is found ([`lammps::find_lmp`]).
    pub lammps: bool,
}

impl WorkPrecisionParams {
    /// Parameters as recorded in the sidecars.
    pub fn record(&self) -> serde_json::Value {
        serde_json::json!({
            "quick": self.quick,
            "tiers": self.tiers.iter().map(|t| t.name()).collect::<Vec<_>>(),
            "lammps": self.lammps,
        })
    }
}

/// Runs the tiers of `p` one after the other (the DEM runs the tiers diagram shares with the
/// DEM tier run once) and hands each tier's rows to `emit` as soon as
/// the tier is done (the command writes its CSV and PNG then). Errors: a scene or a run that
/// cannot start; a setting that fails is a row with its reason in `note`.
pub fn work_precision(
    p: &WorkPrecisionParams,
    progress: &dyn Progress,
    emit: &mut dyn FnMut(Tier, Vec<WorkPrecisionRow>) -> Result<()>,
) -> Result<()> {
    let mut runs = dem::DemRuns::default();
    let lmp = if p.lammps && p.tiers.contains(&Tier::Tiers) {
        let found = lammps::find_lmp();
        if found.is_none() {
            progress
                .note("work-precision: LAMMPS (`lmp`) not found; the tiers diagram leaves it out");
        }
        found
    } else {
        None
    };
    for &tier in &p.tiers {
        let rows = match tier {
            Tier::ScreenMap => screen::run(p.quick, progress)?,
            Tier::Friction => friction::run(p.quick, progress)?,
            Tier::Tolerance => tolerance::run(p.quick, progress)?,
            Tier::Dem => dem::run(p.quick, progress, &mut runs)?,
            Tier::Tiers => tiers::run(p.quick, lmp.as_deref(), progress, &mut runs)?,
        };
        emit(tier, rows)?;
    }
    Ok(())
}
