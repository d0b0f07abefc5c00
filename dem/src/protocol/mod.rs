//! Protocols: equilibrate (under load, control layer held laterally) and slide (equilibrate,
//! attach the pulling spring and relax, slide), with sampling, lock-in detection, checkpoints
//! and extended-XYZ snapshots.

pub mod equilibrate;
pub mod lock_in;
pub mod run;
pub mod sample;
pub mod slide;
pub mod xyz;

pub use equilibrate::{equilibrate_summary, settle_time, EquilibrateSummary};
pub use lock_in::{lock_in, LockIn};
pub use run::{run, step_counts, step_slide, Phase, Progress, RunIo, RunKind};
pub use sample::Sample;
pub use slide::{slide_summary, SlideSummary};
