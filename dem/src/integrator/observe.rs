//! What can be read from a running [`Sim`]: observables, the total energy, the sanity checks
//! that stop a run with a true message, and full snapshots of every particle.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, g_of, mat_vec};
use super::kernel::spring_stretch;
use super::sim::{Observables, Sim};
use crate::model::NormalModel;
use crate::DemError;

/// Every particle's position (m) at the current step, the inactive ones included.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Substrate sphere centres `[x, y, h]`.
    pub substrate: Vec<[f64; 3]>,
    /// Slider sphere centres.
    pub slider: Vec<[f64; 3]>,
    /// Whether each substrate / slider sphere has a failed contact now.
    pub failed_substrate: Vec<bool>,
    /// Same for slider spheres.
    pub failed_slider: Vec<bool>,
}

impl Sim {
    /// Observables of the current state (uses the pair results of the last force evaluation).
    /// O(n + p) over the active particles, sequential.
    pub fn observe(&self) -> Observables {
        let s = &self.state;
        let mut o = Observables {
            t: s.t,
            tilt: s.tilt,
            active_slider: s.act.sl.len(),
            active_substrate: s.act.sub.len(),
            ..Default::default()
        };
        for (k, r) in s.act.out.iter().enumerate() {
            if r.delta > 0.0 {
                o.contacts += 1;
                o.failed += r.failed as usize;
                o.p_max = o.p_max.max(r.p0);
                o.contact_fz += r.force[2];
            }
            o.max_overlap = o.max_overlap.max(r.delta);
            o.ever_failed += s.act.hist[k].ever_failed as usize;
        }
        o.ever_failed += self.idx.ever_failed_inactive;
        o.p_max_peak = s.p0_peak.max(o.p_max);
        let mut zsum = s.act.sl_x.iter().map(|x| x[2]).sum::<f64>();
        if self.idx.n_in > 0 {
            let mut qw = self.q();
            if !self.params.mount.rigid_z {
                for k in 0..3 {
                    qw[k] += s.common.w[k];
                }
            }
            zsum += dot3(self.idx.s_in, qw);
            if !self.params.mount.rigid_z {
                zsum += s.common.dz[0];
            }
        }
        if let Some(z) = &self.body.sizes {
            // the body's reference height: each centre less its anchor offset R − r_i
            zsum -= z.sl_dz.iter().sum::<f64>();
        }
        o.z = zsum / s.sl_x.len() as f64;
        let (sa, ca) = self.params.protocol.alpha.sin_cos();
        if s.spring_on {
            let d = [s.support[0] - s.cl_x[0], s.support[1] - s.cl_x[1]];
            o.spring_force = self.params.protocol.k0
                * (d[0] * ca + d[1] * sa - self.params.protocol.support_lead);
            let ds = [s.support[0] - s.support0[0], s.support[1] - s.support0[1]];
            o.support_travel = ds[0] * ca + ds[1] * sa;
            let dc = [
                s.cl_x[0] - (s.support0[0] - self.params.protocol.support_lead * ca),
                s.cl_x[1] - (s.support0[1] - self.params.protocol.support_lead * sa),
            ];
            o.slider_travel = dc[0] * ca + dc[1] * sa;
        }
        o
    }

    /// Observables of the current state ([`Sim::observe`]) and a fresh start of the peak
    /// pressure: `p_max_peak` is the largest p0 since the previous call (or the run's start),
    /// and the next call's peak starts from here. What each time-series sample takes. O(n + p).
    pub fn observe_sample(&mut self) -> Observables {
        let o = self.observe();
        self.state.p0_peak = 0.0;
        o
    }

