//! [`DeckDrive`]: the [`crate::ProtocolParams`] part in the deck, the load and the drive (pulling
//! spring K0, support lead, speed, direction).

/// The protocol's load and drive in deck terms (nN, nN/µm, µm, µm/µs).
#[derive(Debug, Clone, PartialEq)]
pub struct DeckDrive {
    /// Friction window: slide steps before the window starts.
    pub window_start: u64,
    /// Load per control sphere (nN, positive = downward).
    pub load_per_control: f64,
    /// Pulling spring K0 (nN/µm).
    pub k0: f64,
    /// Spring rest vector = support lead along α (µm).
    pub lead: f64,
    /// cos α, sin α of the pulling direction.
    pub alpha_cs: [f64; 2],
    /// Support speed (µm/µs).
    pub speed: f64,
    /// Support start position (µm).
    pub support0: [f64; 2],
    /// Atom ID of the support.
    pub support_id: u64,
}
