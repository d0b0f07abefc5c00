//! [`Mount`]: the implicit step of the slider mount's linear z network (full model with
//! [`crate::MountParams::implicit_mount`]).
//!
//! The network: each slider sphere i on its k_z spring to its anchor `g_i·q` on the control
//! layer (`q = (Z, t_x, t_y)`, `g_i = (1, y_i, −x_i)`), the spheres' damping `−m_s(ż_i − r g_i·q̇)/τ`
//! (r = 1 in the relative damping frame), the layer's mass matrix M, its damping `−M q̇/τ`, the
//! mount springs K_t on the tilts and the load W. It is linear, so it can be advanced stably at
//! any step; only the contact forces are explicit. One step (Strang split):
//!
//! `K_c(dt/2) · D(dt/2) · C(dt) · D(dt/2) · K_c(dt/2)`
//!
//! - K_c: half kick of the sphere z velocities with their contact forces (the first one here,
//!   the second in the force pass);
//! - D: the damping alone, exactly: `q̇ ← e q̇`, `ż_i ← e (ż_i + r (h/τ) g_i·q̇)`, `e = e^{−h/τ}`
//!   (so a fast mode decays at the right rate however large ω·dt);
//! - C: the springs and the load by the trapezoidal (implicit-midpoint) rule, which keeps the
//!   energy of each mode, sits a sphere under a constant force exactly at F/k_z, and turns a
//!   mode by `2·atan(ω dt/2) < π` per step (no resonance with the contact kicks, whose step
//!   limit stays `ω_contact·dt < 2`). With the mean velocities ū as unknowns:
//!   `(2m_s + γ) ū_i − γ g_i·U = 2m_s ż_i + dt k_z (g_i·q − z_i)` per sphere (γ = dt² k_z/2),
//!   the same for the common mode of the free spheres (weight `G_in = Σ_in g gᵀ`), and for the
//!   layer `(2M + (dt²/2)(k_z G_all + K_t)) U − γ (Σ g_i ū_i + G_in ū_W) = 2M q̇ + dt F_q`.
//!   The spheres couple only to q (a star), so eliminating them leaves the 3×3 Schur complement
//!   `S = 2M + γ (2m_s/(2m_s + γ)) G_all + (dt²/2) K_t`, which does not depend on the active set
//!   (`G_act + G_in = G_all`) and is inverted once. Then `x ← x + dt ū`, `v ← 2ū − v`.
//!
//! Cost per step: two serial passes over the active slider spheres (a few flops each) and a
//! 3×3 product; the sums run in sphere order, so the result does not depend on the thread
//! count. The deviations of ringing free spheres get the same map (`ring.rs`), so the active set
//! stays exact to round-off.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, g_of, inverse3, mat_vec, Body, Sizes};
use super::kernel::Index;
use crate::params::DampingFrame;
use crate::system::{Active, State};
use crate::SimParams;

/// The constant data of the implicit mount step for one `dt` (SI).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Mount {
    /// γ = dt² k_z / 2 (kg).
    gamma: f64,
    /// 2 m_s + γ (kg).
    a: f64,
    /// Mass matrix of q (locked mount: `diag(M_z, 1, 1)`, the last two unused).
    m: [[f64; 3]; 3],
    /// K_t in the tilt block of a 3×3 (N·m/rad); zero with a locked mount.
    kt: [[f64; 3]; 3],
    /// Inverse of the Schur complement S (see the module doc).
    s_inv: [[f64; 3]; 3],
    /// e^{−h/τ} (1 without damping).
    decay: f64,
    /// r·h/τ: the pull of the layer's velocity in the relative damping frame (0 otherwise).
    drag: f64,
    /// Whether q has tilt components.
    tilting: bool,
    /// With per-sphere sizes, each slider sphere's own `a_i = 2 m_i + γ` (kg), in global
    /// order: its row `(2m_i + γ) ū_i − γ g_i·U = 2m_i ż_i + dt k_z (g_i·q + (R − r_i) − z_i)`
    /// and its share `γ (2m_i/a_i) g_i g_iᵀ` of S. `None`: one mass (`a`).
    a_each: Option<Vec<f64>>,
}

