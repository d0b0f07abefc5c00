//! [`BvhSearch`]: candidate pairs from a parry3d bounding-volume hierarchy over the substrate
//! spheres.

use super::candidates::push_if_within;
use super::{CandidatePair, CandidateSearch};
use parry3d_f64::bounding_volume::Aabb;
use parry3d_f64::math::Vector;
use parry3d_f64::partitioning::{Bvh, BvhBuildStrategy};

/// A parry3d [`Bvh`] whose leaves are the axis-aligned boxes of the substrate spheres
/// (centre `[x, y, h]`, half extent = sphere radius). A slider sphere at lateral position
/// `(x, y)` queries the box `[x ± reach, y ± reach] × [h_min, h_max]`, i.e. every substrate
/// sphere that can touch it at any slider height; the hits are then filtered by exact lateral
/// distance `< reach`.
///
/// Works for any lattice, perturbed heights and irregular substrates. Build O(N log N);
/// query O(log N + hits) per slider sphere.
pub struct BvhSearch {
    spheres: Vec<[f64; 3]>,
    bvh: Bvh,
    z_range: [f64; 2],
    radius: f64,
}

impl BvhSearch {
    /// Builds the hierarchy over `spheres` `[x, y, h]` (m) of radius `radius` (m).
    pub fn new(spheres: &[[f64; 3]], radius: f64) -> Self {
        let leaves: Vec<Aabb> = spheres
            .iter()
            .map(|p| {
                Aabb::from_half_extents(
                    Vector::new(p[0], p[1], p[2]),
                    Vector::new(radius, radius, radius),
                )
            })
            .collect();
        let bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves);
        let mut z_range = [f64::INFINITY, f64::NEG_INFINITY];
        for p in spheres {
            z_range[0] = z_range[0].min(p[2] - radius);
            z_range[1] = z_range[1].max(p[2] + radius);
        }
        if spheres.is_empty() {
            z_range = [0.0, 0.0];
        }
        BvhSearch {
            spheres: spheres.to_vec(),
            bvh,
            z_range,
            radius,
        }
    }

    /// The substrate spheres `[x, y, h]` (m) the hierarchy was built on.
    pub fn spheres(&self) -> &[[f64; 3]] {
        &self.spheres
    }
}

impl CandidateSearch for BvhSearch {
    fn pairs(&self, slider_xy: &[[f64; 2]], reach: f64, out: &mut Vec<CandidatePair>) {
        let r2max = reach * reach;
        // Leaf boxes are ±radius around the centre, so a query half-width of reach − radius
        // (inclusive test) already finds every centre with |dx|, |dy| ≤ reach.
        let half = (reach - self.radius).max(0.0);
        let mut local: Vec<CandidatePair> = Vec::with_capacity(16);
        for (si, p) in slider_xy.iter().enumerate() {
            let query = Aabb::new(
                Vector::new(p[0] - half, p[1] - half, self.z_range[0]),
                Vector::new(p[0] + half, p[1] + half, self.z_range[1]),
            );
            local.clear();
            for k in self.bvh.intersect_aabb(&query) {
                push_if_within(&mut local, si, *p, k, self.spheres[k as usize], r2max);
            }
            local.sort_by_key(|c| c.substrate);
            out.extend_from_slice(&local);
        }
    }
}
