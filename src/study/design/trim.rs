//! What a design keeps of a pattern once its own files are written: [`PatternResult::trim`]
//! drops the rows that only those files need (the screen, the orientations, the α scans and
//! friction rows of the evaluated θ, the friction rows of candidates below the top few), so the
//! memory of a design over many patterns (`design --patterns DIR/index.csv`) does not grow with
//! their rows. What stays is what the DEM stage, the answers, the report, `ranking.csv` and
//! `patterns.csv` read: every candidate's score and its lowest-load friction row, the full
//! friction rows of the top designs, the levels, θ list and wall times.

use super::confirm::corner_jobs;
use super::rank::Candidate;
use super::{DesignParams, PatternResult};

/// Designs per pattern drawn in the μ-versus-load chart (`mu_<p>.png`): the top ones keep
/// their friction rows after [`PatternResult::trim`].
pub const CHART_DESIGNS: usize = 5;

/// Candidates of `ranking` with a load whose failed contacts sit on a mount in resonance (the
/// report's resonance note). Cost: one pass over the friction rows.
pub fn resonance_flagged(ranking: &[Candidate]) -> usize {
    ranking
        .iter()
        .filter(|c| c.friction.iter().any(|r| r.mount_resonance == Some(true)))
        .count()
}

impl PatternResult {
    /// Drops the rows that only the pattern's own files need (see the module docs); the ranks
    /// kept whole are the top `max(confirm, CHART_DESIGNS)` (the DEM runs, the answers, the
    /// μ chart) and, with the DEM, a candidate at a tolerance corner of the best design (its
    /// estimate sits beside that DEM run). Call after the pattern's estimates for the DEM
    /// ([`super::design`] does) and after `resonance_flagged` is counted. Idempotent.
    /// Cost: frees O(screen rows + scan rows + friction rows) of memory.
    pub fn trim(&mut self, p: &DesignParams) {
        self.screen = Vec::new();
        self.orientations = Vec::new();
        for e in &mut self.evaluated {
            e.eval.scan = Vec::new();
            e.eval.friction = Vec::new();
        }
        let keep = p.confirm.max(CHART_DESIGNS);
        let corners: Vec<(f64, f64)> = match (p.no_dem, self.ranking.first()) {
            (false, Some(best)) => corner_jobs(self, best, p)
                .into_iter()
                .map(|(_, e)| (e.2, e.3))
                .collect(),
            _ => Vec::new(),
        };
        for c in self.ranking.iter_mut().skip(keep) {
            if !corners.contains(&(c.theta_deg, c.alpha_deg)) {
                c.friction.truncate(1);
                c.friction.shrink_to_fit();
            }
        }
        self.trimmed = true;
    }
}
