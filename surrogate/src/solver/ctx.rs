//! [`Ctx`]: what a load-sharing model needs besides the pairs (contact law, substrate, knobs,
//! the mount's tilt stiffness), shared by the pair law and the assembly.

use super::{PairSet, SolverParams};
use crate::contact::Hertz;
use crate::scene::{Coating, Scene};
use std::cell::Cell;

/// What a solve on a *partial* pair list relied on ([`super::path_pairs`]): the list holds every
/// pair whose touch height is above a floor, and a solve is exact (bit-identical to one on every
/// pair) when every height it looked at — the z root's lowest bracket, the tilt working set's
/// floor, and each tilted state lowered by its rim drop `|q₁₂|·gmax` — lies above that floor.
/// The models record the lowest such height (m, relative to z_ref) here.
pub(crate) struct Watch {
    /// Bound on the lever `|g| = |arm|/L` of every slider sphere (the path's, not the list's).
    pub gmax: f64,
    /// Lowest height (m, relative to z_ref) a model relied on since the last reset.
    pub lowest: Cell<f64>,
    /// Warm start of the untilted z root (m, relative to z_ref; NaN: none): the previous
    /// sample's root on a path, or its estimate where that sample continued the tilt model
    /// (moved by the extrapolation of the tilted state; it also places the tilt working set).
    pub guess: Cell<f64>,
    /// The untilted z root last found (m, relative to z_ref; NaN: none); on a sample that
    /// continued the tilt model, its estimate (the guess moved as the tilted height moved).
    pub root: Cell<f64>,
    /// Warm start of the tilt Newton (NaN: none): the previous sample's tilted state
    /// `[ζ, L·t_x, L·t_y]` (m, ζ relative to z_ref) where that sample escalated to the tilt model.
    pub tilt_guess: Cell<[f64; 3]>,
    /// The tilted state last found, likewise (NaN: none, or the untilted state was the answer).
    pub tilt_root: Cell<[f64; 3]>,
}

impl Watch {
    /// A watch for a slider whose levers are bounded by `gmax`.
    pub fn new(gmax: f64) -> Watch {
        Watch {
            gmax,
            lowest: Cell::new(f64::INFINITY),
            guess: Cell::new(f64::NAN),
            root: Cell::new(f64::NAN),
            tilt_guess: Cell::new([f64::NAN; 3]),
            tilt_root: Cell::new([f64::NAN; 3]),
        }
    }
}

/// Per-sphere radii of a scene with per-site sizes (the slow path; `None` in [`Ctx`] for one
/// size per body). Geometry: see [`crate::scene::SiteList`].
pub(crate) struct Sizes {
    /// Radius (m) of each slider sphere (slider order).
    pub slider: Vec<f64>,
    /// Radius (m) of each substrate sphere (substrate order).
    pub substrate: Vec<f64>,
    /// The slider's reference radius R_sl (m): a slider sphere of radius r_i hangs `r_i − R_sl`
    /// below the slider's reference centre plane.
    pub r_sl: f64,
    /// Effective modulus E* (Pa).
    pub e_star: f64,
}

impl Sizes {
    /// The per-sphere radii of `scene`, `None` without per-site sizes. O(N).
    pub fn of(scene: &Scene, n_slider: usize, n_substrate: usize) -> Option<Sizes> {
        if !scene.has_site_sizes() {
            return None;
        }
        let fill = |r: Option<&[f64]>, n: usize, r0: f64| match r {
            Some(r) => r.to_vec(),
            None => vec![r0; n],
        };
        Some(Sizes {
            slider: fill(scene.slider_radii(), n_slider, scene.slider_sphere_radius()),
            substrate: fill(scene.substrate_radii(), n_substrate, scene.sphere_radius),
            r_sl: scene.slider_sphere_radius(),
            e_star: scene.e_star(),
        })
    }

    /// Contact distance `r_i + r_j` (m) of slider sphere `i` and substrate sphere `j`.
    #[inline]
    pub fn distance(&self, i: u32, j: u32) -> f64 {
        self.slider[i as usize] + self.substrate[j as usize]
    }

    /// Hertz law of the pair: `R_eff = r_i r_j/(r_i + r_j)`.
    #[inline]
    pub fn hertz(&self, i: u32, j: u32) -> Hertz {
        let (a, b) = (self.slider[i as usize], self.substrate[j as usize]);
        Hertz {
            e_star: self.e_star,
            r_eff: a * b / (a + b),
        }
    }
}

/// Everything a model needs besides the pairs: the contact law, the substrate, the knobs.
pub(crate) struct Ctx<'a> {
    pub hertz: &'a Hertz,
    /// Contact distance 2R (m); with per-site sizes the largest pair's `max r_i + max r_j`.
    pub two_r: f64,
    /// Per-sphere radii when the scene has per-site sizes (`None`: one size per body).
    pub sizes: Option<&'a Sizes>,
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
    /// Set when the pairs are a partial list ([`Watch`]); `None` for a complete one.
    pub watch: Option<&'a Watch>,
}

impl Ctx<'_> {
    /// Records that the solve relied on every pair touching above height `z` (m, relative to
    /// z_ref) being in the list. O(1); nothing without a [`Watch`].
    #[inline]
    pub fn rely(&self, z: f64) {
        if let Some(w) = self.watch {
            w.lowest.set(w.lowest.get().min(z));
        }
    }

    /// [`Ctx::rely`] for the tilted state `q = [ζ, L·t_x, L·t_y]`: a pair of touch height c
    /// touches there iff `c − q₁₂·g > ζ`, so every pair above `ζ − |q₁₂|·gmax` counts.
    #[inline]
    pub fn rely_tilted(&self, q: [f64; 3]) {
        if let Some(w) = self.watch {
            self.rely(q[0] - q[1].hypot(q[2]) * w.gmax);
        }
    }

    /// The bound on every pair's lever `|g|` the tilt working set uses: the watch's (a partial
    /// list's slider positions are only those of its pairs), else [`Ctx::max_lever`].
    pub fn lever_bound(&self, ps: &PairSet) -> f64 {
        match self.watch {
            Some(w) => w.gmax,
            None => self.max_lever(ps),
        }
    }

    /// Bound on the lever `|g| = |arm|/L` of every pair of `ps`: the largest slider-sphere
    /// distance from the disc centre over L (plus round-off). O(slider spheres).
    pub fn max_lever(&self, ps: &PairSet) -> f64 {
        let mut r2: f64 = 0.0;
        for p in &ps.slider_xy {
            let (dx, dy) = (p[0] - ps.centre[0], p[1] - ps.centre[1]);
            r2 = r2.max(dx * dx + dy * dy);
        }
        r2.sqrt() / self.scale * (1.0 + 1e-12)
    }

    /// Hertz law of slider sphere `i` on substrate sphere `j` (the scene's one law without
    /// per-site sizes). O(1).
    #[inline]
    pub fn pair_hertz(&self, i: u32, j: u32) -> Hertz {
        match self.sizes {
            None => *self.hertz,
            Some(s) => s.hertz(i, j),
        }
    }

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
