//! [`StartArgs`]: how a DEM run starts (`--start`, `--gap-nm`).

use super::checks;
use anyhow::Result;
use dem::Start;
use surrogate::units::NM;

/// How the slider starts.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum StartKind {
    /// At the surrogate's quasi-static equilibrium height (contacts already loaded): short
    /// equilibration.
    Surrogate,
    /// Resting `--gap-nm` above first touch, falling under the load.
    Gap,
}

/// The start flags of `equilibrate` and `slide`.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct StartArgs {
    /// How the slider starts: at the surrogate's equilibrium, or from a gap of `--gap-nm`.
    #[arg(long, value_enum, default_value_t = StartKind::Surrogate)]
    pub start: StartKind,
    /// Gap in nm above first touch for `--start gap` (> 0).
    #[arg(
        long = "gap-nm",
        value_name = "NM",
        default_value_t = 20.0,
        allow_hyphen_values = true
    )]
    pub gap_nm: f64,
}

impl StartArgs {
    /// The engine's start (`--gap-nm` checked > 0 whatever `--start`, naming the flag).
    pub fn start(&self) -> Result<Start> {
        let gap = checks::positive(self.gap_nm, "--gap-nm")? * NM;
        Ok(match self.start {
            StartKind::Surrogate => Start::Surrogate,
            StartKind::Gap => Start::Gap(gap),
        })
    }
}
