//! [`Body`]: the static description of the slider as a body — site offsets, masses and the
//! control layer's generalized coordinates `q = (Z, t_x, t_y)` with their mass matrix and the
//! mount's rotational stiffness.
//!
//! Small-angle tilt convention (both tiers): slider sphere i at offset `(x_i, y_i)` from the
//! control-layer centre has its z-anchor at `a_i = g_i·q`, `g_i = (1, y_i, −x_i)`. The mass
//! matrix of q is `M = m Σ g_i g_iᵀ` (m: one control sphere, plus one slider sphere with
//! `rigid_z`), the generalized force `Q = Σ F_i^z g_i − (W, 0, 0) − (0, K_t t) − M q̇/τ`, and
//! `q̈ = M⁻¹ Q`. With a locked mount q is Z alone and `M = N m`.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use crate::system::SystemSpec;
use crate::SimParams;

/// Static slider-body data of a run (SI).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Body {
    /// Site offsets `(x_i, y_i)` from the control-layer centre (m).
    pub off: Vec<[f64; 2]>,
    /// Control-layer centre at the start (m).
    pub centre0: [f64; 2],
    /// Mass of one slider sphere (kg).
    pub m_s: f64,
    /// Mass of one substrate sphere (kg).
    pub m_b: f64,
    /// Effective mass of a slider–substrate pair (kg), `m_s m_b/(m_s + m_b)` (`m_s/2` for one
    /// sphere size).
    pub m_eff: f64,
    /// Control-layer mass (kg), the lateral inertia of the layer.
    pub m_cl: f64,
    /// Mass moving with Z (kg): the layer, plus the slider spheres with `rigid_z`.
    pub mz: f64,
    /// Tilt data; `None` with a locked mount.
    pub tilt: Option<Tilt>,
    /// Σ g_i g_iᵀ over every slider site (m⁰, m¹, m²).
    pub g_all: [[f64; 3]; 3],
    /// Largest |x_i| and |y_i| (m).
    pub arm: [f64; 2],
    /// Each sphere's own radius and mass when sizes differ ([`SystemSpec::has_sizes`]);
    /// `None`: one size per body (`m_s`, `m_b`, `m_eff` hold, the one-size arithmetic).
    pub sizes: Option<Sizes>,
}

/// Per-sphere data of a layout whose sphere sizes differ (both bodies filled, the one without
/// a site file with its body's size). SI.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Sizes {
    /// Slider sphere radii r_i (m).
    pub sl_r: Vec<f64>,
    /// Slider sphere masses `ρ 4/3 π r_i³` (kg).
    pub sl_m: Vec<f64>,
    /// Anchor offsets `R − r_i` (m): slider sphere i's z-spring is relaxed that far above the
    /// body's reference anchor `g_i·q` (its top on the slider plate).
    pub sl_dz: Vec<f64>,
    /// Substrate sphere radii r_j (m).
    pub sub_r: Vec<f64>,
    /// Substrate sphere masses (kg).
    pub sub_m: Vec<f64>,
}

impl Sizes {
    /// The per-pair constants of slider sphere `i` and substrate sphere `j`: contact distance
    /// `r_i + r_j` (m), `R_eff = r_i r_j/(r_i + r_j)` (m) and the reduced mass (kg). O(1).
    #[inline]
    pub fn pair(&self, i: usize, j: usize) -> (f64, f64, f64) {
        let (a, b) = (self.sl_r[i], self.sub_r[j]);
        (
            a + b,
            a * b / (a + b),
            crate::model::reduced_mass(self.sl_m[i], self.sub_m[j]),
        )
    }
}

/// The tilt degrees of freedom of the control layer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tilt {
    /// Mass matrix of q (kg, kg·m, kg·m²).
    pub m: [[f64; 3]; 3],
    /// Its inverse.
    pub m_inv: [[f64; 3]; 3],
    /// Rotational stiffness K_t (N·m/rad) on `[t_x, t_y]`.
    pub k: [[f64; 2]; 2],
}

