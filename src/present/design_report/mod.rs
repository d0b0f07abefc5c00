//! The design's final outputs: `report.md` (the answer first), the CSVs behind it, the PNGs —
//! each with its sidecar, each rewritten only when its bytes change. The design workflow
//! (`crate::study::design::design`) returns its
//! [`DesignOutcome`](crate::study::design::DesignOutcome); the command calls [`publish`].
//!
//! | file | content |
//! |---|---|
//! | `report.md` | the answer table (a row per pattern) and a paragraph per answer, how to run each answer, how to read it, how sure (DEM vs estimate), ranking, shortlist, wall times, reproduction commands: `report.md.j2` over [`ReportData`] |
//! | `answer_<p>.toml` | each answer's scene with its θ set ([`top::answer_toml`]), run by the report's `slide`, `tolerance` and `export-lammps` commands |
//! | `ranking.csv` | [`RankingRow`](crate::study::design::rank::RankingRow) per candidate, best first within each pattern |
//! | `shortlist_<p>.csv` | [`ShortlistRow`] per screened θ: coating-intact load, P_max and contacts there, level, kept, evaluated |
//! | `screen_<p>.csv` | the screen (the `screen` schema; a stage file) |
//! | `corrugation_<p>.csv` | the α scans of the evaluated θ (the `corrugation` schema) |
//! | `friction_<p>.csv` | the friction estimates of every candidate (the `friction` schema) |
//! | `dem.csv` | [`DemRow`] per DEM run: μ_DEM next to μ_est |
//! | `patterns.csv`, `patterns.png`, `contacts_<p>.png` | per pattern its geometry beside its best design; the limit against the family's parameter; the contact maps of the best three ([`patterns`]) |
//! | `yield_<p>.csv`, `.json`, `.png` | with `--yield-samples`: each answer's yield over fabrication, one row per device, the summary, the curve ([`yields`]) |
//! | `yield_rank.csv` | with `--rank-by yield`: the designs ranked by yield, their load at yield q beside the robust limit ([`yields::YieldRankRow`]) |
//! | `pmax_<p>.png`, `corrugation_<p>.png`, `mu_<p>.png` | P_max vs θ per load with P_crit; corrugation vs α of the finalists; μ vs load, surrogate lines and DEM markers ([`charts`]) |
//!
//! Each pattern's own files (`shortlist_`, `corrugation_`, `friction_<p>.csv`, `pmax_`,
//! `corrugation_<p>.png`) are written as the design completes the pattern ([`Writer`], the
//! design's hook), before its rows are dropped; the rest at the end ([`finish()`]), from the
//! trimmed outcome.
//!
//! One job per file: [`rows`] (the CSV rows), [`data`] (the template's data), [`words`] (the
//! answer sentences), [`commands`] (the reproduction commands), [`charts`], [`pattern_files`]
//! (each pattern's files), [`finish()`] (the global files), `markdown.rs` (`report.md`), `publish.rs`
//! (the entry points), `notes.rs` (the log lines), `redraw.rs` (a figure drawn when stale).

mod answer_line;
pub mod charts;
pub mod commands;
pub mod data;
mod finish;
pub mod log;
mod markdown;
mod notes;
pub mod pattern_files;
pub mod patterns;
mod publish;
pub mod recipes;
mod redraw;
pub mod rows;
pub mod stamp;
pub mod top;
pub mod words;
pub mod yields;

pub use data::ReportData;
pub use finish::finish;
pub use log::Log;
pub use markdown::{markdown, render, TEMPLATE};
pub use notes::answer_notes;
pub use pattern_files::Writer;
pub use publish::{publish, write};
pub use rows::{dem_rows, DemProtocol, DemRow, DemStatus, ShortlistRow};
