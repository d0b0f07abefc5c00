//! The accuracy knobs of the work-precision diagrams ([`Knob`]): which knob a row varies is a
//! value of this enum; its name (with the unit of its settings) is text for the CSV and the
//! charts only.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// One accuracy knob of a tier (the tiers diagram's one knob is [`Knob::Tier`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Knob {
    /// The solver model (screen/map: categorical; DEM: reduced, full, full-explicit).
    Model,
    /// Landscape grid points per side.
    GridPoints,
    /// Corrugation path step (µm).
    CorrugationStepUm,
    /// Friction estimate: path step (µm).
    StepUm,
    /// Friction estimate: path length (µm).
    LengthUm,
    /// Friction estimate: the transverse search (µm; on or off).
    TransverseUm,
    /// Friction estimate: inertial starts.
    Starts,
    /// Friction estimate: search segment (µm), a speed-only knob.
    SegmentUm,
    /// Tolerance search: θ sampling step (degrees).
    ThetaStepDeg,
    /// Tolerance search: direction sampling step (degrees).
    DirectionStepDeg,
    /// DEM: time step as a fraction of the stable step.
    DtFraction,
    /// DEM: the tangential history.
    Tangential,
    /// DEM: the friction window's slide time (µs).
    SlideUs,
    /// DEM: the active set, a speed-only knob.
    ActiveSet,
    /// DEM on the study scenes: reduced against full at the default step.
    ModelDefaultStep,
    /// The tiers diagram: each setting a method.
    Tier,
}

impl Knob {
    /// Every knob.
    pub const ALL: [Knob; 16] = [
        Knob::Model,
        Knob::GridPoints,
        Knob::CorrugationStepUm,
        Knob::StepUm,
        Knob::LengthUm,
        Knob::TransverseUm,
        Knob::Starts,
        Knob::SegmentUm,
        Knob::ThetaStepDeg,
        Knob::DirectionStepDeg,
        Knob::DtFraction,
        Knob::Tangential,
        Knob::SlideUs,
        Knob::ActiveSet,
        Knob::ModelDefaultStep,
        Knob::Tier,
    ];

    /// The name with the unit of its settings, as the CSV and the charts print it
    /// (`grid_points`, `step_um`, `segment_um (speed only)`).
    pub fn name(self) -> &'static str {
        match self {
            Knob::Model => "model",
            Knob::GridPoints => "grid_points",
            Knob::CorrugationStepUm => "corrugation_step_um",
            Knob::StepUm => "step_um",
            Knob::LengthUm => "length_um",
            Knob::TransverseUm => "transverse_um",
            Knob::Starts => "starts",
            Knob::SegmentUm => "segment_um (speed only)",
            Knob::ThetaStepDeg => "theta_step_deg",
            Knob::DirectionStepDeg => "direction_step_deg",
            Knob::DtFraction => "dt_fraction_of_stable",
            Knob::Tangential => "tangential",
            Knob::SlideUs => "slide_us",
            Knob::ActiveSet => "active_set (speed only)",
            Knob::ModelDefaultStep => "model (default step)",
            Knob::Tier => "tier",
        }
    }

    /// Whether the knob changes only the speed, never a result (its rows show that nothing
    /// moves).
    pub fn speed_only(self) -> bool {
        matches!(self, Knob::SegmentUm | Knob::ActiveSet)
    }

    /// Which way the knob is refined: `Some(true)` when a larger value is finer (grid points,
    /// path length, inertial starts, slide time), `Some(false)` when a smaller one is (steps,
    /// step fractions); `None` for categorical and speed-only knobs (and the transverse
    /// search, on or off).
    pub fn larger_is_finer(self) -> Option<bool> {
        match self {
            Knob::GridPoints | Knob::LengthUm | Knob::Starts | Knob::SlideUs => Some(true),
            Knob::CorrugationStepUm
            | Knob::StepUm
            | Knob::ThetaStepDeg
            | Knob::DirectionStepDeg
            | Knob::DtFraction => Some(false),
            Knob::Model
            | Knob::TransverseUm
            | Knob::SegmentUm
            | Knob::Tangential
            | Knob::ActiveSet
            | Knob::ModelDefaultStep
            | Knob::Tier => None,
        }
    }
}

impl std::fmt::Display for Knob {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl Serialize for Knob {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> Deserialize<'de> for Knob {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Knob, D::Error> {
        let text = String::deserialize(d)?;
        Knob::ALL
            .into_iter()
            .find(|k| k.name() == text)
            .ok_or_else(|| serde::de::Error::custom(format!("unknown knob `{text}`")))
    }
}