    /// Total mechanical energy (J): kinetic, Hertz, slider springs, tethers, mount springs,
    /// load potential (`W·Z`) and pulling spring, inactive particles included. Tangential
    /// spring energy is not included (exact for μ = 0).
    pub fn energy(&self) -> f64 {
        let s = &self.state;
        let p = &self.params;
        let m = self.body.m_s;
        let rigid = p.mount.rigid_z;
        let a = &s.act;
        let mut e = 0.0;
        let sizes = self.body.sizes.as_ref();
        for (v, j) in a.sub_v.iter().zip(&a.sub) {
            let mb = sizes.map_or(self.body.m_b, |z| z.sub_m[*j as usize]);
            e += 0.5 * mb * (v[0] * v[0] + v[1] * v[1]);
        }
        for (v, i) in a.sl_v.iter().zip(&a.sl) {
            let vz = if rigid { 0.0 } else { v[2] * v[2] };
            let m = sizes.map_or(m, |z| z.sl_m[*i as usize]);
            e += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + vz);
        }
        let q = self.q();
        let qd = self.qdot();
        e += 0.5 * self.body.m_cl * (s.cl_v[0].powi(2) + s.cl_v[1].powi(2));
        match &self.body.tilt {
            None => e += 0.5 * self.body.mz * s.cl_v[2].powi(2),
            Some(t) => {
                e += 0.5 * dot3(qd, mat_vec(&t.m, qd));
                let k = &t.k;
                let tv = s.tilt;
                e += 0.5
                    * (tv[0] * (k[0][0] * tv[0] + k[0][1] * tv[1])
                        + tv[1] * (k[1][0] * tv[0] + k[1][1] * tv[1]));
            }
        }
        for o in &a.out {
            e += self.model.normal.energy(o.delta);
        }
        let tilting = self.body.tilt.is_some();
        for (k, x) in a.sl_x.iter().enumerate() {
            let o = self.body.off[a.sl[k] as usize];
            let d = [x[0] - s.cl_x[0] - o[0], x[1] - s.cl_x[1] - o[1]];
            e += 0.5 * p.mount.k_slider_xy * (d[0] * d[0] + d[1] * d[1]);
            if !rigid {
                let az = if tilting { dot3(g_of(o), q) } else { q[0] };
                e += 0.5 * p.mount.k_slider_z * (x[2] - az).powi(2);
            }
        }
        // inactive slider spheres (common mode)
        let c = &s.common;
        let n_in = self.idx.n_in as f64;
        e += n_in
            * 0.5
            * (m * (c.v[0].powi(2) + c.v[1].powi(2))
                + p.mount.k_slider_xy * (c.u[0].powi(2) + c.u[1].powi(2)));
        if !rigid && self.idx.n_in > 0 {
            e += 0.5 * m * dot3(c.s, mat_vec(&self.idx.g_in, c.s));
            e += 0.5 * p.mount.k_slider_z * dot3(c.w, mat_vec(&self.idx.g_in, c.w));
        }
        for (k, x) in a.sub_x.iter().enumerate() {
            let q = self.spec.substrate[a.sub[k] as usize];
            e += 0.5 * p.mount.k_substrate_xy * ((x[0] - q[0]).powi(2) + (x[1] - q[1]).powi(2));
        }
        e += p.protocol.load * s.cl_x[2];
        if s.spring_on {
            let d = spring_stretch(p, s.support, s.cl_x);
            e += 0.5 * p.protocol.k0 * (d[0] * d[0] + d[1] * d[1]);
        }
        e
    }

    /// The ringing deviations advanced to the current step (positions now; velocities at the
    /// last half step, or at the full step with `full_step_velocity`).
    #[allow(clippy::type_complexity)]
    fn ringing_now(
        &self,
        full_step_velocity: bool,
    ) -> (Vec<(u32, [f64; 6])>, Vec<(u32, [f64; 4])>) {
        let maps = self.ring_maps(self.state.step - self.state.mark.step);
        let r = &self.state.ringing;
        let h = 0.5 * self.dt;
        let it = self.inv_tau();
        let [w_xy, w_z, w_b] = self.free_omega2();
        let kick = |x: f64, v: f64, w2: f64| {
            if full_step_velocity {
                v + h * (-w2 * x - v * it)
            } else {
                v
            }
        };
        let sl =
            r.sl.iter()
                .zip(&r.sl_dev)
                .map(|(&i, d)| {
                    let mut d = self.advance_sl(&maps, *d);
                    d[3] = kick(d[0], d[3], w_xy);
                    d[4] = kick(d[1], d[4], w_xy);
                    // (implicit mount: the z velocity is already the full step's)
                    if self.mount.is_none() {
                        d[5] = kick(d[2], d[5], w_z);
                    }
                    (i, d)
                })
                .collect();
        let sub = r
            .sub
            .iter()
            .zip(&r.sub_dev)
            .map(|(&j, d)| {
                let mut d = Self::advance_sub(&maps, *d);
                d[2] = kick(d[0], d[2], w_b);
                d[3] = kick(d[1], d[3], w_b);
                (j, d)
            })
            .collect();
        (sl, sub)
    }

    /// How far (m) the slider disc plus one sphere radius reaches beyond the substrate
    /// rectangle now (≤ 0: wholly over it); `None` when the layout has no outline.
    pub fn overhang(&self) -> Option<f64> {
        let (c0, _) = self.spec.disc?;
        let s = &self.state;
        let c = [
            c0[0] + s.cl_x[0] - self.body.centre0[0],
            c0[1] + s.cl_x[1] - self.body.centre0[1],
        ];
        self.spec.overhang_at(c)
    }

    /// Checks the state: every position finite, the slider still over the substrate (or no
    /// further over its edge than at the start), no slider sphere torn a radius from its site,
    /// the slider above the substrate plane, every overlap below `overlap_bound · R`. O(n + p).
    pub fn check(&self) -> Result<(), DemError> {
        let s = &self.state;
        let a = &s.act;
        let fin = a.sl_x.iter().all(|x| x.iter().all(|v| v.is_finite()))
            && a.sub_x.iter().all(|x| x.iter().all(|v| v.is_finite()))
            && s.common
                .u
                .iter()
                .chain(&s.common.w)
                .chain(&s.common.d)
                .chain(&s.common.dz)
                .all(|v| v.is_finite());
        if !fin {
            return Err(self.unstable("non-finite particle position".into()));
        }
        if let Some(h) = self.overhang() {
            if h > self.overhang0.max(0.0) + 1e-12 {
                let c = [
                    s.cl_x[0] - self.body.centre0[0],
                    s.cl_x[1] - self.body.centre0[1],
                ];
                return Err(DemError::OffSubstrate {
                    t_us: s.t * 1e6,
                    over_um: h * 1e6,
                    moved_um: [c[0] * 1e6, c[1] * 1e6],
                });
            }
        }
        // A slider sphere torn from its control-layer site by more than its radius, or a
        // slider below the substrate plane, means the integration has blown up (the overlap
        // bound alone misses spheres that jumped clean through the substrate).
        self.check_slider_spheres()?;
        if s.cl_x[2] < self.h_min {
            return Err(self.unstable("the slider fell through the substrate".into()));
        }
        // relative to the smaller sphere when the two bodies' sizes differ
        let bound = self.params.numerics.overlap_bound
            * match self.body.sizes {
                None => self
                    .spec
                    .slider_sphere_radius
                    .min(self.spec.substrate_sphere_radius),
                // the smallest sphere of either body
                Some(_) => self.spec.min_radius(),
            };
        let m = a.out.iter().map(|o| o.delta).fold(0.0, f64::max);
        if m > bound {
            return Err(self.unstable(format!(
                "overlap {:.4e} µm beyond the bound {:.4e} µm",
                m * 1e6,
                bound * 1e6
            )));
        }
        Ok(())
    }

    /// Whether every slider sphere, active or free (common mode plus the largest ringing
    /// deviation), is within one radius of its control-layer site. O(n).
    fn check_slider_spheres(&self) -> Result<(), DemError> {
        let s = &self.state;
        let a = &s.act;
        let sizes = self.body.sizes.as_ref();
        let r_ref = self.spec.slider_sphere_radius;
        let q = self.q();
        let tilting = self.body.tilt.is_some();
        for (k, x) in a.sl_x.iter().enumerate() {
            let i = a.sl[k] as usize;
            let o = self.body.off[i];
            let az = if tilting { dot3(g_of(o), q) } else { q[0] };
            // each sphere's own anchor offset and radius with per-sphere sizes
            let (az, r) = match sizes {
                None => (az, r_ref),
                Some(z) => (az + z.sl_dz[i], z.sl_r[i]),
            };
            let d = [
                x[0] - s.cl_x[0] - o[0],
                x[1] - s.cl_x[1] - o[1],
                if self.params.mount.rigid_z {
                    0.0
                } else {
                    x[2] - az
                },
            ];
            let m = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            if m.is_nan() || m > r {
                return Err(self.unstable(format!(
                    "slider sphere {i} displaced {:.4e} µm from its control-layer site (bound: one radius)",
                    m * 1e6
                )));
            }
        }
        // the free slider spheres: the common mode plus the largest ringing deviation
        let c = &s.common;
        let [ax, ay] = self.body.arm;
        let ring = s
            .ringing
            .sl_dev
            .iter()
            .map(|d| (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt())
            .fold(0.0, f64::max);
        let z = if self.params.mount.rigid_z {
            0.0
        } else {
            c.w[0].abs() + c.w[1].abs() * ay + c.w[2].abs() * ax
        };
        let m = (c.u[0] * c.u[0] + c.u[1] * c.u[1] + z * z).sqrt() + ring;
        if self.idx.n_in > 0 && (m.is_nan() || m > r_ref) {
            return Err(self.unstable(format!(
                "free slider spheres displaced up to {:.4e} µm from their control-layer sites (bound: one radius)",
                m * 1e6
            )));
        }
        Ok(())
    }

    /// Every particle's position now (inactive ones from their rest / common-mode state) and
    /// which spheres have a failed contact. O(N + P); allocates.
    pub fn snapshot(&self) -> Snapshot {
        let s = &self.state;
        let a = &s.act;
        let mut substrate: Vec<[f64; 3]> = self.spec.substrate.clone();
        for (k, &j) in a.sub.iter().enumerate() {
            substrate[j as usize][0] = a.sub_x[k][0];
            substrate[j as usize][1] = a.sub_x[k][1];
        }
        let mut slider: Vec<[f64; 3]> = (0..s.sl_x.len()).map(|i| self.common_state(i).0).collect();
        for (k, &i) in a.sl.iter().enumerate() {
            slider[i as usize] = a.sl_x[k];
        }
        let (ring_sl, ring_sub) = self.ringing_now(false);
        for (i, d) in ring_sl {
            for c in 0..3 {
                slider[i as usize][c] += d[c];
            }
        }
        for (j, d) in ring_sub {
            substrate[j as usize][0] += d[0];
            substrate[j as usize][1] += d[1];
        }
        let mut failed_slider = vec![false; slider.len()];
        let mut failed_substrate = vec![false; substrate.len()];
        for (p, o) in a.out.iter().enumerate() {
            if o.delta > 0.0 && o.failed {
                let k = a.pairs[p] as usize;
                failed_slider[s.pairs.i[k] as usize] = true;
                failed_substrate[s.pairs.j[k] as usize] = true;
            }
        }
        Snapshot {
            substrate,
            slider,
            failed_substrate,
            failed_slider,
        }
    }
}