impl Body {
    /// The body of `spec` for `params` (reads `rigid_z`, `control_sphere_radius`).
    pub fn new(spec: &SystemSpec, params: &SimParams) -> Body {
        let n = spec.slider_sites.len();
        let mut c = [0.0; 2];
        for s in &spec.slider_sites {
            c[0] += s[0];
            c[1] += s[1];
        }
        c[0] /= n as f64;
        c[1] /= n as f64;
        let off: Vec<[f64; 2]> = spec
            .slider_sites
            .iter()
            .map(|s| [s[0] - c[0], s[1] - c[1]])
            .collect();
        let m_s = spec.slider_sphere_mass();
        let m_b = spec.substrate_sphere_mass();
        let m_c = spec
            .slider_material
            .sphere_mass(params.mount.control_sphere_radius);
        let m_cl = n as f64 * m_c;
        let sizes = spec.has_sizes().then(|| Sizes::new(spec));
        let mz = match (&sizes, params.mount.rigid_z) {
            (Some(z), true) => m_cl + z.sl_m.iter().sum::<f64>(),
            (None, true) => m_cl + n as f64 * m_s,
            (_, false) => m_cl,
        };
        let mut g_all = [[0.0; 3]; 3];
        let mut arm = [0.0f64; 2];
        for o in &off {
            let g = g_of(*o);
            for a in 0..3 {
                for b in 0..3 {
                    g_all[a][b] += g[a] * g[b];
                }
            }
            arm[0] = arm[0].max(o[0].abs());
            arm[1] = arm[1].max(o[1].abs());
        }
        let tilt = spec.tilt_stiffness.map(|k| {
            Tilt::new(
                k,
                &off,
                sizes.as_ref(),
                &g_all,
                [m_c, m_s],
                params.mount.rigid_z,
            )
        });
        Body {
            off,
            centre0: c,
            m_s,
            m_b,
            m_eff: crate::model::reduced_mass(m_s, m_b),
            m_cl,
            mz,
            tilt,
            g_all,
            arm,
            sizes,
        }
    }
}

impl Sizes {
    /// The per-site sizes of `spec` (one with [`SystemSpec::has_sizes`]): radii, masses and
    /// anchor offsets. O(spheres).
    fn new(spec: &SystemSpec) -> Sizes {
        let n = spec.slider_sites.len();
        let sl_r: Vec<f64> = (0..n).map(|i| spec.slider_radius(i)).collect();
        let sub_r: Vec<f64> = (0..spec.substrate.len())
            .map(|j| spec.substrate_radius(j))
            .collect();
        Sizes {
            sl_m: sl_r
                .iter()
                .map(|&r| spec.slider_material.sphere_mass(r))
                .collect(),
            sl_dz: sl_r
                .iter()
                .map(|&r| spec.slider_sphere_radius - r)
                .collect(),
            sub_m: sub_r
                .iter()
                .map(|&r| spec.substrate_material.sphere_mass(r))
                .collect(),
            sl_r,
            sub_r,
        }
    }
}

impl Tilt {
    /// The tilt data of a layer of rotational stiffness `k` (N·m/rad) over sphere offsets `off`
    /// (m): the mass matrix of q from `[m_c, m_s]` (control, slider sphere masses, kg; with
    /// `rigid_z` and `sizes` each sphere's own), `g_all` = Σ g gᵀ, its inverse.
    fn new(
        k: [[f64; 2]; 2],
        off: &[[f64; 2]],
        sizes: Option<&Sizes>,
        g_all: &[[f64; 3]; 3],
        [m_c, m_s]: [f64; 2],
        rigid_z: bool,
    ) -> Tilt {
        let unit = if rigid_z { m_c + m_s } else { m_c };
        let mut m = [[0.0; 3]; 3];
        match sizes {
            // each sphere moves with the layer in z with its own mass
            Some(z) if rigid_z => {
                for (o, mi) in off.iter().zip(&z.sl_m) {
                    let g = g_of(*o);
                    for a in 0..3 {
                        for b in 0..3 {
                            m[a][b] += (m_c + mi) * g[a] * g[b];
                        }
                    }
                }
            }
            _ => {
                for a in 0..3 {
                    for b in 0..3 {
                        m[a][b] = unit * g_all[a][b];
                    }
                }
            }
        }
        Tilt {
            m,
            m_inv: inverse3(&m),
            k,
        }
    }
}

/// `g = (1, y, −x)` of a site offset `(x, y)`.
#[inline]
pub(crate) fn g_of(o: [f64; 2]) -> [f64; 3] {
    [1.0, o[1], -o[0]]
}

/// Inverse of a symmetric positive definite 3×3 matrix (cofactors).
pub(crate) fn inverse3(m: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let c =
        |r0: usize, r1: usize, c0: usize, c1: usize| m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
    let cof = [
        [c(1, 2, 1, 2), -c(1, 2, 0, 2), c(1, 2, 0, 1)],
        [-c(0, 2, 1, 2), c(0, 2, 0, 2), -c(0, 2, 0, 1)],
        [c(0, 1, 1, 2), -c(0, 1, 0, 2), c(0, 1, 0, 1)],
    ];
    let det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
    let mut inv = [[0.0; 3]; 3];
    for a in 0..3 {
        for b in 0..3 {
            inv[a][b] = cof[b][a] / det;
        }
    }
    inv
}

/// `m·v` for a 3×3 matrix.
#[inline]
pub(crate) fn mat_vec(m: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    [
        m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
        m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
        m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2],
    ]
}

#[inline]
pub(crate) fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_of_a_spd_matrix() {
        let m = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.2], [0.5, 0.2, 2.0]];
        let inv = inverse3(&m);
        for a in 0..3 {
            for b in 0..3 {
                let mut s = 0.0;
                for k in 0..3 {
                    s += m[a][k] * inv[k][b];
                }
                let want = if a == b { 1.0 } else { 0.0 };
                assert!((s - want).abs() < 1e-14, "{a}{b}: {s}");
            }
        }
    }
}
