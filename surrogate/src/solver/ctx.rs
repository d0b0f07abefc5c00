//! [`Ctx`]: what a load-sharing model needs besides the pairs (contact law, substrate, knobs,
//! the mount's tilt stiffness), shared by the pair law and the assembly.

use super::SolverParams;
use crate::contact::Hertz;
use crate::scene::Coating;

/// Everything a model needs besides the pairs: the contact law, the substrate, the knobs.
pub(crate) struct Ctx<'a> {
    pub hertz: &'a Hertz,
    /// Contact distance 2R (m).
    pub two_r: f64,
    pub coating: &'a Coating,
    /// Substrate sphere centres `[x, y, h]` (m).
    pub substrate: &'a [[f64; 3]],
    pub params: &'a SolverParams,
    /// Length scale L (m) of the tilt unknowns: the slider radius (≥ sphere radius).
    pub scale: f64,
    /// Whether the mount lets the slider tilt (`free`, `springs`; not `locked`).
    pub tilts: bool,
    /// Rotational stiffness tensor K_t (N·m/rad, lab frame, at this pose's θ) of the mount,
    /// acting on `[t_x, t_y]`. Zero for `free` and `locked`.
    pub kt: [[f64; 2]; 2],
}

impl Ctx<'_> {
    /// The mount stiffness in the scaled tilt unknowns `q₁₂ = L·t`: `K_q = K_t / L²` (N/m), so
    /// that the stored energy is `½ q₁₂ᵀ K_q q₁₂ = ½ tᵀ K_t t`.
    pub fn kq(&self) -> [[f64; 2]; 2] {
        let l2 = self.scale * self.scale;
        self.kt.map(|r| r.map(|v| v / l2))
    }

    /// The moment `K_t·t` (N·m) the mount exerts against the tilts `t` (rad).
    pub fn mount_moment(&self, t: [f64; 2]) -> [f64; 2] {
        [
            self.kt[0][0] * t[0] + self.kt[0][1] * t[1],
            self.kt[1][0] * t[0] + self.kt[1][1] * t[1],
        ]
    }
}
