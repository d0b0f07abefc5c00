//! The design's DEM confirmation: independent `slide` runs side by side, one thread each,
//! through the study layer's batch runner [`crate::study::batch`] (which this module held
//! before; its names are re-exported here so the design's code and files are unchanged).
//!
//! Each run writes into `dir/<name>/`: `slide.csv`, `slide.json` (or `failed.json`), each with
//! its sidecar; a finished run is reused by its input hash, an interrupted one resumes from its
//! checkpoint `slide.ckpt`; a failing run does not stop the others. Progress: one stage
//! `confirm (DEM)`.

pub use crate::study::batch::{
    job_inputs, run_batch, Failure, SlideJob, SlideOutcome, SlideResult,
};
