//! The superlubric threshold shared by `friction`, `design` and `tolerance`.

use super::checks;
use anyhow::Result;

/// `--mu-superlubric`: the friction coefficient μ_sl below which an estimate counts as
/// superlubric (dimensionless, > 0; default 0.02, the study's).
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct VerdictArgs {
    /// Friction coefficient below which an estimate counts as superlubric: the threshold of
    /// the verdict (superlubric, borderline or not) of a `friction` row, a `design` and a
    /// `tolerance` load.
    #[arg(
        long = "mu-superlubric",
        value_name = "MU",
        default_value_t = 0.02,
        allow_hyphen_values = true
    )]
    pub mu_superlubric: f64,
}

impl VerdictArgs {
    /// μ_sl, checked: finite and > 0 (the error names the flag).
    pub fn mu_superlubric(&self) -> Result<f64> {
        checks::positive(self.mu_superlubric, "--mu-superlubric")
    }
}
