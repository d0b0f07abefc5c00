//! The rows of a landscape: [`LandscapeRow`] (Δz at one shift) and [`LandscapeZRow`] (the
//! exact z of a shard or spill file).

use super::format::{clean, de_exact_um, ser_exact_um};
use serde::{Deserialize, Serialize};
use surrogate::units::{m_to_nm, m_to_um};

/// One grid point of a Δz landscape.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LandscapeRow {
    /// Shift x of the slider centre from its default placement (µm).
    pub x_um: f64,
    /// Shift y (µm).
    pub y_um: f64,
    /// Δz = z − min z over the grid (nm).
    pub dz_nm: f64,
}

impl LandscapeRow {
    /// The row of shift `shift` (m) with `dz` (m).
    pub fn new(shift: [f64; 2], dz: f64) -> LandscapeRow {
        LandscapeRow {
            x_um: clean(m_to_um(shift[0])),
            y_um: clean(m_to_um(shift[1])),
            dz_nm: m_to_nm(dz),
        }
    }
}

/// One grid point's equilibrium height z (not yet Δz): the row of a landscape shard and of the
/// landscape's spill file. Δz = z − min z needs the minimum over the whole grid, so a shard
/// writes z, exactly ([`exact_um`](super::exact_um)), and `superlube merge` (or the landscape's second pass)
/// turns the z rows of the whole grid into [`LandscapeRow`]s.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LandscapeZRow {
    /// Shift x of the slider centre from its default placement (µm).
    pub x_um: f64,
    /// Shift y (µm).
    pub y_um: f64,
    /// Equilibrium height z (m), written in µm as the exact decimal of [`exact_um`](super::exact_um).
    #[serde(
        rename = "z_um",
        serialize_with = "ser_exact_um",
        deserialize_with = "de_exact_um"
    )]
    pub z: f64,
}

impl LandscapeZRow {
    /// The row of shift `shift` (m) with height `z` (m).
    pub fn new(shift: [f64; 2], z: f64) -> LandscapeZRow {
        LandscapeZRow {
            x_um: clean(m_to_um(shift[0])),
            y_um: clean(m_to_um(shift[1])),
            z,
        }
    }

    /// The Δz row of this point, given the grid's min z (m).
    pub fn dz_row(&self, z_min: f64) -> LandscapeRow {
        LandscapeRow {
            x_um: self.x_um,
            y_um: self.y_um,
            dz_nm: m_to_nm(self.z - z_min),
        }
    }
}
