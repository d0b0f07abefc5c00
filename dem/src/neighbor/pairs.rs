//! Verlet pair list with skin: build, history carry-over and the rebuild criterion.

use super::CellList;
use crate::system::{PairHist, PairList};
use rayon::prelude::*;

/// Whether any particle has moved more than `skin/2` since the last build (max over all
/// substrate and slider spheres; max is exact whatever the thread count).
pub fn needs_rebuild(
    sub_x: &[[f64; 2]],
    ref_sub: &[[f64; 2]],
    sl_x: &[[f64; 3]],
    ref_sl: &[[f64; 3]],
    skin: f64,
) -> bool {
    let lim = 0.25 * skin * skin;
    let a = sub_x
        .par_iter()
        .with_min_len(4096)
        .zip(ref_sub.par_iter())
        .map(|(p, q)| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2))
        .reduce(|| 0.0, f64::max);
    if a.is_nan() || a > lim {
        return true;
    }
    let b = sl_x
        .par_iter()
        .with_min_len(1024)
        .zip(ref_sl.par_iter())
        .map(|(p, q)| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2))
        .reduce(|| 0.0, f64::max);
    b.is_nan() || b > lim
}

/// New pair list of every (slider i, substrate j) with centre distance < `cutoff` (m), sorted
/// by (i, j); histories of pairs present in `old` are kept, new pairs start with zero history.
/// `sub_h` are the substrate heights. Cost O(N) + O(P) merge; allocates (only at rebuilds).
pub fn build_pairs(
    sub_x: &[[f64; 2]],
    sub_h: &[f64],
    sl_x: &[[f64; 3]],
    cutoff: f64,
    old: &PairList,
) -> PairList {
    let grid = CellList::new(sub_x, cutoff);
    let c2 = cutoff * cutoff;
    let per: Vec<Vec<u32>> = sl_x
        .par_iter()
        .with_min_len(256)
        .map(|p| {
            let mut v = Vec::new();
            grid.for_near([p[0], p[1]], |j| {
                let q = sub_x[j as usize];
                let d = [p[0] - q[0], p[1] - q[1], p[2] - sub_h[j as usize]];
                if d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < c2 {
                    v.push(j);
                }
            });
            v.sort_unstable();
            v
        })
        .collect();
    let total: usize = per.iter().map(|v| v.len()).sum();
    let mut out = PairList {
        i: Vec::with_capacity(total),
        j: Vec::with_capacity(total),
        hist: Vec::with_capacity(total),
    };
    let mut o = 0usize;
    for (i, js) in per.iter().enumerate() {
        let i = i as u32;
        for &j in js {
            while o < old.i.len() && (old.i[o], old.j[o]) < (i, j) {
                o += 1;
            }
            let h = if o < old.i.len() && (old.i[o], old.j[o]) == (i, j) {
                old.hist[o]
            } else {
                PairHist::default()
            };
            out.i.push(i);
            out.j.push(j);
            out.hist.push(h);
        }
    }
    out
}
