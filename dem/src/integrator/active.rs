//! The active set: which particles are integrated step by step.
//!
//! A substrate sphere at rest at its tether site with no contact feels no force and stays
//! there. A slider sphere with no contact obeys a linear equation driven only by the control
//! layer (spring and damping relative to its anchor), so every such sphere that starts in the
//! same relative state keeps sharing it: one *common mode* (lateral `u`, vertical `w_i = g_i·w`)
//! is integrated for all of them, and its reaction `N_in·k·u` (lateral), `k_z·Σ_in g gᵀ·w`
//! (vertical) acts on the control layer. That is exact, not an approximation.
//!
//! At each *evaluation* a pair is active when its gap (centre distance − 2R) is below
//! `active_margin`; a particle is active when it is in an active pair, or when it deviates from
//! its rest / common-mode state by more than the tolerance (ringing down after a contact). Below
//! the tolerance it is snapped to that state (error ≤ tolerance). An evaluation runs as soon as
//! some particle may have moved `active_margin/2` since the last one (active particles: their
//! own displacement; inactive slider spheres: a bound from the control layer and the common
//! mode; inactive substrate spheres do not move), so an inactive pair cannot close its gap
//! before it is activated — the skin argument of a Verlet list. The candidate pair list (within
//! `2R + skin`) is rebuilt when a particle may have moved `(skin − margin)/2` since its build.
//!
//! Without the active set every particle and candidate pair is active, each evaluation
//! rebuilds the list (the plain Verlet list with skin), and the common mode is empty.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::{dot3, g_of};
use super::chunks::Chunking;
use super::sim::Sim;
use crate::model::PairOut;
use crate::neighbor::build_pairs;

impl Sim {
    /// Re-evaluates the active set (see the module doc). `initial`: every particle is checked
    /// against its rest state (at construction). Cost O(N + P) over all particles and candidate
    /// pairs; allocates.
    pub(crate) fn evaluate(&mut self, initial: bool) {
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
        self.materialize(&was_sl);
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
        let s = &mut self.state;
        s.mark.cl = s.cl_x;
        s.mark.tilt = s.tilt;
        s.mark.u = s.common.u;
        s.mark.w = s.common.w;
        if !initial {
            s.stats.evaluations += 1;
        }
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

    /// Global positions of the inactive slider spheres from the common mode.
    fn materialize(&mut self, was_sl: &[bool]) {
        for i in 0..was_sl.len() {
            if !was_sl[i] {
                let (x, v) = self.common_state(i);
                self.state.sl_x[i] = x;
                self.state.sl_v[i] = v;
            }
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
        let cutoff = 2.0 * self.spec.sphere_radius + self.params.skin;
        s.pairs = build_pairs(&s.sub_x, &self.sub_h, &s.sl_x, cutoff, &s.pairs);
        s.ref_sub.clone_from(&s.sub_x);
        s.ref_sl.clone_from(&s.sl_x);
        s.builds += 1;
    }

    /// Deviation of slider sphere `i` from the common mode, as the amplitude of the spring
    /// force it implies (N): `√((kΔx)² + k m Δv²)` laterally and vertically (full model).
    fn slider_deviation(&self, i: usize) -> f64 {
        let (xc, vc) = self.common_state(i);
        let x = self.state.sl_x[i];
        let v = self.state.sl_v[i];
        let (k, m) = (self.params.k_slider_xy, self.body.m_s);
        let dx = [x[0] - xc[0], x[1] - xc[1]];
        let dv = [v[0] - vc[0], v[1] - vc[1]];
        let lat = (k * k * (dx[0] * dx[0] + dx[1] * dx[1])
            + k * m * (dv[0] * dv[0] + dv[1] * dv[1]))
            .sqrt();
        if self.params.rigid_z {
            return lat;
        }
        let kz = self.params.k_slider_z;
        let (dz, dvz) = (x[2] - xc[2], v[2] - vc[2]);
        lat.max((kz * kz * dz * dz + kz * m * dvz * dvz).sqrt())
    }

    /// Deviation of substrate sphere `j` from rest at its site, as a spring-force amplitude (N).
    fn substrate_deviation(&self, j: usize) -> f64 {
        let x = self.state.sub_x[j];
        let v = self.state.sub_v[j];
        let site = self.spec.substrate[j];
        let (k, m) = (self.params.k_substrate_xy, self.body.m_s);
        let dx = [x[0] - site[0], x[1] - site[1]];
        (k * k * (dx[0] * dx[0] + dx[1] * dx[1]) + k * m * (v[0] * v[0] + v[1] * v[1])).sqrt()
    }

    /// The new active set (sorted slider, substrate and candidate-pair indices); snaps the
    /// particles that leave it.
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
        let two_r = 2.0 * self.spec.sphere_radius;
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
        let tol = self.params.active_tol * self.params.load.abs();
        let (mut on, mut off) = (0u64, 0u64);
        for i in 0..n {
            if sl_on[i] {
                on += (!was_sl[i]) as u64;
            } else if was_sl[i] {
                if self.slider_deviation(i) > tol {
                    sl_on[i] = true;
                } else {
                    let (x, v) = self.common_state(i);
                    self.state.sl_x[i] = x;
                    self.state.sl_v[i] = v;
                    off += 1;
                }
            }
        }
        for j in 0..nb {
            if sub_on[j] {
                on += (!was_sub[j]) as u64;
            } else if was_sub[j] {
                if self.substrate_deviation(j) > tol {
                    sub_on[j] = true;
                } else {
                    let site = self.spec.substrate[j];
                    self.state.sub_x[j] = [site[0], site[1]];
                    self.state.sub_v[j] = [0.0; 2];
                    off += 1;
                }
            }
        }
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

    /// Packs the active particles and pairs densely (positions at this evaluation become the
    /// displacement reference).
    fn gather(&mut self, sl: Vec<u32>, sub: Vec<u32>, pairs: Vec<u32>) {
        let s = &mut self.state;
        let a = &mut s.act;
        a.sl_x.clear();
        a.sl_x.extend(sl.iter().map(|&i| s.sl_x[i as usize]));
        a.sl_v.clear();
        a.sl_v.extend(sl.iter().map(|&i| s.sl_v[i as usize]));
        a.sl_f.clear();
        a.sl_f.resize(sl.len(), [0.0; 3]);
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
        idx.parts.resize(idx.chunks.n_sl_chunks(na), [0.0; 5]);
    }
}
