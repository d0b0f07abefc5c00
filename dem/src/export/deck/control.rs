//! The control layer in the deck: the scene's mount (locked, free, springs) as a LAMMPS rigid
//! body with its torques on or off, its halves' distances and the slider's rotation θ.

use super::number::on;
use std::fmt::Write;

/// How the control layer may tilt, in deck terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DeckMount {
    /// `fix rigid` with every torque component off: translation only.
    Locked,
    /// `fix rigid` with torque about x and y on.
    Free,
    /// As `Free`, plus `fix spring couple` of stiffness `k1` (nN/µm) in z between the opposing
    /// half-layers.
    Springs {
        /// K1 (nN/µm).
        k1: f64,
    },
}

/// The control layer's geometry and mount in deck terms.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckControl {
    /// Mount.
    pub mount: DeckMount,
    /// Half-layer distances `[d_x, d_y]` (µm), slider frame.
    pub half_distance: [f64; 2],
    /// cos θ, sin θ of the slider rotation.
    pub theta_cs: [f64; 2],
}

/// `fix rigid` of the control layer: held laterally (`hold`) or free in x and y, torques about
/// x and y on where the mount `tilts`.
pub(super) fn rigid(s: &mut String, hold: bool, tilts: bool) {
    let _ = writeln!(
        s,
        "fix             rig ctrl rigid single force * {} {} on torque * {} {} off",
        on(!hold),
        on(!hold),
        on(tilts),
        on(tilts)
    );
}
