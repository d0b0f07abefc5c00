//! [`Sim`]: the DEM engine (forces + velocity-Verlet).

use crate::model::{ContactModel, FrictionLaw, NormalModel, PairOut};
use crate::neighbor::{build_pairs, needs_rebuild};
use crate::params::{DampingFrame, SimParams};
use crate::system::{State, SystemSpec};
use crate::DemError;
use rayon::prelude::*;

/// Instantaneous observables of a state (SI).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct Observables {
    /// Simulated time (s).
    pub t: f64,
    /// Touching pairs (δ > 0).
    pub contacts: usize,
    /// Touching pairs whose coating has failed now (p0 > P_crit).
    pub failed: usize,
    /// Listed pairs whose coating failed at some time.
    pub ever_failed: usize,
    /// Largest p0 over the contacts (Pa).
    pub p_max: f64,
    /// Largest overlap (m).
    pub max_overlap: f64,
    /// Mean z of the slider sphere centres (m).
    pub z: f64,
    /// Σ vertical contact force on the slider (N).
    pub contact_fz: f64,
    /// Pulling-spring force along α (N) (0 when detached).
    pub spring_force: f64,
    /// Support travel along α since the spring was attached (m).
    pub support_travel: f64,
    /// Control-layer travel along α since the spring was attached (m).
    pub slider_travel: f64,
}

/// The DEM engine: static layout, contact model, knobs, state and work buffers.
///
/// Per step: O(N + P) work (N particles, P listed pairs), no allocation except at neighbour
/// rebuilds; pair forces are computed in parallel into a per-pair buffer and reduced per
/// particle in a fixed order, so results are bit-identical for any thread count.
pub struct Sim {
    /// Static layout.
    pub spec: SystemSpec,
    /// Contact model.
    pub model: ContactModel,
    /// Knobs (the `dt` actually used is [`Sim::dt`]).
    pub params: SimParams,
    /// Time step (s).
    pub dt: f64,
    /// Estimated critical step (s), reported on instability.
    pub dt_crit: f64,
    /// Dynamic state.
    pub state: State,
    pub(crate) sub_h: Vec<f64>,
    site_off: Vec<[f64; 2]>,
    m_s: f64,
    m_cl: f64,
    m_eff: f64,
    pub(crate) out: Vec<PairOut>,
    sl_start: Vec<u32>,
    sub_start: Vec<u32>,
    sub_items: Vec<u32>,
}

#[inline]
fn kick(v: &mut f64, f: f64, h: f64, m: f64) {
    *v += h * f / m;
}

