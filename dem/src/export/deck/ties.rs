//! The slider ties of the [`crate::MountParams`] part: each slider sphere's k_xy and k_z springs
//! to the control layer as two harmonic bonds.

use super::number::N;
use crate::export::layout::{BOND_AXIAL, BOND_LATERAL};
use std::fmt::Write;

/// The springs of [`crate::MountParams`] in deck terms (nN/µm, µm).
#[derive(Debug, Clone, PartialEq)]
pub struct DeckTies {
    /// Lateral tie stiffness k_xy and axial tie stiffness k_z (nN/µm).
    pub k_xy: f64,
    /// See `k_xy`.
    pub k_z: f64,
    /// Axial tie rest length (µm).
    pub tie_length: f64,
    /// Substrate tether stiffness (nN/µm).
    pub k_substrate: f64,
}

/// `bond_style harmonic` and the two bonds' coefficients (`K = k/2`).
pub(super) fn ties(s: &mut String, ties: &DeckTies) {
    w!(s, "# ---- slider ties: bond {BOND_AXIAL} to the axial control sphere {} um above (k_z - k_xy, axial to first", N(ties.tie_length));
    w!(s, "# order), bond {BOND_LATERAL} to the co-located lateral control sphere (k_xy, isotropic, rest length 0);");
    w!(s, "# harmonic bonds are E = K (r - r0)^2, so K = k/2 ----");
    w!(s, "bond_style      harmonic");
    w!(
        s,
        "bond_coeff      {BOND_AXIAL} {} {}",
        N(0.5 * (ties.k_z - ties.k_xy)),
        N(ties.tie_length)
    );
    w!(
        s,
        "bond_coeff      {BOND_LATERAL} {} 0.0",
        N(0.5 * ties.k_xy)
    );
    w!(s, "special_bonds   lj/coul 0.0 0.0 0.0");
    w!(s, "");
}
