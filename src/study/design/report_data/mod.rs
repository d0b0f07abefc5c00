//! Stage 7 of a design, the report data ([`ReportDataStage`], its knobs [`ReportDataParams`]):
//! each pattern's answer, the tolerance maps around the answers ([`tolerance_map()`]), the best
//! patterns ([`best`]), the recipes' decisions ([`recipe_answer`]) and the P_crit sweep
//! ([`p_crit`]).

pub mod best;
pub mod p_crit;
pub mod recipe_answer;
mod stage;
mod tolerance_map;

pub use stage::{ReportDataInput, ReportDataParams, ReportDataStage};
pub use tolerance_map::tolerance_map;
