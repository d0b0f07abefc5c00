//! The [`crate::NumericsParams`] part in the deck: the time step, the neighbour skin and the
//! 0 K viscous bath.

use super::number::N;
use crate::export::deck_sizes::DeckSizes;
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
pub(super) fn timestep(s: &mut String, numerics: &DeckNumerics) {
    w!(s, "timestep        {}", N(numerics.dt));
    w!(s, "# equal atom counts per MPI rank in the plane");
    w!(s, "balance         1.0 shift xy 20 1.0");
    w!(s, "");
}

/// The viscous bath's fixes: `fix viscous` with a γ per type (per-site sizes: one per size),
/// and in the relative frame the slider's add-back of γ·v_control; a comment when τ = ∞.
pub(super) fn viscous(s: &mut String, numerics: &DeckNumerics, sizes: Option<&DeckSizes>) {
    match numerics.viscous {
        Some(v) if sizes.is_some() => {
            let z = sizes.unwrap();
            crate::export::deck_sizes::viscous(s, z, v.gamma_sphere * v.control_ratio, v.relative);
        }
        Some(v) => {
            w!(
                s,
                "# 0 K Langevin-equivalent damping F = -m v / tau (gamma = m/tau per type)"
            );
            let sub = match v.substrate_ratio {
                Some(r) => format!(" scale 1 {}", N(r)),
                None => String::new(),
            };
            w!(
                s,
                "fix             visc damped viscous {}{sub} scale 3 {} scale 4 {}",
                N(v.gamma_sphere),
                N(v.control_ratio),
                N(v.control_ratio)
            );
            if v.relative {
                w!(s, "# relative frame (the Rust default): slider spheres are damped relative to the control layer's");
                w!(s, "# velocity: add back gamma * v_control");
                w!(s, "compute         vctrl ctrl reduce ave vx vy vz   # = vcm (equal masses), once per step");
                w!(
                    s,
                    "variable        rvx equal {}*c_vctrl[1]",
                    N(v.gamma_sphere)
                );
                w!(
                    s,
                    "variable        rvy equal {}*c_vctrl[2]",
                    N(v.gamma_sphere)
                );
                w!(
                    s,
                    "variable        rvz equal {}*c_vctrl[3]",
                    N(v.gamma_sphere)
                );
                w!(s, "fix             relsl slider addforce v_rvx v_rvy v_rvz");
            }
        }
        None => {
            w!(s, "# no viscous damping (tau = infinity)");
        }
    }
}
