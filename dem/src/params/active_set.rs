//! [`ActiveSetParams`]: which particles are integrated — the exact reductions (pruning the
//! unreachable substrate, the active set) and their margins.

use serde::{Deserialize, Serialize};

/// The exact reductions of a run (both exact to round-off; docs/validation/dem-engine.md).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ActiveSetParams {
    /// Reduction (a): leave out substrate spheres farther than `slider radius + 2R + prune_margin`
    /// from the slider centre's path (start → start + travel along α).
    pub prune_substrate: bool,
    /// Extra margin (m) of reduction (a).
    pub prune_margin: f64,
    /// Active set (exact to round-off): integrate step by step only the particles in or near
    /// contact; the rest follow their rest state (substrate: tether site; slider: its site on
    /// the control layer plus the common relative motion of all free slider spheres) plus, while
    /// they ring down after a contact, an exactly propagated deviation. See `docs/validation/dem-engine.md`.
    /// With per-site sphere sizes every sphere of a body whose sizes differ stays in the set (the
    /// common mode and the ringing maps take one mass).
    #[serde(rename = "active_set")]
    pub enabled: bool,
    /// Activation margin (m): a slider–substrate pair is integrated while its gap
    /// (centre distance − 2R) is below this; the set is re-evaluated as soon as some particle
    /// has moved `margin/2` since the last evaluation, so no pair can touch unnoticed.
    #[serde(rename = "active_margin")]
    pub margin: f64,
}

impl Default for ActiveSetParams {
    fn default() -> Self {
        ActiveSetParams {
            prune_substrate: false,
            prune_margin: 3e-6,
            enabled: false,
            margin: 20e-9,
        }
    }
}
