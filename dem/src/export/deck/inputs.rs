//! [`DeckInputs`]: everything the deck needs, one part a field.

use super::contacts::DeckContact;
use super::control::DeckControl;
use super::drive::DeckDrive;
use super::numerics::DeckNumerics;
use super::ties::DeckTies;
use crate::export::deck_sizes::DeckSizes;
use crate::export::meta::Steps;

/// Everything the deck needs, in LAMMPS micro units (µm, µs, pg, nN, 10³ Pa, nN/µm), one
/// field per part of the model.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckInputs {
    /// Header lines (without `#`), e.g. the scene and the command.
    pub header: Vec<String>,
    /// Step counts.
    pub steps: Steps,
    /// Time step, skin, viscous bath ([`crate::NumericsParams`]).
    pub numerics: DeckNumerics,
    /// The contact law ([`crate::ContactParams`] and the materials).
    pub contact: DeckContact,
    /// The slider ties and substrate tethers ([`crate::MountParams`]).
    pub ties: DeckTies,
    /// The control layer: the scene's mount, halves, θ.
    pub control: DeckControl,
    /// Load and drive ([`crate::ProtocolParams`]).
    pub drive: DeckDrive,
    /// Per-site sphere sizes (then `contact_distance` is the largest radius sum, for the
    /// communication cutoff); `None`: one size per body.
    pub sizes: Option<DeckSizes>,
}
