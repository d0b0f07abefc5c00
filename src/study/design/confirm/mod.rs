//! Stage 6 of a design, the DEM confirmation: which runs (the top designs at the confirmation
//! loads and at the corners of their tolerance boxes, borderline designs first: [`jobs`]),
//! the friction estimates they are compared with ([`estimates`]), and the batch of
//! independent `slide` runs side by side, one thread each ([`ConfirmStage`], through a
//! [`DemRunner`]: the study layer's batch runner [`crate::study::batch`]).
//!
//! Each run writes into `dir/<name>/`: `slide.csv`, `slide.json` (or `failed.json`), each with
//! its sidecar; a finished run is reused by its input hash, an interrupted one resumes from its
//! checkpoint `slide.ckpt`; a failing run does not stop the others. Progress: one stage
//! `confirm (DEM)`.

pub mod estimates;
pub mod jobs;
mod params;
pub mod protocol_check;
pub mod runner;
mod stage;

pub use crate::study::batch::{SlideJob, SlideOutcome};
pub use crate::study::design::model::{ConfirmEntry, DemEntry, DemProtocol};
pub use jobs::{
    confirm_jobs, dem_model, dem_params, design_dem_params, loads_to_confirm, run_name, to_entries,
};
pub use params::ConfirmParams;
pub use protocol_check::{protocol_check_design, ProtocolCheck};
pub use runner::{BatchRunner, DemRunner};
pub use stage::ConfirmStage;

#[cfg(test)]
mod tests;
