//! The [`crate::NumericsParams`] part in the deck: the time step, the neighbour skin and the
//! 0 K viscous bath.

use super::{DeckInputs, N};
use std::fmt::Write;

/// The integrator's knobs in deck terms (µs, µm).
#[derive(Debug, Clone, PartialEq)]
pub struct DeckNumerics {
    /// Time step (µs).
    pub dt: f64,
    /// Neighbour skin (µm).
    pub skin: f64,
    /// Viscous damping; `None` = off (τ = ∞).
    pub viscous: Option<DeckViscous>,
}

/// Damping of the 0 K Langevin-equivalent viscous drag, in deck terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckViscous {
    /// γ = m/τ of a slider sphere (pg/µs).
    pub gamma_sphere: f64,
    /// γ of one control sphere / γ of a slider sphere (–).
    pub control_ratio: f64,
    /// γ of a substrate sphere / γ of a slider sphere (–) when the two bodies' sphere sizes
    /// differ; `None` for one size (the substrate takes `gamma_sphere`).
    pub substrate_ratio: Option<f64>,
    /// Relative frame: slider spheres damped relative to the control layer's velocity, the
    /// control layer (x, y) relative to the support's.
    pub relative: bool,
}

/// `timestep` and the load balance.
pub(super) fn timestep(s: &mut String, d: &DeckInputs) {
    w!(s, "timestep        {}", N(d.numerics.dt));
    w!(s, "# equal atom counts per MPI rank in the plane");
    w!(s, "balance         1.0 shift xy 20 1.0");
    w!(s, "");
}
