//! The candidate-pair searches of a [`Solver`]: the slider's sites at a pose, its pairs at a
//! pose or within a margin of it, the pairs swept along a straight stretch, and the pairs of a
//! pose taken from a wider set.

use super::{PairSet, Pose, Solver};
use crate::contact::{swept_distance2, CandidatePair};
use crate::scene::place;

impl Solver {
    /// Slider sphere centres `[x, y]` (m) and the disc centre at `pose`. O(N_slider).
    fn slider_xy_at(&self, pose: Pose) -> (Vec<[f64; 2]>, [f64; 2]) {
        let mut slider_xy = Vec::with_capacity(self.local.len());
        let centre = self.fill_slider_xy(pose, &mut slider_xy);
        (slider_xy, centre)
    }

    /// Replaces `out` with the slider sphere centres `[x, y]` (m) at `pose` ([`place`] of each
    /// site) and returns the disc centre. O(N_slider), no allocation once `out` has grown.
    pub(super) fn fill_slider_xy(&self, pose: Pose, out: &mut Vec<[f64; 2]>) -> [f64; 2] {
        let centre = self.centre_at(pose);
        let sc = pose.theta.sin_cos();
        out.clear();
        out.extend(self.local.iter().map(|&p| place(centre, sc, p)));
        centre
    }

    /// The disc centre `[x, y]` (m) at `pose`: the scene's offset plus the pose's shift. O(1).
    #[inline]
    pub(crate) fn centre_at(&self, pose: Pose) -> [f64; 2] {
        [
            self.scene.slider.offset[0] + pose.shift[0],
            self.scene.slider.offset[1] + pose.shift[1],
        ]
    }

    /// Candidate pairs (lateral distance < 2R) of the slider at `pose`. O(N_slider) with the
    /// grid, O(N_slider log N_substrate) with the BVH. Load-independent: reuse for every load.
    pub fn pairs_at(&self, pose: Pose) -> PairSet {
        self.pairs_within(pose, 0.0)
    }

    /// Candidate pairs of the slider at `pose` with lateral distance < 2R + `extra` (m): a
    /// superset of the pairs of every pose with the same θ whose shift lies within `extra` of
    /// `pose.shift`. Turn it into the pairs of such a pose with [`Solver::pairs_from`] (a path
    /// then searches once per segment instead of once per sample).
    pub fn pairs_within(&self, pose: Pose, extra: f64) -> PairSet {
        let (slider_xy, centre) = self.slider_xy_at(pose);
        let mut pairs = Vec::with_capacity(slider_xy.len() * 3);
        let extra = extra.max(0.0);
        self.candidate_search()
            .pairs(&slider_xy, self.reach + extra, &mut pairs);
        if let Some(s) = &self.sizes {
            // each pair's own reach r_i + r_j (+ extra)
            pairs.retain(|c| {
                let d = s.distance(c.slider, c.substrate) + extra;
                c.r2 < d * d
            });
        }
        PairSet {
            slider_xy,
            centre,
            theta: pose.theta,
            pairs,
        }
    }

    /// The pairs that come within contact distance (plus a round-off margin) of each other
    /// somewhere on the straight stretch of poses `pose.shift ± half` (m) at `pose.theta`: a
    /// superset of every such pose's pairs, for [`Solver::pairs_from`], from one grid scan of
    /// each sphere's swept capsule
    /// ([`GridSearch::pairs_swept`](crate::contact::GridSearch::pairs_swept)). O(N_slider).
    ///
    /// Fills `out` (its buffers reused: no allocation once they have grown).
    ///
    /// `floor` (m, absolute; −∞: every pair): only the pairs whose touch height
    /// `h + drop + √(d² − r²)` can rise above it are needed, so the capsules shrink to the
    /// lateral distance `ρ = √(d² − (floor − h_max − drop_max)²)` below which any pair can
    /// (with a margin); a superset of the pairs a floor at or above `floor` keeps.
    ///
    /// `extra` (m, ≥ 0) widens every capsule: the pairs of every stretch whose poses lie within
    /// `extra` of this one's (a path in a nearby direction).
    pub(crate) fn pairs_swept_into(
        &self,
        pose: Pose,
        half: [f64; 2],
        floor: f64,
        extra: f64,
        out: &mut PairSet,
    ) {
        out.centre = self.fill_slider_xy(pose, &mut out.slider_xy);
        out.theta = pose.theta;
        out.pairs.clear();
        let slider_xy = &out.slider_xy;
        let pairs = &mut out.pairs;
        let margin = 1e-9 * self.reach + 1e-15;
        let rise = floor - self.top_base;
        let reach = if rise > 0.0 {
            ((self.reach * self.reach - rise * rise).max(0.0).sqrt() * (1.0 + 1e-8)).min(self.reach)
        } else {
            self.reach
        };
        self.grid
            .pairs_swept(slider_xy, half, reach + margin + extra, pairs);
        if let Some(s) = &self.sizes {
            // each pair's own reach r_i + r_j, swept
            let h2 = half[0] * half[0] + half[1] * half[1];
            pairs.retain(|c| {
                let p = slider_xy[c.slider as usize];
                let q = self.substrate[c.substrate as usize];
                let v = [q[0] - p[0], q[1] - p[1]];
                let d = s.distance(c.slider, c.substrate) + margin + extra;
                swept_distance2(v, half, h2) < d * d
            });
        }
    }

    /// The pairs of `pose` (lateral distance < 2R) taken from `near`, a [`Solver::pairs_within`]
    /// set of the same θ built with `extra` ≥ the distance between the two shifts: identical to
    /// [`Solver::pairs_at`]`(pose)` (same order, same r² arithmetic), without a candidate search.
    /// O(pairs of `near`).
    pub fn pairs_from(&self, near: &PairSet, pose: Pose) -> PairSet {
        let (slider_xy, centre) = self.slider_xy_at(pose);
        let reach = self.reach;
        let r2max = reach * reach;
        let pairs = near
            .pairs
            .iter()
            .filter_map(|c| {
                let p = slider_xy[c.slider as usize];
                let q = self.substrate[c.substrate as usize];
                let dx = q[0] - p[0];
                let dy = q[1] - p[1];
                let r2 = dx * dx + dy * dy;
                let max = match &self.sizes {
                    None => r2max,
                    Some(s) => s.distance(c.slider, c.substrate).powi(2),
                };
                (r2 < max).then_some(CandidatePair { r2, ..*c })
            })
            .collect();
        PairSet {
            slider_xy,
            centre,
            theta: pose.theta,
            pairs,
        }
    }
}
