//! The active set: which particles are integrated step by step.
//!
//! A substrate sphere at rest at its tether site with no contact feels no force and stays
//! there. A slider sphere with no contact obeys a linear equation driven only by the control
//! layer (spring and damping relative to its anchor), so every such sphere that starts in the
//! same relative state keeps sharing it: one *common mode* (lateral `u`, vertical `w_i = g_i·w`)
//! is integrated for all of them, and its reaction `N_in·k·u` (lateral), `k_z·Σ_in g gᵀ·w`
//! (vertical) acts on the control layer. That is exact, not an approximation.
//!
//! A sphere that leaves contact still rings for a while. Its *deviation* from the rest state
//! obeys a homogeneous linear equation (its own spring and damping, nothing else), identical
//! for every such sphere: it is advanced exactly by a matrix power of the step map
//! ([`super::ring`]) at each evaluation, and the control layer feels the sum of all deviations,
//! integrated as one more mode of [`crate::system::CommonMode`]. So no tolerance is involved:
//! the active set is exact to round-off.
//!
//! At each *evaluation* a pair is active when its gap (centre distance − 2R) is below
//! `active_margin`, and a particle is active when it is in an active pair. An evaluation runs
//! as soon as some particle may have moved `active_margin/2` since the last one (active
//! particles: their own displacement; inactive slider spheres: a bound from the control layer,
//! the common mode and the largest ringing amplitude; inactive substrate spheres: the largest
//! ringing amplitude), so an inactive pair cannot close its gap before it is activated — the
//! skin argument of a Verlet list. The candidate pair list (within `2R + skin`) is rebuilt when
//! a particle may have moved `(skin − margin)/2` since its build.
//!
//! Without the active set every particle and candidate pair is active, each evaluation
//! rebuilds the list (the plain Verlet list with skin), and the common mode is empty.
//!
//! This file holds the evaluation, its trigger and the ringing; the choice of the new set is in
//! `active_select.rs`, its dense packing and index in `active_index.rs`.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, g_of};
use super::ring::{amplitude, bound_factor, StepMap, IMPLICIT_BOUND_FACTOR};
use super::sim::Sim;
use crate::neighbor::build_pairs;

impl Sim {
    /// ω² (1/s²) of the free deviation modes: slider lateral, slider vertical, substrate.
    pub(crate) fn free_omega2(&self) -> [f64; 3] {
        let p = &self.params;
        let (m, mb) = (self.body.m_s, self.body.m_b);
        [
            p.mount.k_slider_xy / m,
            p.mount.k_slider_z / m,
            p.mount.k_substrate_xy / mb,
        ]
    }

    /// The step maps of `n` steps of the three free deviation modes (slider z: the implicit
    /// mount's map when it is on).
    pub(crate) fn ring_maps(&self, n: u64) -> [StepMap; 3] {
        let it = self.inv_tau();
        let w = self.free_omega2();
        let z = if self.mount.is_some() {
            StepMap::implicit(w[1], it, self.dt)
        } else {
            StepMap::new(w[1], it, self.dt)
        };
        [
            StepMap::new(w[0], it, self.dt).pow(n),
            z.pow(n),
            StepMap::new(w[2], it, self.dt).pow(n),
        ]
    }

    /// Slider deviation advanced by `maps`.
    pub(crate) fn advance_sl(&self, maps: &[StepMap; 3], d: [f64; 6]) -> [f64; 6] {
        let (x, vx) = maps[0].apply(d[0], d[3]);
        let (y, vy) = maps[0].apply(d[1], d[4]);
        let (z, vz) = if self.params.mount.rigid_z {
            (0.0, 0.0)
        } else {
            maps[1].apply(d[2], d[5])
        };
        [x, y, z, vx, vy, vz]
    }

    /// Substrate deviation advanced by `maps`.
    pub(crate) fn advance_sub(maps: &[StepMap; 3], d: [f64; 4]) -> [f64; 4] {
        let (x, vx) = maps[2].apply(d[0], d[2]);
        let (y, vy) = maps[2].apply(d[1], d[3]);
        [x, y, vx, vy]
    }

