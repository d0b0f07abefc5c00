//! What the DEM confirmation stage ([`super::super::confirm`]) returns: each run ([`DemEntry`]), which
//! design it checks, where and with which protocol ([`ConfirmEntry`], [`DemProtocol`]). Types
//! only, below the stages that read them (the answer, the report data).

use crate::study::batch::SlideOutcome;
use serde::{Deserialize, Serialize};

/// The protocol of a confirmation run (`dem.csv`'s `protocol`: `design` or `study`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DemProtocol {
    /// The design's confirmation protocol.
    Design,
    /// The study's protocol (10 + 10 + 300 µs), the protocol check of a shorter one.
    Study,
}

impl std::fmt::Display for DemProtocol {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            DemProtocol::Design => "design",
            DemProtocol::Study => "study",
        })
    }
}

/// One DEM run of the confirmation: which design it checks, where and how.
#[derive(Debug, Clone, PartialEq)]
pub struct ConfirmEntry {
    /// Pattern name.
    pub pattern: String,
    /// Rank of the design within its pattern (1 = best).
    pub rank: usize,
    /// θ of the run (degrees).
    pub theta_deg: f64,
    /// α of the run (degrees from the contact line).
    pub alpha_deg: f64,
    /// Load W (N).
    pub load: f64,
    /// The run's protocol: the design's, or the study's (the protocol check).
    pub protocol: DemProtocol,
    /// θ offset (degrees) from the design for a tolerance-corner run (0: the design itself).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees, substrate frame) for a tolerance-corner run.
    pub direction_offset_deg: f64,
}

/// One DEM confirmation run and what it is compared with.
#[derive(Debug, Clone)]
pub struct DemEntry {
    /// Which design the run checks, where and how.
    pub run: ConfirmEntry,
    /// The run.
    pub outcome: SlideOutcome,
}
