//! # The presentation layer: reports, tables, charts and reproduction commands
//!
//! Layers, one way: `cli` (flags) → `present` (what the user reads) → `study` (the workflows)
//! → `runs` (the run machinery). A workflow returns its outcome; the command hands it to this
//! layer, which formats it. Generated text comes from a template (`minijinja`) rendered over one
//! data struct built here. `src/study` and `src/runs` never import this layer (`.ci/layers`).
//!
//! | output | module |
//! |---|---|
//! | `superlube design`'s `report.md`, CSVs and PNGs | [`design_report`] |

pub mod design_report;
pub mod inputs;
pub mod yield_words;
