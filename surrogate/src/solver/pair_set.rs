//! [`PairSet`]: the candidate contact pairs of one slider pose, shared by every load and model.

use crate::contact::CandidatePair;

/// Candidate slider–substrate pairs of one lateral pose (θ, shift), with the lever arms needed by
/// the tilt and compliant models. The pairs are load- and height-independent (lateral distance
/// < 2R), so one `PairSet` serves every load of a θ. Build with [`super::Solver::pairs_at`].
#[derive(Debug, Clone, Default)]
pub struct PairSet {
    /// Slider sphere centres `[x, y]` (m) in the substrate frame.
    pub slider_xy: Vec<[f64; 2]>,
    /// Disc centre `[x, y]` (m) in the substrate frame.
    pub centre: [f64; 2],
    /// Rotation θ (rad) of the slider lattice at this pose (orients the mount's tilt stiffness).
    pub theta: f64,
    /// Candidate pairs, in slider-then-substrate index order.
    pub pairs: Vec<CandidatePair>,
}

impl PairSet {
    /// Lever arm `[x_i − x_c, y_i − y_c]` (m) of slider sphere `i` about the disc centre.
    #[inline]
    pub fn arm(&self, i: u32) -> [f64; 2] {
        let p = self.slider_xy[i as usize];
        [p[0] - self.centre[0], p[1] - self.centre[1]]
    }

    /// Ranges of `pairs` sharing one slider sphere: `(slider index, start..end)`.
    pub fn groups(&self) -> Vec<(u32, std::ops::Range<usize>)> {
        let mut out = Vec::new();
        let mut s = 0;
        while s < self.pairs.len() {
            let i = self.pairs[s].slider;
            let mut e = s + 1;
            while e < self.pairs.len() && self.pairs[e].slider == i {
                e += 1;
            }
            out.push((i, s..e));
            s = e;
        }
        out
    }
}
