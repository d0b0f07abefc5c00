//! The order the pipeline takes the patterns in ([`Pipeline::order`]).

use super::search::{Order, Search};
use super::Pipeline;
use crate::study::design::model::{rank, Candidate, DesignScene};
use crate::study::design::observer::Event;
use crate::study::design::report_data::best::BEST_PATTERNS;
use anyhow::Result;

impl Pipeline<'_> {
    /// The order in which [`Pipeline::run`] takes the patterns ([`Order`]).
    ///
    /// With more than [`BEST_PATTERNS`] patterns and a tolerance, every pattern is first
    /// evaluated at its nominal orientation only (no robust search; stored, so the second pass
    /// reuses them): the patterns are then taken best nominal design first
    /// ([`rank::compare`]), and a pattern's candidates whose nominal limit is at most the
    /// [`BEST_PATTERNS`]-th best robust limit found so far are not searched over the
    /// tolerance box (the robust limit never exceeds the nominal one, so they cannot enter the
    /// top). Otherwise the order given, no floor. Cost: the nominal pass, about the design at
    /// tolerance 0 (docs/validation/tolerance-cost.md).
    pub fn order(&self, scenes: &[DesignScene]) -> Result<Order> {
        let given: Vec<usize> = (0..scenes.len()).collect();
        if self.plan.limit.tolerance_box().is_point() || scenes.len() <= BEST_PATTERNS {
            return Ok(Order {
                patterns: given,
                cross: false,
            });
        }
        self.obs.event(&Event::NominalFirst {
            patterns: scenes.len(),
        });
        let mut firsts: Vec<(usize, Option<Candidate>)> = Vec::new();
        for (i, ds) in scenes.iter().enumerate() {
            let pr = self.pattern(ds, Search::Nominal)?;
            firsts.push((
                i,
                pr.ranking.into_iter().next().map(|mut c| {
                    c.friction.truncate(1);
                    c
                }),
            ));
        }
        // best first; a stable sort keeps the order given among equals
        firsts.sort_by(|(_, a), (_, b)| match (a, b) {
            (Some(x), Some(y)) => rank::compare(x, y),
            (Some(_), None) => std::cmp::Ordering::Less,
            (None, Some(_)) => std::cmp::Ordering::Greater,
            (None, None) => std::cmp::Ordering::Equal,
        });
        Ok(Order {
            patterns: firsts.into_iter().map(|(i, _)| i).collect(),
            cross: true,
        })
    }
}
