//! [`Equilibrium`]: the result of one quasi-static solve.

use super::Model;
use serde::{Deserialize, Serialize};

/// One touching slider–substrate sphere pair at equilibrium (SI).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ContactInfo {
    /// Slider sphere index (scene order).
    pub slider: u32,
    /// Substrate sphere index (scene order).
    pub substrate: u32,
    /// Contact point: midpoint of the slider and substrate sphere centres `[x, y, z]` (m).
    pub point: [f64; 3],
    /// Overlap δ (m), > 0.
    pub overlap: f64,
    /// Normal (Hertz) force magnitude (N).
    pub force_n: f64,
    /// Vertical component of the normal force on the slider (N).
    pub force_z: f64,
    /// Maximum Hertz pressure p0 (Pa).
    pub p0: f64,
    /// Whether the coating of this contact has failed (p0 > P_crit).
    pub failed: bool,
    /// Upward deflection (m) of the slider sphere against its vertical spring k_z relative to
    /// the rigid body (compliant model: its spring force k_z·deflection balances the sphere's
    /// contact forces); 0 for the rigid models.
    pub deflection: f64,
}

impl ContactInfo {
    /// Unit contact normal `n` (from the substrate sphere centre to the slider sphere centre),
    /// given the substrate sphere centre `[x, y, h]` (m) of this pair (the slider sphere centre
    /// is `2·point − substrate`). The contact force on the slider is `force_n·n`, so
    /// `force_z = force_n·n_z` and its lateral part is `force_n·(n_x, n_y)`. O(1).
    pub fn normal(&self, substrate: [f64; 3]) -> [f64; 3] {
        let d = [
            2.0 * (self.point[0] - substrate[0]),
            2.0 * (self.point[1] - substrate[1]),
            2.0 * (self.point[2] - substrate[2]),
        ];
        let inv = 1.0 / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        [d[0] * inv, d[1] * inv, d[2] * inv]
    }
}

/// Equilibrium of the slider under load W (SI).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Equilibrium {
    /// Model actually used.
    pub model: Model,
    /// Applied load W (N).
    pub load: f64,
    /// Height z (m) of the slider's sphere-centre plane (at its centre) above the substrate's
    /// unperturbed sphere-centre plane. 2R at first touch of an on-top pair.
    pub z: f64,
    /// Tilts `[about x, about y]` (rad): slider sphere i sits at `z + tilt[0]·y_i − tilt[1]·x_i`
    /// relative to the disc centre. Zero for the rigid-z model.
    pub tilt: [f64; 2],
    /// Touching pairs (δ > 0), in slider-then-substrate index order.
    pub contacts: Vec<ContactInfo>,
    /// Largest p0 (Pa) over the contacts (0 if none).
    pub p_max: f64,
    /// Residual ΣF_z − W (N), recomputed from the contact list.
    pub residual: f64,
    /// Iterations the root find took.
    pub iterations: usize,
    /// Moment of the contact forces about the disc centre, about the x and y axes,
    /// `M_c = [Σ F_z·(y − y_c), −Σ F_z·(x − x_c)]` (N·m): the generalized force conjugate to the
    /// tilts `[t_x, t_y]` (a positive `M_c[0]` tilts the slider towards positive t_x).
    pub contact_moment: [f64; 2],
    /// Unbalanced moment `M_c − K_t·t` (N·m) with the mount's rotational stiffness K_t
    /// ([`crate::Scene::tilt_stiffness_at`]): zero to the solver tolerance (`moment_rtol`·W·L)
    /// for rigid-tilt and compliant under a `free` or `springs` mount, where the moment balance
    /// is `M_c = K_t·t`. For rigid-z (t = 0) it equals `M_c`: the moment a locked mount carries,
    /// and the test `Model::Auto` uses to decide whether rigid-z is exact for a tilting mount.
    pub moment_residual: [f64; 2],
}

impl Equilibrium {
    /// Contact number: pairs with δ > 0.
    pub fn contact_count(&self) -> usize {
        self.contacts.len()
    }
    /// Number of contacts whose coating has failed.
    pub fn failed_count(&self) -> usize {
        self.contacts.iter().filter(|c| c.failed).count()
    }
    /// Whether any contact's coating has failed (P_max > P_crit).
    pub fn coating_failed(&self) -> bool {
        self.contacts.iter().any(|c| c.failed)
    }
    /// |ΣF_z − W| / W: relative force-balance residual.
    pub fn residual_rel(&self) -> f64 {
        (self.residual / self.load).abs()
    }
}