    /// Re-evaluates the active set (see the module doc). `initial`: at construction. Cost
    /// O(N + P) over all particles and candidate pairs; allocates.
    pub(crate) fn evaluate(&mut self, initial: bool) {
        // positions are at step `now` (inside a step the counter is incremented afterwards)
        let now = self.state.step + u64::from(!initial);
        let maps = self.ring_maps(now - self.state.mark.step);
        {
            let r = &self.state.ringing;
            let sl_dev: Vec<[f64; 6]> = r
                .sl_dev
                .iter()
                .map(|d| self.advance_sl(&maps, *d))
                .collect();
            let sub_dev: Vec<[f64; 4]> = r
                .sub_dev
                .iter()
                .map(|d| Self::advance_sub(&maps, *d))
                .collect();
            self.state.ringing.sl_dev = sl_dev;
            self.state.ringing.sub_dev = sub_dev;
        }
        let n = self.state.sl_x.len();
        let nb = self.state.sub_x.len();
        let mut was_sl = vec![false; n];
        let mut was_sub = vec![false; nb];
        for &i in &self.state.act.sl {
            was_sl[i as usize] = true;
        }
        for &j in &self.state.act.sub {
            was_sub[j as usize] = true;
        }
        self.scatter();
        self.materialize(&was_sl, &was_sub);
        let all = !self.params.active.enabled;
        let old_pairs: Vec<(u32, u32)> = {
            let s = &self.state;
            s.act
                .pairs
                .iter()
                .map(|&k| (s.pairs.i[k as usize], s.pairs.j[k as usize]))
                .collect()
        };
        let slack = 0.5 * (self.params.numerics.skin - self.params.active.margin);
        if all || initial || self.build_disp2() > slack * slack {
            self.rebuild();
        }
        let (sl, sub, pairs) = if all {
            (
                (0..n as u32).collect(),
                (0..nb as u32).collect(),
                (0..self.state.pairs.i.len() as u32).collect(),
            )
        } else {
            self.select(&was_sl, &was_sub, &old_pairs, initial)
        };
        self.gather(sl, sub, pairs);
        self.index();
        let ring = self.ring_bounds();
        let s = &mut self.state;
        s.mark.cl = s.cl_x;
        s.mark.tilt = s.tilt;
        s.mark.u = s.common.u;
        s.mark.w = s.common.w;
        s.mark.step = now;
        s.mark.ring = ring;
        if !initial {
            s.stats.evaluations += 1;
        }
    }

    /// Half-displacement limit (m) that triggers an active-set evaluation.
    #[inline]
    pub(super) fn trigger(&self) -> f64 {
        if self.params.active.enabled {
            0.5 * self.params.active.margin
        } else {
            0.5 * self.params.numerics.skin
        }
    }

    /// Upper bound (m) of how far the ringing deviation of an inactive slider / substrate
    /// sphere has moved in the `steps` steps since the last evaluation: the smaller of twice its
    /// largest amplitude (`mark.ring`) and `steps·dt` times its largest speed. A free
    /// deviation's speed is at most ω times the same bound as its position (the step maps keep
    /// `ω²δ² + δv² − dt ω² δ δv`, symmetric in ωδ and δv; `ring.rs`), so the speed bound is
    /// `ω·ring/2`, ω the largest of the sphere's free modes. Right after a slip, when the
    /// spheres that left contact ring by tens of nm, this lets the set go several steps
    /// between evaluations instead of one (docs/validation/dem-engine.md, "The active set").
    /// O(1).
    fn ring_since_mark(&self, steps: u64) -> [f64; 2] {
        let mk = &self.state.mark;
        let [w_xy, w_z, w_b] = self.free_omega2();
        let w_sl = if self.params.mount.rigid_z {
            w_xy
        } else {
            w_xy.max(w_z)
        };
        let t = steps as f64 * self.dt;
        [
            mk.ring[0].min(t * w_sl.sqrt() * 0.5 * mk.ring[0]),
            mk.ring[1].min(t * w_b.sqrt() * 0.5 * mk.ring[1]),
        ]
    }

    /// Upper bound of the displacement (m) of every inactive particle since the last
    /// evaluation: slider spheres move with the control layer and the common mode, plus their
    /// ringing deviation ([`Self::ring_since_mark`]); substrate spheres by their ringing
    /// deviation only.
    pub(super) fn frame_disp(&self) -> f64 {
        let s = &self.state;
        let mk = &s.mark;
        let lat = [
            s.cl_x[0] - mk.cl[0] + s.common.u[0] - mk.u[0],
            s.cl_x[1] - mk.cl[1] + s.common.u[1] - mk.u[1],
        ];
        let mut dq = [
            s.cl_x[2] - mk.cl[2],
            s.tilt[0] - mk.tilt[0],
            s.tilt[1] - mk.tilt[1],
        ];
        if !self.params.mount.rigid_z {
            for k in 0..3 {
                dq[k] += s.common.w[k] - mk.w[k];
            }
        }
        let [ax, ay] = self.body.arm;
        let z = dq[0].abs() + dq[1].abs() * ay + dq[2].abs() * ax;
        let ring = self.ring_since_mark(s.step + 1 - mk.step);
        let d = (lat[0] * lat[0] + lat[1] * lat[1] + z * z).sqrt() + ring[0];
        let d = d.max(ring[1]);
        if d.is_nan() {
            f64::INFINITY
        } else {
            d
        }
    }

