//! The leaf of the engine: the small kernels every pass uses (kicks, the NaN-propagating max,
//! the pulling spring's stretch) and the active set's derived [`Index`]. It imports no sibling
//! that knows [`super::Sim`], so the files that add `impl Sim` blocks (`sim.rs`, `build.rs`,
//! `step.rs`, `forces.rs`, `active.rs`, `active_select.rs`, `active_index.rs`, `observe.rs`)
//! and the mount (`mount.rs`) share these without importing each other.

use super::chunks::Chunking;
use crate::model::ContactBatch;
use crate::params::SimParams;

/// Half kick `v += h·f/m` (m/s, N, s, kg).
#[inline]
pub(crate) fn kick(v: &mut f64, f: f64, h: f64, m: f64) {
    *v += h * f / m;
}

/// Kick with the precomputed `h/m` (no division in the particle loops).
#[inline]
pub(crate) fn kick_hm(v: &mut f64, f: f64, hm: f64) {
    *v += f * hm;
}

/// Max that propagates NaN (a non-finite displacement must reach the caller).
#[inline]
pub(crate) fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Pulling-spring stretch (m): the spring's rest anchor (the support moved back by the lead along
/// α) minus the control layer's centre `cl`, in x and y. The spring force is K0 times this.
#[inline]
pub(crate) fn spring_stretch(p: &SimParams, support: [f64; 2], cl: [f64; 3]) -> [f64; 2] {
    let (sa, ca) = p.protocol.alpha.sin_cos();
    [
        support[0] - p.protocol.support_lead * ca - cl[0],
        support[1] - p.protocol.support_lead * sa - cl[1],
    ]
}

/// Derived index data of the active set (rebuilt at each evaluation and after a checkpoint
/// load; never checkpointed).
#[derive(Debug, Clone, Default)]
pub(crate) struct Index {
    /// Per active slider sphere: its active pairs are `sl_pair_start[a]..sl_pair_start[a+1]`.
    pub sl_pair_start: Vec<u32>,
    /// Per active pair: the dense index of its substrate sphere.
    pub pair_b: Vec<u32>,
    /// Per active substrate sphere: its pairs are `sub_items[sub_start[b]..sub_start[b+1]]`.
    pub sub_start: Vec<u32>,
    /// Active-pair indices, grouped by substrate sphere, ascending within a group.
    pub sub_items: Vec<u32>,
    /// Inactive slider spheres.
    pub n_in: usize,
    /// Σ g gᵀ over the inactive slider spheres.
    pub g_in: [[f64; 3]; 3],
    /// Σ g over the inactive slider spheres.
    pub s_in: [f64; 3],
    /// Inactive candidate pairs whose coating failed at some time.
    pub ever_failed_inactive: usize,
    /// Chunking of the slider and substrate passes.
    pub chunks: Chunking,
    /// Per slider chunk: its reaction on the control layer (lateral x, y; generalized z, t_x,
    /// t_y) and the largest p0 (Pa) of its pairs.
    pub parts: Vec<[f64; 6]>,
    /// Per slider chunk: the pass's scratch [`ContactBatch`] (empty between passes; kept so
    /// that no pass zeroes one).
    pub batches: Vec<ContactBatch>,
}
