//! # superlube — screen, map and confirm patterned superlubric interfaces
//!
//! Data flows one way: scene (crate `surrogate::scene`) → contacts → load sharing
//! (`surrogate::solver`) or dynamics (crate `dem`) → the workflows of [`study`] → rows, reports
//! and figures ([`plot`]). The `superlube` binary's commands ([`cli`]) parse flags and call one
//! workflow each; other programs (and the tests) can call the workflows directly.

pub mod cli;
pub mod plot;
pub mod present;
pub mod runs;
pub mod study;