    /// How far (m) a ringing inactive slider / substrate sphere can move between two
    /// evaluations: twice the largest bound of its deviation.
    fn ring_bounds(&self) -> [f64; 2] {
        let [w_xy, w_z, w_b] = self.free_omega2();
        let (f_xy, f_z, f_b) = (
            bound_factor(w_xy, self.dt),
            if self.mount.is_some() {
                IMPLICIT_BOUND_FACTOR
            } else {
                bound_factor(w_z, self.dt)
            },
            bound_factor(w_b, self.dt),
        );
        let r = &self.state.ringing;
        let sl = r
            .sl_dev
            .iter()
            .map(|d| {
                let (ax, ay) = (amplitude(d[0], d[3], w_xy), amplitude(d[1], d[4], w_xy));
                let lat = (ax * ax + ay * ay).sqrt();
                let z = if d[2] == 0.0 && d[5] == 0.0 {
                    0.0
                } else {
                    f_z * amplitude(d[2], d[5], w_z)
                };
                f_xy * lat + z
            })
            .fold(0.0, f64::max);
        let sub = r
            .sub_dev
            .iter()
            .map(|d| {
                let (ax, ay) = (amplitude(d[0], d[2], w_b), amplitude(d[1], d[3], w_b));
                f_b * (ax * ax + ay * ay).sqrt()
            })
            .fold(0.0, f64::max);
        [2.0 * sl, 2.0 * sub]
    }

    /// Writes the dense (active) particles and pair histories back to the global arrays.
    fn scatter(&mut self) {
        let s = &mut self.state;
        let a = &s.act;
        for (k, &i) in a.sl.iter().enumerate() {
            s.sl_x[i as usize] = a.sl_x[k];
            s.sl_v[i as usize] = a.sl_v[k];
        }
        for (k, &j) in a.sub.iter().enumerate() {
            s.sub_x[j as usize] = a.sub_x[k];
            s.sub_v[j as usize] = a.sub_v[k];
        }
        for (p, &k) in a.pairs.iter().enumerate() {
            s.pairs.hist[k as usize] = a.hist[p];
        }
    }

    /// Position and velocity of a slider sphere in the common mode (its rest state relative to
    /// the control layer): lateral `X + o + u`, vertical `g·(q + w)` (rigid-z: `g·q`).
    pub(crate) fn common_state(&self, i: usize) -> ([f64; 3], [f64; 3]) {
        let s = &self.state;
        let o = self.body.off[i];
        let c = &s.common;
        let (q, qd) = (self.q(), self.qdot());
        let g = g_of(o);
        let (z, vz) = if self.params.mount.rigid_z {
            if self.body.tilt.is_some() {
                (dot3(g, q), dot3(g, qd))
            } else {
                (q[0], qd[0])
            }
        } else if self.body.tilt.is_some() {
            (dot3(g, q) + dot3(g, c.w), dot3(g, c.s))
        } else {
            (q[0] + c.w[0], c.s[0])
        };
        (
            [s.cl_x[0] + o[0] + c.u[0], s.cl_x[1] + o[1] + c.u[1], z],
            [c.v[0], c.v[1], vz],
        )
    }

    /// Global positions of the inactive particles: slider spheres from the common mode plus
    /// their ringing deviation, substrate spheres at their site plus theirs.
    fn materialize(&mut self, was_sl: &[bool], was_sub: &[bool]) {
        for i in 0..was_sl.len() {
            if !was_sl[i] {
                let (x, v) = self.common_state(i);
                self.state.sl_x[i] = x;
                self.state.sl_v[i] = v;
            }
        }
        let r = &self.state.ringing;
        for (k, &i) in r.sl.iter().enumerate() {
            let d = r.sl_dev[k];
            let (x, v) = (
                &mut self.state.sl_x[i as usize],
                &mut self.state.sl_v[i as usize],
            );
            for c in 0..3 {
                x[c] += d[c];
                v[c] += d[3 + c];
            }
        }
        for j in 0..was_sub.len() {
            if !was_sub[j] {
                let site = self.spec.substrate[j];
                self.state.sub_x[j] = [site[0], site[1]];
                self.state.sub_v[j] = [0.0; 2];
            }
        }
        for (k, &j) in r.sub.iter().enumerate() {
            let d = r.sub_dev[k];
            let (x, v) = (
                &mut self.state.sub_x[j as usize],
                &mut self.state.sub_v[j as usize],
            );
            x[0] += d[0];
            x[1] += d[1];
            v[0] += d[2];
            v[1] += d[3];
        }
    }

