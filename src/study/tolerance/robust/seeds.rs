//! The spread over substrate realisations: each seed's own limit at the nominal (θ, direction).

use super::RobustSearch;
use anyhow::Result;

impl RobustSearch<'_> {
    /// The superlubric limit (loads) of each substrate seed at the nominal offset, in seed
    /// order: the spread behind the robust limit, which is the worst over the box and every
    /// seed. Estimates each seed's missing loads up to its first known failure (or its placement
    /// bound) on one path. Cost: at most one path per seed.
    pub fn seed_limits(&mut self) -> Result<Vec<usize>> {
        let nominal: Vec<usize> = (0..self.solvers.len())
            .filter_map(|si| {
                self.state.samples.iter().position(|s| {
                    s.seed == si && s.theta_offset_deg == 0.0 && s.direction_offset_deg == 0.0
                })
            })
            .collect();
        let todo: Vec<(usize, Vec<usize>)> = nominal
            .iter()
            .map(|&i| {
                let rows = &self.state.samples[i].rows;
                let upto = self.limit_bound(i);
                (i, (0..upto).filter(|&k| rows[k].is_none()).collect())
            })
            .filter(|(_, w): &(usize, Vec<usize>)| !w.is_empty())
            .collect();
        self.estimate(&todo)?;
        Ok(nominal
            .iter()
            .map(|&i| {
                let rows = &self.state.samples[i].rows;
                let upto = self.limit_bound(i);
                (0..upto)
                    .take_while(|&k| rows[k].as_ref().is_some_and(|r| self.ok(r)))
                    .count()
            })
            .collect())
    }
}
