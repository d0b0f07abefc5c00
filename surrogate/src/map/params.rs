//! [`MapParams`]: every numerical knob of the landscape and corrugation computations.

use serde::{Deserialize, Serialize};

/// Numerical knobs of [`super::compute_landscape`] and the corrugation paths (SI).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MapParams {
    /// Grid points per cell side N (both cell edges included, so N ≥ 2). Study: 51.
    pub grid: usize,
    /// Sliding distance of a corrugation path (m). Study: 30 µm.
    pub distance: f64,
    /// Sampling step along a corrugation path (m). Default 0.05 µm (601 solves per 30 µm path).
    pub step: f64,
    /// Largest multiple of the primitive vectors searched for a rectangular repeat cell.
    pub max_cell_mult: i32,
    /// Relative tolerance selecting the first reciprocal shell of a lattice (contact lines).
    pub shell_rtol: f64,
    /// Moiré wave vectors shorter than this fraction of the shortest reciprocal vector count as
    /// zero (commensurate first shells: no contact line, fall back to the substrate row).
    pub q_zero_rtol: f64,
    /// Length (m) of path sharing one refresh of the pair list, twelve of them one candidate
    /// search (speed only: results agree to the solver's tolerance for any value > 0;
    /// validation/path-solve.md). Default 0.5 µm.
    pub segment: f64,
}

impl Default for MapParams {
    fn default() -> Self {
        MapParams {
            grid: 51,
            distance: 30e-6,
            step: 0.05e-6,
            max_cell_mult: 4,
            shell_rtol: 1e-6,
            q_zero_rtol: 1e-6,
            segment: 0.5e-6,
        }
    }
}