    /// Largest squared displacement (m²) of any particle since the last candidate-list build.
    fn build_disp2(&self) -> f64 {
        let s = &self.state;
        let a = s
            .sub_x
            .iter()
            .zip(&s.ref_sub)
            .map(|(p, q)| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2))
            .fold(0.0, f64::max);
        let b = s
            .sl_x
            .iter()
            .zip(&s.ref_sl)
            .map(|(p, q)| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2))
            .fold(0.0, f64::max);
        if a.is_nan() || b.is_nan() {
            f64::INFINITY
        } else {
            a.max(b)
        }
    }

    /// Rebuilds the candidate pair list from the global positions (keeps histories).
    fn rebuild(&mut self) {
        let s = &mut self.state;
        let cutoff = self.spec.max_contact_distance() + self.params.numerics.skin;
        s.pairs = build_pairs(&s.sub_x, &self.sub_h, &s.sl_x, cutoff, &s.pairs);
        s.ref_sub.clone_from(&s.sub_x);
        s.ref_sl.clone_from(&s.sl_x);
        s.builds += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::SimParams;

    /// The bound of [`Sim::ring_since_mark`] holds on a slide where spheres leave contact
    /// ringing: a small slider with every contact failed (μ = 0.5, so the spheres deflect far
    /// and ring when a contact breaks), reduced and full model, pulled at 1 m/s. After every
    /// step, each ringing inactive sphere's deviation has moved from its value at the last
    /// evaluation by at most the bound, and the bound's speed part (`steps·dt·ω·ring/2`) is
    /// the smaller one on some steps, so it is what this checks.
    #[test]
    fn ringing_spheres_move_within_the_bound_between_evaluations() {
        let mut scene = surrogate::Scene::preset("square-tri").unwrap();
        scene.slider.radius = 12e-6;
        scene.slider.theta = 10.2f64.to_radians();
        scene.substrate.size = [60e-6, 60e-6];
        scene.coating.p_crit = 1e6;
        for rigid_z in [true, false] {
            let p = SimParams {
                protocol: crate::ProtocolParams {
                    load: 1.4e-3 / 3505.0 * scene.slider_sites().len() as f64,
                    equilibrate_time: 0.2e-6,
                    relax_time: 0.2e-6,
                    slide_time: 3e-6,
                    support_speed: 1.0,
                    ..Default::default()
                },
                mount: crate::MountParams {
                    rigid_z,
                    ..Default::default()
                },
                active: crate::ActiveSetParams {
                    prune_substrate: true,
                    enabled: true,
                    ..Default::default()
                },
                ..SimParams::default()
            };
            let mut sim = crate::prepare(&scene, p, crate::Start::Surrogate, None)
                .unwrap()
                .sim;
            let (mut worst, mut speed_part, mut ringing) = (0.0f64, 0u64, 0u64);
            crate::protocol::step_slide(&mut sim, |sim| {
                let s = &sim.state;
                let n = s.step - s.mark.step;
                let bound = sim.ring_since_mark(n);
                let maps = sim.ring_maps(n);
                for d in &s.ringing.sl_dev {
                    let e = sim.advance_sl(&maps, *d);
                    let moved = (0..3).map(|c| (e[c] - d[c]).powi(2)).sum::<f64>().sqrt();
                    worst = worst.max(moved / bound[0]);
                }
                for d in &s.ringing.sub_dev {
                    let e = Sim::advance_sub(&maps, *d);
                    let moved = ((e[0] - d[0]).powi(2) + (e[1] - d[1]).powi(2)).sqrt();
                    worst = worst.max(moved / bound[1]);
                }
                if !s.ringing.sl.is_empty() {
                    ringing += 1;
                    speed_part += u64::from(bound[0] < s.mark.ring[0]);
                }
            })
            .unwrap();
            eprintln!(
                "rigid_z {rigid_z}: {ringing} steps with ringing spheres, the speed part decided on {speed_part}; worst moved / bound {worst:.3}; {} evaluations",
                sim.state.stats.evaluations
            );
            assert!(
                worst <= 1.0,
                "rigid_z {rigid_z}: a ringing sphere moved {worst} × its bound"
            );
            assert!(
                speed_part > 0,
                "rigid_z {rigid_z}: the speed bound was never used"
            );
            assert_eq!(sim.state.stats.late_pairs, 0);
        }
    }
}
