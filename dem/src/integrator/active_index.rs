//! The dense packing of the active set at an evaluation ([`Sim::evaluate`], see `active.rs`)
//! and its derived index: pair ranges per slider sphere, pair lists per substrate sphere, the
//! inactive sums and the chunking.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::body::g_of;
use super::chunks::Chunking;
use super::sim::Sim;
use crate::model::{ContactBatch, PairOut};

impl Sim {
    /// Packs the active particles and pairs densely (positions at this evaluation become the
    /// displacement reference).
    pub(super) fn gather(&mut self, sl: Vec<u32>, sub: Vec<u32>, pairs: Vec<u32>) {
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
            self.params.numerics.chunk_min,
            self.params.numerics.parallel_min_work,
        );
        idx.parts.clear();
        idx.parts.resize(idx.chunks.n_sl_chunks(na), [0.0; 6]);
        if idx.batches.len() < idx.parts.len() {
            idx.batches
                .resize_with(idx.parts.len(), ContactBatch::default);
        }
    }
}