impl Mount {
    /// The step data for `body`, `params` and step `dt` (s). Cost O(1).
    pub fn new(body: &Body, params: &SimParams, dt: f64) -> Mount {
        let n = body.off.len() as f64;
        let m_s = body.m_s;
        let kz = params.mount.k_slider_z;
        let gamma = 0.5 * dt * dt * kz;
        let a = 2.0 * m_s + gamma;
        let (m, kt, g_all, tilting) = match &body.tilt {
            Some(t) => {
                let mut kt = [[0.0; 3]; 3];
                for r in 0..2 {
                    for c in 0..2 {
                        kt[r + 1][c + 1] = t.k[r][c];
                    }
                }
                (t.m, kt, body.g_all, true)
            }
            None => {
                let m = [[body.mz, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
                let mut g = [[0.0; 3]; 3];
                g[0][0] = n;
                (m, [[0.0; 3]; 3], g, false)
            }
        };
        let mut s = [[0.0; 3]; 3];
        // γ(1 − γ/a) = γ·2m_s/a, written without the cancellation
        let c = gamma * 2.0 * m_s / a;
        for r in 0..3 {
            for k in 0..3 {
                s[r][k] = 2.0 * m[r][k] + c * g_all[r][k] + 0.5 * dt * dt * kt[r][k];
            }
        }
        let a_each = body.sizes.as_ref().map(|z| {
            // S = 2M + Σ_i γ (2m_i/a_i) g_i g_iᵀ + (dt²/2) K_t
            let mut g_w = [[0.0; 3]; 3];
            let a_each: Vec<f64> = z.sl_m.iter().map(|mi| 2.0 * mi + gamma).collect();
            for ((o, mi), ai) in body.off.iter().zip(&z.sl_m).zip(&a_each) {
                let g = if tilting { g_of(*o) } else { [1.0, 0.0, 0.0] };
                let w = gamma * 2.0 * mi / ai;
                for r in 0..3 {
                    for k in 0..3 {
                        g_w[r][k] += w * g[r] * g[k];
                    }
                }
            }
            for r in 0..3 {
                for k in 0..3 {
                    s[r][k] = 2.0 * m[r][k] + g_w[r][k] + 0.5 * dt * dt * kt[r][k];
                }
            }
            a_each
        });
        let t = params.numerics.damping_time;
        let inv_tau = if t.is_finite() && t > 0.0 {
            1.0 / t
        } else {
            0.0
        };
        let h = 0.5 * dt;
        let rel = params.numerics.damping_frame == DampingFrame::Relative;
        Mount {
            gamma,
            a,
            m,
            kt,
            s_inv: inverse3(&s),
            decay: (-h * inv_tau).exp(),
            drag: if rel { h * inv_tau } else { 0.0 },
            tilting,
            a_each,
        }
    }

    /// `g` of a site offset as the mount sees it (`(1, 0, 0)` with a locked mount).
    #[inline]
    fn g(&self, o: [f64; 2]) -> [f64; 3] {
        if self.tilting {
            g_of(o)
        } else {
            [1.0, 0.0, 0.0]
        }
    }

    /// Keeps the tilt components only when q has them.
    #[inline]
    fn mask(&self, v: [f64; 3]) -> [f64; 3] {
        if self.tilting {
            v
        } else {
            [v[0], 0.0, 0.0]
        }
    }

    /// `D(h)` of a sphere-like z velocity `v` whose anchor moves at `g·q̇ = vq`.
    #[inline]
    fn damp(&self, v: f64, vq: f64) -> f64 {
        self.decay * (v + self.drag * vq)
    }

    /// `K_c(h)·D(h)·C(dt)·D(h)` of the mount network (module doc) at step `dt` (s): the z state
    /// of the active slider spheres, of the common mode and of the ringing aggregate, and the
    /// layer's Z and tilts, in `state`. The second contact half kick is the force pass's.
    /// `idx`: the active set's index (the inactive spheres' weight `G_in`).
    pub(crate) fn step(
        &self,
        dt: f64,
        body: &Body,
        params: &SimParams,
        idx: &Index,
        state: &mut State,
    ) {
        let mt = self;
        let h = 0.5 * dt;
        let m_s = body.m_s;
        let hm = h / m_s;
        let kz = params.mount.k_slider_z;
        let load = params.protocol.load;
        let off = &body.off;
        let g_in = if mt.tilting {
            idx.g_in
        } else {
            let mut g = [[0.0; 3]; 3];
            g[0][0] = idx.n_in as f64;
            g
        };
        let s = state;
        let q0 = [s.cl_x[2], s.tilt[0], s.tilt[1]];
        let qd_in = mt.mask([s.cl_v[2], s.tilt_v[0], s.tilt_v[1]]);
        // D(h) of the layer (absolute damping)
        let qd0 = qd_in.map(|v| mt.decay * v);
        // active spheres: K_c(h), D(h); the sums Σ g (z − g·q) and Σ g rhs
        let a = &mut s.act;
        // with per-sphere sizes: each sphere's mass, a_i and anchor offset; r_sum then holds
        // Σ g rhs/a_i (the one-mass path divides by a once, below)
        let sized = body.sizes.as_ref().zip(mt.a_each.as_deref());
        let (e_sum, r_sum) = mt.sphere_sums(a, off, sized, [dt, hm, kz, m_s], q0, qd_in);
        // common mode of the free spheres (w relative, s absolute) and the ringing aggregate
        let c = &mut s.common;
        let mut rhs_w = [0.0; 3];
        let mut ud = [0.0; 3];
        let mut dz_mid = [0.0; 3];
        for r in 0..3 {
            c.s[r] = mt.damp(c.s[r], qd_in[r]);
            rhs_w[r] = 2.0 * m_s * c.s[r] - dt * kz * c.w[r];
            c.dzv[r] *= mt.decay;
            ud[r] = (2.0 * m_s * c.dzv[r] - dt * kz * c.dz[r]) / mt.a;
            dz_mid[r] = c.dz[r] + h * ud[r];
        }
        // the layer: F_q at the start (with the aggregate at the midpoint), then U = S⁻¹ RHS
        let gw = mat_vec(&g_in, c.w);
        let dz_mid = mt.mask(dz_mid);
        let ktq = mat_vec(&mt.kt, q0);
        let mqd = mat_vec(&mt.m, qd0);
        let gr = mat_vec(&g_in, rhs_w);
        let mut rhs = [0.0; 3];
        for r in 0..3 {
            let f = kz * (e_sum[r] + gw[r] + dz_mid[r]) - ktq[r] - if r == 0 { load } else { 0.0 };
            rhs[r] = 2.0 * mqd[r]
                + dt * f
                + match sized {
                    None => mt.gamma / mt.a * (r_sum[r] + gr[r]),
                    // no free spheres (the active set is off with per-sphere sizes)
                    Some(_) => mt.gamma * r_sum[r],
                };
        }
        let u = mt.mask(mat_vec(&mt.s_inv, mt.mask(rhs)));
        let mut qd1 = [0.0; 3];
        for r in 0..3 {
            qd1[r] = 2.0 * u[r] - qd0[r];
        }
        // back-substitution: spheres, common mode, aggregate; then D(h)
        mt.back_substitute(&mut s.act, off, sized, [dt, m_s, kz], q0, u, qd1);
        let c = &mut s.common;
        for r in 0..3 {
            let uw = (rhs_w[r] + mt.gamma * u[r]) / mt.a;
            c.w[r] += dt * (uw - u[r]);
            c.s[r] = mt.damp(2.0 * uw - c.s[r], qd1[r]);
            c.dz[r] += dt * ud[r];
            c.dzv[r] = mt.decay * (2.0 * ud[r] - c.dzv[r]);
        }
        s.cl_x[2] = q0[0] + dt * u[0];
        s.cl_v[2] = mt.decay * qd1[0];
        if mt.tilting {
            for r in 0..2 {
                s.tilt[r] = q0[r + 1] + dt * u[r + 1];
                s.tilt_v[r] = mt.decay * qd1[r + 1];
            }
        }
    }

    /// The active spheres' `K_c(h)`, `D(h)` of their z velocities, and the sums Σ g (z − g·q)
    /// and Σ g rhs (Σ g rhs/a_i with per-sphere sizes `sized`). `c`: dt (s), h/m (s/kg), k_z
    /// (N/m), m (kg); `q0`, `qd_in`: the layer's z state at the start.
    #[inline]
    fn sphere_sums(
        &self,
        a: &mut Active,
        off: &[[f64; 2]],
        sized: Option<(&Sizes, &[f64])>,
        [dt, hm, kz, m_s]: [f64; 4],
        q0: [f64; 3],
        qd_in: [f64; 3],
    ) -> ([f64; 3], [f64; 3]) {
        let mt = self;
        let h = 0.5 * dt;
        let (mut e_sum, mut r_sum) = ([0.0; 3], [0.0; 3]);
        for k in 0..a.sl.len() {
            let i = a.sl[k] as usize;
            let g = mt.g(off[i]);
            let v = &mut a.sl_v[k][2];
            match sized {
                None => {
                    *v = mt.damp(*v + hm * a.sl_f[k][2], dot3(g, qd_in));
                    let dz = a.sl_x[k][2] - dot3(g, q0);
                    let rhs = 2.0 * m_s * *v - dt * kz * dz;
                    for r in 0..3 {
                        e_sum[r] += g[r] * dz;
                        r_sum[r] += g[r] * rhs;
                    }
                }
                Some((z, ae)) => {
                    let mi = z.sl_m[i];
                    *v = mt.damp(*v + h / mi * a.sl_f[k][2], dot3(g, qd_in));
                    let dz = a.sl_x[k][2] - dot3(g, q0) - z.sl_dz[i];
                    let rhs = (2.0 * mi * *v - dt * kz * dz) / ae[i];
                    for r in 0..3 {
                        e_sum[r] += g[r] * dz;
                        r_sum[r] += g[r] * rhs;
                    }
                }
            }
        }
        (e_sum, r_sum)
    }

    /// The active spheres' back-substitution: z and its velocity from the layer's `u`, then
    /// `D(h)` against the layer's new `qd1`. `c`: dt (s), m (kg), k_z (N/m).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn back_substitute(
        &self,
        a: &mut Active,
        off: &[[f64; 2]],
        sized: Option<(&Sizes, &[f64])>,
        [dt, m_s, kz]: [f64; 3],
        q0: [f64; 3],
        u: [f64; 3],
        qd1: [f64; 3],
    ) {
        let mt = self;
        for k in 0..a.sl.len() {
            let i = a.sl[k] as usize;
            let g = mt.g(off[i]);
            let (x, v) = (&mut a.sl_x[k][2], &mut a.sl_v[k][2]);
            let ub = match sized {
                None => {
                    let rhs = 2.0 * m_s * *v - dt * kz * (*x - dot3(g, q0));
                    (rhs + mt.gamma * dot3(g, u)) / mt.a
                }
                Some((z, ae)) => {
                    let rhs = 2.0 * z.sl_m[i] * *v - dt * kz * (*x - dot3(g, q0) - z.sl_dz[i]);
                    (rhs + mt.gamma * dot3(g, u)) / ae[i]
                }
            };
            *x += dt * ub;
            *v = mt.damp(2.0 * ub - *v, dot3(g, qd1));
        }
    }
}
