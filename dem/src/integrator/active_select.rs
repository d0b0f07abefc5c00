//! The choice of a new active set at an evaluation ([`Sim::evaluate`], see `active.rs`):
//! which pairs and particles are active, and the ringing lists of the spheres that leave or
//! enter the set, with the aggregate mode the control layer feels.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::g_of;
use super::ring::amplitude;
use super::sim::Sim;

/// Ringing deviations below this amplitude (m) are forgotten individually (they stay in the
/// aggregate mode): far below the round-off of any position (~10⁻²⁰ m).
const DROP_AMPLITUDE: f64 = 1e-25;

impl Sim {
    /// The new active set (sorted slider, substrate and candidate-pair indices) and the new
    /// ringing lists: a sphere that leaves the set keeps its deviation from the rest state as a
    /// ringing entry (added to the aggregate mode); one that enters it leaves the ringing list
    /// (its deviation taken out of the aggregate). At construction, spheres off their rest state
    /// stay active instead.
    pub(super) fn select(
        &mut self,
        was_sl: &[bool],
        was_sub: &[bool],
        old_pairs: &[(u32, u32)],
        initial: bool,
    ) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
        let n = was_sl.len();
        let nb = was_sub.len();
        let mut sl_on = vec![false; n];
        let mut sub_on = vec![false; nb];
        let (pairs, late) = self.active_pairs(&mut sl_on, &mut sub_on, old_pairs, initial);
        // per-site sizes: a body whose spheres differ in mass keeps every sphere integrated (the
        // common mode of the free slider spheres and the ringing maps take one mass); the
        // other body's spheres still leave the set
        if self.spec.slider_radii.is_some() {
            sl_on.fill(true);
        }
        if self.spec.substrate_radii.is_some() {
            sub_on.fill(true);
        }
        let [w_xy, w_z, w_b] = self.free_omega2();
        let (ring_sl, ring_sl_dev, on_sl, off_sl) =
            self.ring_slider(&mut sl_on, was_sl, initial, [w_xy, w_z]);
        let (ring_sub, ring_sub_dev, on_sub, off_sub) =
            self.ring_substrate(&mut sub_on, was_sub, initial, w_b);
        let (on, off) = (on_sl + on_sub, off_sl + off_sub);
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

    /// The candidate pairs within the activation margin (indices into the pair list, sorted),
    /// their spheres marked in `sl_on` / `sub_on`, and how many of them entered the set already
    /// overlapping (late: the margin was too small).
    fn active_pairs(
        &self,
        sl_on: &mut [bool],
        sub_on: &mut [bool],
        old_pairs: &[(u32, u32)],
        initial: bool,
    ) -> (Vec<u32>, u64) {
        let margin = self.params.active.margin;
        let two_r = self.spec.contact_distance();
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
        (pairs, late)
    }

    /// The slider spheres' new ringing list (indices, deviations) and how many spheres entered
    /// and left the set; a sphere leaving is added to the aggregate mode, one entering taken out
    /// of it (at construction, one off its rest state stays on in `sl_on`). `w`: the free
    /// modes' ω² (lateral, normal).
    fn ring_slider(
        &mut self,
        sl_on: &mut [bool],
        was_sl: &[bool],
        initial: bool,
        [w_xy, w_z]: [f64; 2],
    ) -> (Vec<u32>, Vec<[f64; 6]>, u64, u64) {
        let n = was_sl.len();
        // slider spheres: deviations of the ringing ones, as of now
        let mut dev_sl: Vec<Option<[f64; 6]>> = vec![None; n];
        for (k, &i) in self.state.ringing.sl.iter().enumerate() {
            dev_sl[i as usize] = Some(self.state.ringing.sl_dev[k]);
        }
        let rigid = self.params.mount.rigid_z;
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
        (ring_sl, ring_sl_dev, on, off)
    }

    /// The substrate spheres' new ringing list (indices, deviations) and how many spheres
    /// entered and left the set (at construction, one off its site stays on in `sub_on`). `w_b`:
    /// the substrate tether's ω².
    fn ring_substrate(
        &self,
        sub_on: &mut [bool],
        was_sub: &[bool],
        initial: bool,
        w_b: f64,
    ) -> (Vec<u32>, Vec<[f64; 4]>, u64, u64) {
        let nb = was_sub.len();
        let (mut on, mut off) = (0u64, 0u64);
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
        (ring_sub, ring_sub_dev, on, off)
    }

    /// Adds (`sign` = 1) or removes (−1) a slider sphere's deviation `d` (with its `g`) to / from
    /// the aggregate mode the control layer feels.
    fn aggregate_sl(&mut self, d: [f64; 6], g: [f64; 3], sign: f64) {
        let c = &mut self.state.common;
        for k in 0..2 {
            c.d[k] += sign * d[k];
            c.dv[k] += sign * d[3 + k];
        }
        if !self.params.mount.rigid_z {
            for r in 0..3 {
                c.dz[r] += sign * d[2] * g[r];
                c.dzv[r] += sign * d[5] * g[r];
            }
        }
    }
}