impl Sim {
    /// Creates the engine at rest in the layout `spec`, with step `dt` (s) and the critical-step
    /// estimate `dt_crit` (s, for messages). Builds the pair list and the initial forces.
    pub fn new(
        spec: SystemSpec,
        model: ContactModel,
        params: SimParams,
        dt: f64,
        dt_crit: f64,
    ) -> Result<Sim, DemError> {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(DemError::invalid("dt_us", dt * 1e6, "must be positive"));
        }
        if spec.slider_sites.is_empty() {
            return Err(DemError::invalid(
                "slider.radius_um",
                0,
                "the slider has no spheres",
            ));
        }
        let n = spec.slider_sites.len();
        let mut c = [0.0; 2];
        for s in &spec.slider_sites {
            c[0] += s[0];
            c[1] += s[1];
        }
        c[0] /= n as f64;
        c[1] /= n as f64;
        let site_off = spec
            .slider_sites
            .iter()
            .map(|s| [s[0] - c[0], s[1] - c[1]])
            .collect();
        let m_s = spec.sphere_mass();
        let m_cl = n as f64 * spec.material.sphere_mass(params.control_sphere_radius);
        let nb = spec.substrate.len();
        let state = State {
            sub_x: spec.substrate.iter().map(|p| [p[0], p[1]]).collect(),
            sub_v: vec![[0.0; 2]; nb],
            sub_f: vec![[0.0; 2]; nb],
            sl_x: spec
                .slider_sites
                .iter()
                .zip(&spec.slider_z)
                .map(|(s, z)| [s[0], s[1], *z])
                .collect(),
            sl_v: vec![[0.0; 3]; n],
            sl_f: vec![[0.0; 3]; n],
            cl_x: [c[0], c[1], spec.control_z],
            held_xy: true,
            ..Default::default()
        };
        let mut sim = Sim {
            sub_h: spec.substrate.iter().map(|p| p[2]).collect(),
            spec,
            model,
            params,
            dt,
            dt_crit,
            state,
            site_off,
            m_s,
            m_cl,
            m_eff: 0.5 * m_s,
            out: Vec::new(),
            sl_start: Vec::new(),
            sub_start: Vec::new(),
            sub_items: Vec::new(),
        };
        sim.rebuild();
        sim.compute_forces();
        Ok(sim)
    }

    /// Control-layer mass (kg): one control sphere per slider sphere.
    pub fn control_mass(&self) -> f64 {
        self.m_cl
    }

    /// Mass of a slider / substrate sphere (kg).
    pub fn sphere_mass(&self) -> f64 {
        self.m_s
    }

    /// Number of slider spheres.
    pub fn n_slider(&self) -> usize {
        self.state.sl_x.len()
    }

    /// Number of substrate spheres.
    pub fn n_substrate(&self) -> usize {
        self.state.sub_x.len()
    }

    /// Moving particles integrated per step (substrate + slider + 1 control body).
    pub fn particles(&self) -> usize {
        self.n_substrate() + self.n_slider() + 1
    }

    /// Rest offset (m) of slider sphere `i` from the control-layer centre of mass.
    pub fn site_offset(&self, i: usize) -> [f64; 2] {
        self.site_off[i]
    }

    /// Rebuilds the pair list from the current positions (keeps histories) and the index maps.
    pub fn rebuild(&mut self) {
        let s = &mut self.state;
        let cutoff = 2.0 * self.spec.sphere_radius + self.params.skin;
        s.pairs = build_pairs(&s.sub_x, &self.sub_h, &s.sl_x, cutoff, &s.pairs);
        s.ref_sub.clone_from(&s.sub_x);
        s.ref_sl.clone_from(&s.sl_x);
        s.builds += 1;
        self.index_pairs();
    }

    /// Recomputes the per-particle pair index maps (after a rebuild or a checkpoint load).
    pub fn index_pairs(&mut self) {
        let p = &self.state.pairs;
        let n = self.state.sl_x.len();
        let nb = self.state.sub_x.len();
        self.sl_start = vec![0; n + 1];
        for &i in &p.i {
            self.sl_start[i as usize + 1] += 1;
        }
        for i in 0..n {
            self.sl_start[i + 1] += self.sl_start[i];
        }
        self.sub_start = vec![0; nb + 1];
        for &j in &p.j {
            self.sub_start[j as usize + 1] += 1;
        }
        for j in 0..nb {
            self.sub_start[j + 1] += self.sub_start[j];
        }
        let mut fill = self.sub_start.clone();
        self.sub_items = vec![0; p.j.len()];
        for (k, &j) in p.j.iter().enumerate() {
            self.sub_items[fill[j as usize] as usize] = k as u32;
            fill[j as usize] += 1;
        }
        self.out = vec![PairOut::default(); p.i.len()];
    }

    /// Computes every force from the current positions and (half-step) velocities; updates the
    /// tangential histories by one step.
    pub fn compute_forces(&mut self) {
        let dt = self.dt;
        let m_eff = self.m_eff;
        let model = &self.model;
        let p = &self.params;
        let s = &mut self.state;
        let sub_h = &self.sub_h;
        // 1. pair forces, in parallel into the per-pair buffer
        {
            let (sl_x, sl_v, sub_x, sub_v) = (&s.sl_x, &s.sl_v, &s.sub_x, &s.sub_v);
            self.out
                .par_iter_mut()
                .with_min_len(512)
                .zip(s.pairs.hist.par_iter_mut())
                .zip(s.pairs.i.par_iter())
                .zip(s.pairs.j.par_iter())
                .for_each(|(((o, h), &i), &j)| {
                    let (i, j) = (i as usize, j as usize);
                    let a = sl_x[i];
                    let b = sub_x[j];
                    let va = sl_v[i];
                    let vb = sub_v[j];
                    let d = [a[0] - b[0], a[1] - b[1], a[2] - sub_h[j]];
                    let v = [va[0] - vb[0], va[1] - vb[1], va[2]];
                    *o = model.pair(d, v, &mut h.xi, m_eff, dt);
                    h.ever_failed |= o.failed;
                });
        }
        let inv_tau = if p.damping_time.is_finite() && p.damping_time > 0.0 {
            1.0 / p.damping_time
        } else {
            0.0
        };
        let rel = p.damping_frame == DampingFrame::Relative;
        let (cx, cv) = (s.cl_x, s.cl_v);
        let vref = if rel { cv } else { [0.0; 3] };
        let m_s = self.m_s;
        let (kxy, kz, rigid) = (p.k_slider_xy, p.k_slider_z, p.rigid_z);
        // 2. slider spheres
        {
            let out = &self.out;
            let st = &self.sl_start;
            let off = &self.site_off;
            let (sl_x, sl_v) = (&s.sl_x, &s.sl_v);
            s.sl_f
                .par_iter_mut()
                .with_min_len(256)
                .enumerate()
                .for_each(|(i, f)| {
                    let mut acc = [0.0; 3];
                    for o in &out[st[i] as usize..st[i + 1] as usize] {
                        acc[0] += o.force[0];
                        acc[1] += o.force[1];
                        acc[2] += o.force[2];
                    }
                    let x = sl_x[i];
                    let v = sl_v[i];
                    acc[0] += kxy * (cx[0] + off[i][0] - x[0]) - m_s * (v[0] - vref[0]) * inv_tau;
                    acc[1] += kxy * (cx[1] + off[i][1] - x[1]) - m_s * (v[1] - vref[1]) * inv_tau;
                    if !rigid {
                        acc[2] += kz * (cx[2] - x[2]) - m_s * (v[2] - vref[2]) * inv_tau;
                    }
                    *f = acc;
                });
        }
        // 3. substrate spheres
        {
            let out = &self.out;
            let (ss, si) = (&self.sub_start, &self.sub_items);
            let kt = p.k_substrate_xy;
            let spec = &self.spec.substrate;
            let (sub_x, sub_v) = (&s.sub_x, &s.sub_v);
            s.sub_f
                .par_iter_mut()
                .with_min_len(1024)
                .enumerate()
                .for_each(|(j, f)| {
                    let x = sub_x[j];
                    let v = sub_v[j];
                    let mut acc = [
                        kt * (spec[j][0] - x[0]) - m_s * v[0] * inv_tau,
                        kt * (spec[j][1] - x[1]) - m_s * v[1] * inv_tau,
                    ];
                    for &k in &si[ss[j] as usize..ss[j + 1] as usize] {
                        let o = &out[k as usize];
                        acc[0] -= o.force[0];
                        acc[1] -= o.force[1];
                    }
                    *f = acc;
                });
        }
        // 4. control layer (sequential, fixed order)
        let mut f = [0.0; 3];
        for (i, x) in s.sl_x.iter().enumerate() {
            f[0] += kxy * (x[0] - cx[0] - self.site_off[i][0]);
            f[1] += kxy * (x[1] - cx[1] - self.site_off[i][1]);
            if rigid {
                f[2] += s.sl_f[i][2];
            } else {
                f[2] += kz * (x[2] - cx[2]);
            }
        }
        f[2] -= p.load;
        let mz = z_mass(self.m_cl, m_s, s.sl_x.len(), rigid);
        f[2] -= mz * cv[2] * inv_tau;
        let vr = if rel { s.support_v } else { [0.0; 2] };
        f[0] -= self.m_cl * (cv[0] - vr[0]) * inv_tau;
        f[1] -= self.m_cl * (cv[1] - vr[1]) * inv_tau;
        if s.spring_on {
            let d = spring_stretch(p, s.support, cx);
            f[0] += p.k0 * d[0];
            f[1] += p.k0 * d[1];
        }
        s.cl_f = f;
    }

    fn half_kick(&mut self) {
        let h = 0.5 * self.dt;
        let m = self.m_s;
        let rigid = self.params.rigid_z;
        let s = &mut self.state;
        s.sub_v
            .par_iter_mut()
            .with_min_len(2048)
            .zip(s.sub_f.par_iter())
            .for_each(|(v, f)| {
                kick(&mut v[0], f[0], h, m);
                kick(&mut v[1], f[1], h, m);
            });
        s.sl_v
            .par_iter_mut()
            .with_min_len(1024)
            .zip(s.sl_f.par_iter())
            .for_each(|(v, f)| {
                kick(&mut v[0], f[0], h, m);
                kick(&mut v[1], f[1], h, m);
                if !rigid {
                    kick(&mut v[2], f[2], h, m);
                }
            });
        let mz = z_mass(self.m_cl, m, s.sl_x.len(), rigid);
        if s.held_xy {
            s.cl_v[0] = 0.0;
            s.cl_v[1] = 0.0;
        } else {
            kick(&mut s.cl_v[0], s.cl_f[0], h, self.m_cl);
            kick(&mut s.cl_v[1], s.cl_f[1], h, self.m_cl);
        }
        kick(&mut s.cl_v[2], s.cl_f[2], h, mz);
        if rigid {
            let vz = s.cl_v[2];
            s.sl_v
                .par_iter_mut()
                .with_min_len(1024)
                .for_each(|v| v[2] = vz);
        }
    }

    fn drift(&mut self) {
        let dt = self.dt;
        let rigid = self.params.rigid_z;
        let s = &mut self.state;
        s.sub_x
            .par_iter_mut()
            .with_min_len(2048)
            .zip(s.sub_v.par_iter())
            .for_each(|(x, v)| {
                x[0] += dt * v[0];
                x[1] += dt * v[1];
            });
        for k in 0..3 {
            s.cl_x[k] += dt * s.cl_v[k];
        }
        let z = s.cl_x[2];
        s.sl_x
            .par_iter_mut()
            .with_min_len(1024)
            .zip(s.sl_v.par_iter())
            .for_each(|(x, v)| {
                x[0] += dt * v[0];
                x[1] += dt * v[1];
                if rigid {
                    x[2] = z;
                } else {
                    x[2] += dt * v[2];
                }
            });
        s.support[0] += dt * s.support_v[0];
        s.support[1] += dt * s.support_v[1];
    }

    /// One velocity-Verlet step: half kick, drift, (rebuild), forces, half kick. Errors with
    /// [`DemError::Unstable`] if the control layer's state is no longer finite.
    pub fn step(&mut self) -> Result<(), DemError> {
        self.half_kick();
        self.drift();
        let s = &self.state;
        if needs_rebuild(&s.sub_x, &s.ref_sub, &s.sl_x, &s.ref_sl, self.params.skin) {
            self.rebuild();
        }
        self.compute_forces();
        self.half_kick();
        self.state.step += 1;
        self.state.t = self.state.step as f64 * self.dt;
        let c = self.state.cl_x;
        if !(c.iter().all(|v| v.is_finite()) && self.state.cl_v.iter().all(|v| v.is_finite())) {
            return Err(self.unstable("non-finite control-layer state".into()));
        }
        Ok(())
    }

    /// The instability error for the current time.
    pub fn unstable(&self, what: String) -> DemError {
        DemError::Unstable {
            t_us: self.state.t * 1e6,
            what,
            dt_us: self.dt * 1e6,
            dt_crit_us: self.dt_crit * 1e6,
        }
    }

    /// Checks every position for finiteness and every overlap against the bound
    /// (`overlap_bound · R`). O(N + P).
    pub fn check(&self) -> Result<(), DemError> {
        let s = &self.state;
        let fin = s.sl_x.iter().all(|x| x.iter().all(|v| v.is_finite()))
            && s.sub_x.iter().all(|x| x.iter().all(|v| v.is_finite()));
        if !fin {
            return Err(self.unstable("non-finite particle position".into()));
        }
        // A slider sphere torn from its control-layer site by more than a sphere radius, or a
        // slider below the substrate plane, means the integration has blown up (the overlap
        // bound alone misses spheres that jumped clean through the substrate).
        let r = self.spec.sphere_radius;
        let c = s.cl_x;
        for (i, x) in s.sl_x.iter().enumerate() {
            let d = [
                x[0] - c[0] - self.site_off[i][0],
                x[1] - c[1] - self.site_off[i][1],
                if self.params.rigid_z {
                    0.0
                } else {
                    x[2] - c[2]
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
        let h_min = self.sub_h.iter().copied().fold(f64::INFINITY, f64::min);
        if c[2] < h_min {
            return Err(self.unstable("the slider fell through the substrate".into()));
        }
        let bound = self.params.overlap_bound * self.spec.sphere_radius;
        let m = self.out.iter().map(|o| o.delta).fold(0.0, f64::max);
        if m > bound {
            return Err(self.unstable(format!(
                "overlap {:.4e} µm beyond the bound {:.4e} µm",
                m * 1e6,
                bound * 1e6
            )));
        }
        Ok(())
    }

    /// Releases the lateral hold of the control layer and attaches the pulling spring with the
    /// support `support_lead` ahead along α (zero initial spring force).
    pub fn attach_spring(&mut self) {
        let (sa, ca) = self.params.alpha.sin_cos();
        let s = &mut self.state;
        s.held_xy = false;
        s.spring_on = true;
        s.support = [
            s.cl_x[0] + self.params.support_lead * ca,
            s.cl_x[1] + self.params.support_lead * sa,
        ];
        s.support0 = s.support;
        self.compute_forces_keep_history();
    }

    /// Sets the support moving at `support_speed` along α.
    pub fn start_support(&mut self) {
        let (sa, ca) = self.params.alpha.sin_cos();
        let v = self.params.support_speed;
        self.state.support_v = [v * ca, v * sa];
    }

    fn compute_forces_keep_history(&mut self) {
        // Only the control-layer force changes when the spring is attached; recompute it
        // without touching the pair histories.
        let p = &self.params;
        let s = &mut self.state;
        if s.spring_on {
            // the spring is at rest length when attached: adds 0 up to rounding
            let d = spring_stretch(p, s.support, s.cl_x);
            s.cl_f[0] += p.k0 * d[0];
            s.cl_f[1] += p.k0 * d[1];
        }
    }

    /// Observables of the current state (uses the pair results of the last force evaluation).
    /// O(N + P), sequential.
    pub fn observe(&self) -> Observables {
        let s = &self.state;
        let mut o = Observables {
            t: s.t,
            ..Default::default()
        };
        for (k, r) in self.out.iter().enumerate() {
            if r.delta > 0.0 {
                o.contacts += 1;
                o.failed += r.failed as usize;
                o.p_max = o.p_max.max(r.p0);
                o.contact_fz += r.force[2];
            }
            o.max_overlap = o.max_overlap.max(r.delta);
            o.ever_failed += s.pairs.hist[k].ever_failed as usize;
        }
        o.z = s.sl_x.iter().map(|x| x[2]).sum::<f64>() / s.sl_x.len() as f64;
        let (sa, ca) = self.params.alpha.sin_cos();
        if s.spring_on {
            let d = [s.support[0] - s.cl_x[0], s.support[1] - s.cl_x[1]];
            o.spring_force = self.params.k0 * (d[0] * ca + d[1] * sa - self.params.support_lead);
            let ds = [s.support[0] - s.support0[0], s.support[1] - s.support0[1]];
            o.support_travel = ds[0] * ca + ds[1] * sa;
            let dc = [
                s.cl_x[0] - (s.support0[0] - self.params.support_lead * ca),
                s.cl_x[1] - (s.support0[1] - self.params.support_lead * sa),
            ];
            o.slider_travel = dc[0] * ca + dc[1] * sa;
        }
        o
    }

    /// Total mechanical energy (J): kinetic + Hertz + spring + tether + load potential
    /// (`W·Z`) + pulling spring. Tangential spring energy is not included (exact for μ = 0).
    pub fn energy(&self) -> f64 {
        let s = &self.state;
        let p = &self.params;
        let m = self.m_s;
        let mut e = 0.0;
        for v in &s.sub_v {
            e += 0.5 * m * (v[0] * v[0] + v[1] * v[1]);
        }
        for v in &s.sl_v {
            let vz = if p.rigid_z { 0.0 } else { v[2] * v[2] };
            e += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + vz);
        }
        let mz = z_mass(self.m_cl, m, s.sl_x.len(), p.rigid_z);
        e += 0.5 * self.m_cl * (s.cl_v[0].powi(2) + s.cl_v[1].powi(2))
            + 0.5 * mz * s.cl_v[2].powi(2);
        for o in &self.out {
            e += self.model.normal.energy(o.delta);
        }
        for (i, x) in s.sl_x.iter().enumerate() {
            let d = [
                x[0] - s.cl_x[0] - self.site_off[i][0],
                x[1] - s.cl_x[1] - self.site_off[i][1],
            ];
            e += 0.5 * p.k_slider_xy * (d[0] * d[0] + d[1] * d[1]);
            if !p.rigid_z {
                e += 0.5 * p.k_slider_z * (x[2] - s.cl_x[2]).powi(2);
            }
        }
        for (x, q) in s.sub_x.iter().zip(&self.spec.substrate) {
            e += 0.5 * p.k_substrate_xy * ((x[0] - q[0]).powi(2) + (x[1] - q[1]).powi(2));
        }
        e += p.load * s.cl_x[2];
        if s.spring_on {
            let d = spring_stretch(p, s.support, s.cl_x);
            e += 0.5 * p.k0 * (d[0] * d[0] + d[1] * d[1]);
        }
        e
    }

    /// Per-pair results of the last force evaluation (parallel to `state.pairs`).
    pub fn pair_results(&self) -> &[PairOut] {
        &self.out
    }

    /// Friction coefficient μ(p0) of the model's friction law.
    pub fn mu_at(&self, p0: f64) -> f64 {
        self.model.friction.mu(p0)
    }
}

/// Mass (kg) that moves with the control layer in z: the layer alone, or with `rigid_z` the layer
/// plus its `n` slider spheres of mass `m_s`.
#[inline]
fn z_mass(m_cl: f64, m_s: f64, n: usize, rigid_z: bool) -> f64 {
    if rigid_z {
        m_cl + n as f64 * m_s
    } else {
        m_cl
    }
}

/// Pulling-spring stretch (m): the spring's rest anchor (the support moved back by the lead along
/// α) minus the control layer's centre `cl`, in x and y. The spring force is K0 times this.
#[inline]
fn spring_stretch(p: &SimParams, support: [f64; 2], cl: [f64; 3]) -> [f64; 2] {
    let (sa, ca) = p.alpha.sin_cos();
    [
        support[0] - p.support_lead * ca - cl[0],
        support[1] - p.support_lead * sa - cl[1],
    ]
}
