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

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, g_of};
use super::chunks::Chunking;
use super::ring::{amplitude, bound_factor, StepMap, IMPLICIT_BOUND_FACTOR};
use super::sim::Sim;
use crate::model::PairOut;
use crate::neighbor::build_pairs;

/// Ringing deviations below this amplitude (m) are forgotten individually (they stay in the
/// aggregate mode): far below the round-off of any position (~10⁻²⁰ m).
const DROP_AMPLITUDE: f64 = 1e-25;

impl Sim {
    /// ω² (1/s²) of the free deviation modes: slider lateral, slider vertical, substrate.
    pub(crate) fn free_omega2(&self) -> [f64; 3] {
        let p = &self.params;
        let (m, mb) = (self.body.m_s, self.body.m_b);
        [p.k_slider_xy / m, p.k_slider_z / m, p.k_substrate_xy / mb]
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
        let (z, vz) = if self.params.rigid_z {
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
        let all = !self.params.active_set;
        let old_pairs: Vec<(u32, u32)> = {
            let s = &self.state;
            s.act
                .pairs
                .iter()
                .map(|&k| (s.pairs.i[k as usize], s.pairs.j[k as usize]))
                .collect()
        };
        let slack = 0.5 * (self.params.skin - self.params.active_margin);
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
                let lat = amplitude(d[0], d[3], w_xy).hypot(amplitude(d[1], d[4], w_xy));
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
            .map(|d| f_b * amplitude(d[0], d[2], w_b).hypot(amplitude(d[1], d[3], w_b)))
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
        let (z, vz) = if self.params.rigid_z {
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
        let cutoff = self.spec.max_contact_distance() + self.params.skin;
        s.pairs = build_pairs(&s.sub_x, &self.sub_h, &s.sl_x, cutoff, &s.pairs);
        s.ref_sub.clone_from(&s.sub_x);
        s.ref_sl.clone_from(&s.sl_x);
        s.builds += 1;
    }

    /// The new active set (sorted slider, substrate and candidate-pair indices) and the new
    /// ringing lists: a sphere that leaves the set keeps its deviation from the rest state as a
    /// ringing entry (added to the aggregate mode); one that enters it leaves the ringing list
    /// (its deviation taken out of the aggregate). At construction, spheres off their rest state
    /// stay active instead.
    fn select(
        &mut self,
        was_sl: &[bool],
        was_sub: &[bool],
        old_pairs: &[(u32, u32)],
        initial: bool,
    ) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
        let n = was_sl.len();
        let nb = was_sub.len();
        let margin = self.params.active_margin;
        let two_r = self.spec.contact_distance();
        let mut sl_on = vec![false; n];
        let mut sub_on = vec![false; nb];
        let mut pairs = Vec::new();
        let mut late = 0u64;
        {
            let s = &self.state;
            let mut o = 0usize;
            for k in 0..s.pairs.i.len() {
                let (i, j) = (s.pairs.i[k], s.pairs.j[k]);
                let a = s.sl_x[i as usize];
                let b = s.sub_x[j as usize];
                let d = [a[0] - b[0], a[1] - b[1], a[2] - self.sub_h[j as usize]];
                let two_r = match &self.body.sizes {
                    None => two_r,
                    Some(z) => z.sl_r[i as usize] + z.sub_r[j as usize],
                };
                let gap = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() - two_r;
                if gap < margin {
                    pairs.push(k as u32);
                    sl_on[i as usize] = true;
                    sub_on[j as usize] = true;
                    while o < old_pairs.len() && old_pairs[o] < (i, j) {
                        o += 1;
                    }
                    let was = o < old_pairs.len() && old_pairs[o] == (i, j);
                    if !was && !initial && gap <= 0.0 {
                        late += 1;
                    }
                }
            }
        }
        // per-site sizes: a body whose spheres differ in mass keeps every sphere integrated (the
        // common mode of the free slider spheres and the ringing maps take one mass); the
        // other body's spheres still leave the set
        if self.spec.slider_radii.is_some() {
            sl_on.fill(true);
        }
        if self.spec.substrate_radii.is_some() {
            sub_on.fill(true);
        }
        // slider spheres: deviations of the ringing ones, as of now
        let mut dev_sl: Vec<Option<[f64; 6]>> = vec![None; n];
        for (k, &i) in self.state.ringing.sl.iter().enumerate() {
            dev_sl[i as usize] = Some(self.state.ringing.sl_dev[k]);
        }
        let [w_xy, w_z, w_b] = self.free_omega2();
        let rigid = self.params.rigid_z;
        let (mut on, mut off) = (0u64, 0u64);
        let mut ring_sl = Vec::new();
        let mut ring_sl_dev = Vec::new();
        for i in 0..n {
            let g = g_of(self.body.off[i]);
            if sl_on[i] {
                if !was_sl[i] {
                    on += 1;
                    if let Some(d) = dev_sl[i] {
                        self.aggregate_sl(d, g, -1.0);
                    }
                }
                continue;
            }
            let d = if was_sl[i] {
                let (xc, vc) = self.common_state(i);
                let (x, v) = (self.state.sl_x[i], self.state.sl_v[i]);
                let mut d = [
                    x[0] - xc[0],
                    x[1] - xc[1],
                    x[2] - xc[2],
                    v[0] - vc[0],
                    v[1] - vc[1],
                    v[2] - vc[2],
                ];
                if rigid {
                    d[2] = 0.0;
                    d[5] = 0.0;
                }
                if d == [0.0; 6] {
                    off += 1;
                    continue;
                }
                if initial {
                    sl_on[i] = true;
                    continue;
                }
                off += 1;
                self.aggregate_sl(d, g, 1.0);
                d
            } else if let Some(d) = dev_sl[i] {
                d
            } else {
                continue;
            };
            let amp = amplitude(d[0], d[3], w_xy)
                + amplitude(d[1], d[4], w_xy)
                + amplitude(d[2], d[5], w_z);
            if amp >= DROP_AMPLITUDE {
                ring_sl.push(i as u32);
                ring_sl_dev.push(d);
            }
        }
        let mut dev_sub: Vec<Option<[f64; 4]>> = vec![None; nb];
        for (k, &j) in self.state.ringing.sub.iter().enumerate() {
            dev_sub[j as usize] = Some(self.state.ringing.sub_dev[k]);
        }
        let mut ring_sub = Vec::new();
        let mut ring_sub_dev = Vec::new();
        for j in 0..nb {
            if sub_on[j] {
                on += u64::from(!was_sub[j]);
                continue;
            }
            let d = if was_sub[j] {
                let site = self.spec.substrate[j];
                let (x, v) = (self.state.sub_x[j], self.state.sub_v[j]);
                let d = [x[0] - site[0], x[1] - site[1], v[0], v[1]];
                if d == [0.0; 4] {
                    off += 1;
                    continue;
                }
                if initial {
                    sub_on[j] = true;
                    continue;
                }
                off += 1;
                d
            } else if let Some(d) = dev_sub[j] {
                d
            } else {
                continue;
            };
            if amplitude(d[0], d[2], w_b) + amplitude(d[1], d[3], w_b) >= DROP_AMPLITUDE {
                ring_sub.push(j as u32);
                ring_sub_dev.push(d);
            }
        }
        let r = &mut self.state.ringing;
        r.sl = ring_sl;
        r.sl_dev = ring_sl_dev;
        r.sub = ring_sub;
        r.sub_dev = ring_sub_dev;
        let st = &mut self.state.stats;
        if !initial {
            st.activations += on;
            st.deactivations += off;
        }
        st.late_pairs += late;
        let list = |f: &[bool]| {
            f.iter()
                .enumerate()
                .filter(|(_, &b)| b)
                .map(|(i, _)| i as u32)
                .collect::<Vec<u32>>()
        };
        (list(&sl_on), list(&sub_on), pairs)
    }

    /// Adds (`sign` = 1) or removes (−1) a slider sphere's deviation `d` (with its `g`) to / from
    /// the aggregate mode the control layer feels.
    fn aggregate_sl(&mut self, d: [f64; 6], g: [f64; 3], sign: f64) {
        let c = &mut self.state.common;
        for k in 0..2 {
            c.d[k] += sign * d[k];
            c.dv[k] += sign * d[3 + k];
        }
        if !self.params.rigid_z {
            for r in 0..3 {
                c.dz[r] += sign * d[2] * g[r];
                c.dzv[r] += sign * d[5] * g[r];
            }
        }
    }

    /// Packs the active particles and pairs densely (positions at this evaluation become the
    /// displacement reference).
    fn gather(&mut self, sl: Vec<u32>, sub: Vec<u32>, pairs: Vec<u32>) {
        let s = &mut self.state;
        let a = &mut s.act;
        a.sl_x.clear();
        a.sl_x.extend(sl.iter().map(|&i| s.sl_x[i as usize]));
        a.sl_v.clear();
        a.sl_v.extend(sl.iter().map(|&i| s.sl_v[i as usize]));
        // forces of the spheres that stay active carry over (the implicit mount's contact
        // velocity prediction reads them; velocity-Verlet recomputes them before any use)
        let mut f = vec![[0.0; 3]; sl.len()];
        let mut o = 0usize;
        for (k, &i) in sl.iter().enumerate() {
            while o < a.sl.len() && a.sl[o] < i {
                o += 1;
            }
            if o < a.sl.len() && a.sl[o] == i {
                f[k] = a.sl_f[o];
            }
        }
        a.sl_f = f;
        a.sl_x0.clone_from(&a.sl_x);
        a.sl = sl;
        a.sub_x.clear();
        a.sub_x.extend(sub.iter().map(|&j| s.sub_x[j as usize]));
        a.sub_v.clear();
        a.sub_v.extend(sub.iter().map(|&j| s.sub_v[j as usize]));
        a.sub_f.clear();
        a.sub_f.resize(sub.len(), [0.0; 2]);
        a.sub_x0.clone_from(&a.sub_x);
        a.sub = sub;
        a.hist.clear();
        a.hist
            .extend(pairs.iter().map(|&k| s.pairs.hist[k as usize]));
        a.out.clear();
        a.out.resize(pairs.len(), PairOut::default());
        a.pairs = pairs;
    }

    /// Recomputes the derived index data of the active set (after an evaluation or a
    /// checkpoint load): pair ranges per slider sphere, pair lists per substrate sphere, the
    /// inactive sums and the chunking.
    pub(crate) fn index(&mut self) {
        let s = &self.state;
        let a = &s.act;
        let na = a.sl.len();
        let nba = a.sub.len();
        let np = a.pairs.len();
        let idx = &mut self.idx;
        // pairs per active slider sphere (pairs and sliders are both ascending)
        idx.sl_pair_start.clear();
        idx.sl_pair_start.resize(na + 1, 0);
        let mut cursor = 0usize;
        for (p, &k) in a.pairs.iter().enumerate() {
            let i = s.pairs.i[k as usize];
            while a.sl[cursor] != i {
                cursor += 1;
                idx.sl_pair_start[cursor] = p as u32;
            }
        }
        for c in cursor + 1..=na {
            idx.sl_pair_start[c] = np as u32;
        }
        // dense substrate index of each pair
        idx.pair_b.clear();
        idx.pair_b.extend(a.pairs.iter().map(|&k| {
            let j = s.pairs.j[k as usize];
            a.sub
                .binary_search(&j)
                .expect("active pair's substrate sphere is active") as u32
        }));
        // pairs per active substrate sphere
        idx.sub_start.clear();
        idx.sub_start.resize(nba + 1, 0);
        for &b in &idx.pair_b {
            idx.sub_start[b as usize + 1] += 1;
        }
        for b in 0..nba {
            idx.sub_start[b + 1] += idx.sub_start[b];
        }
        let mut fill = idx.sub_start.clone();
        idx.sub_items.clear();
        idx.sub_items.resize(np, 0);
        for (p, &b) in idx.pair_b.iter().enumerate() {
            idx.sub_items[fill[b as usize] as usize] = p as u32;
            fill[b as usize] += 1;
        }
        // sums over the inactive slider spheres
        let n = s.sl_x.len();
        idx.n_in = n - na;
        idx.g_in = [[0.0; 3]; 3];
        idx.s_in = [0.0; 3];
        if idx.n_in > 0 {
            let mut c = 0usize;
            for i in 0..n {
                if c < na && a.sl[c] as usize == i {
                    c += 1;
                    continue;
                }
                let g = g_of(self.body.off[i]);
                for r in 0..3 {
                    idx.s_in[r] += g[r];
                    for q in 0..3 {
                        idx.g_in[r][q] += g[r] * g[q];
                    }
                }
            }
        }
        // inactive candidate pairs that failed at some time
        let mut on = vec![false; s.pairs.i.len()];
        for &k in &a.pairs {
            on[k as usize] = true;
        }
        idx.ever_failed_inactive = s
            .pairs
            .hist
            .iter()
            .zip(&on)
            .filter(|(h, &o)| !o && h.ever_failed)
            .count();
        idx.chunks = Chunking::for_work(
            na,
            nba,
            np,
            self.params.chunk_min,
            self.params.parallel_min_work,
        );
        idx.parts.clear();
        idx.parts.resize(idx.chunks.n_sl_chunks(na), [0.0; 6]);
    }
}
