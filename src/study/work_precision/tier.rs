//! The tiers of the work-precision diagrams ([`Tier`]).

use serde::{Deserialize, Serialize};

/// The tiers of the diagrams, in run order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Tier {
    /// Tier 1 screen and Tier 2 maps: solver model, landscape grid, corrugation path step.
    ScreenMap,
    /// The friction estimate: path step, length, transverse search, inertial starts; the
    /// search segment as a speed-only knob.
    Friction,
    /// The tolerance search: θ and direction sampling steps.
    Tolerance,
    /// Tier 3 DEM: time step, model, tangential history, friction window, active set.
    Dem,
    /// The tiers on one diagram: screen, estimate, DEM (reduced, full), LAMMPS, against the
    /// best reference (the full DEM at a quarter of the default step).
    Tiers,
}

impl Tier {
    /// Every tier, in run order.
    pub const ALL: [Tier; 5] = [
        Tier::ScreenMap,
        Tier::Friction,
        Tier::Tolerance,
        Tier::Dem,
        Tier::Tiers,
    ];

    /// The kebab-case name (file names `work_precision_<name>.csv`).
    pub fn name(self) -> &'static str {
        match self {
            Tier::ScreenMap => "screen-map",
            Tier::Friction => "friction",
            Tier::Tolerance => "tolerance",
            Tier::Dem => "dem",
            Tier::Tiers => "tiers",
        }
    }

    /// The file stem of its CSV and PNG (`work_precision_screen_map`).
    pub fn stem(self) -> String {
        format!("work_precision_{}", self.name().replace('-', "_"))
    }
}
