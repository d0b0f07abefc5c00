//! What a design keeps of a pattern once its own files are written: [`PatternResult::trim`]
//! drops the rows that only those files need (the screen, the orientations, the α scans and
//! friction rows of the evaluated θ, the friction rows of candidates below the top few), so the
//! memory of a design over many patterns (`design --patterns DIR/index.csv`) does not grow with
//! their rows. What stays is what the DEM stage, the answers, the report, `ranking.csv` and
//! `patterns.csv` read: every candidate's score and its lowest-load friction row, the full
//! friction rows of the top designs, the levels, θ list and wall times.

use super::pattern_result::PatternResult;

/// Designs per pattern drawn in the μ-versus-load chart (`mu_<p>.png`): the top ones keep
/// their friction rows after [`PatternResult::trim`].
pub const CHART_DESIGNS: usize = 5;

impl PatternResult {
    /// Drops the rows that only the pattern's own files need (see the module docs); the ranks
    /// kept whole are the top `max(confirmed, CHART_DESIGNS)` (`confirmed`: the designs per
    /// pattern the DEM confirms; the DEM runs, the answers, the μ chart; they keep their
    /// corner estimates, which sit beside their corner DEM runs).
    /// Call after the pattern's estimates for the DEM
    /// ([`super::super::design`] does) and after `resonance_flagged` is counted. Idempotent.
    /// Cost: frees O(screen rows + scan rows + friction rows) of memory.
    pub fn trim(&mut self, confirmed: usize) {
        self.screen = Vec::new();
        self.orientations = Vec::new();
        for e in &mut self.evaluated {
            e.eval.scan = Vec::new();
            e.eval.friction = Vec::new();
        }
        let keep = confirmed.max(CHART_DESIGNS);
        for c in self.ranking.iter_mut().skip(keep) {
            c.friction.truncate(1);
            c.friction.shrink_to_fit();
            c.corners = Vec::new();
        }
        self.trimmed = true;
    }
}
