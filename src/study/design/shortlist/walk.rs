//! The level walk of one pattern: which shortlist level is evaluated next, which is skipped
//! under a robust floor, and when the walk stops ([`LevelWalk`]). The rule is the
//! shortlist's bound ([`super::ShortlistStage`] module docs): a design is superlubric at most up to
//! its orientation's coating-intact load, so a level whose load is below the best limit found
//! (once the ranking holds the designs it needs) cannot beat it. Cost: comparisons, and where a
//! floor applies one placement solve per pick and θ offset (`robust::level_reach`).

use crate::study::design::model::{Candidate, Stop};
use crate::study::rows::label;
use anyhow::Result;
use surrogate::units::n_to_mn;

/// What the walk does with the next level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Next {
    /// Evaluate it (α scan, estimate and, with a tolerance, the robust search).
    Evaluate,
    /// Skip it: under the floor, its orientations cannot exceed it over the tolerance box.
    Skip,
    /// Stop: no level from here on can reach the best limit found.
    Stop,
}

/// The walk over a pattern's shortlist levels, highest first (see the module docs).
#[derive(Debug, Clone)]
pub struct LevelWalk {
    /// Designs the ranking must hold before the walk may stop or skip.
    need: usize,
    /// The robust floor (mN; 0: none), applied only with a robust search.
    floor_mn: f64,
    /// Whether the robust search runs (a tolerance, and not the nominal pass).
    robust: bool,
    /// The best exact superlubric limit so far (mN).
    best_mn: f64,
    /// Levels taken so far (evaluated or skipped).
    taken: usize,
    /// Levels skipped under the floor (indices into the levels).
    skipped: Vec<usize>,
    /// Why the walk stopped.
    stop: Stop,
}

/// Where a pattern's walk ended: the levels taken and skipped and why it stopped.
#[derive(Debug, Clone, PartialEq)]
pub struct Walked {
    /// Levels taken from the top (evaluated or skipped).
    pub taken: usize,
    /// Levels skipped under the floor (indices into the levels).
    pub skipped: Vec<usize>,
    /// Why the walk stopped.
    pub stop: Stop,
}

impl LevelWalk {
    /// A walk needing `need` designs before it stops, with the robust floor `floor_mn` (mN; 0:
    /// none) where `robust`.
    pub fn new(need: usize, floor_mn: f64, robust: bool) -> Self {
        LevelWalk {
            need,
            floor_mn,
            robust,
            best_mn: 0.0,
            taken: 0,
            skipped: Vec::new(),
            stop: Stop::EveryLevel,
        }
    }

    /// What to do with level `li` of load `load` (N), given the `ranking` so far; `reach` is
    /// the most (mN) the level's orientations can reach over the tolerance box, asked only
    /// where a floor applies and the level's load is above it.
    pub fn next(
        &mut self,
        li: usize,
        load: f64,
        ranking: &[Candidate],
        reach: impl FnOnce() -> Result<f64>,
    ) -> Result<Next> {
        let w_mn = label(n_to_mn(load));
        let enough = ranking.len() >= self.need;
        if w_mn < self.best_mn && enough {
            self.stop = Stop::Before {
                level: load,
                reach_mn: w_mn,
                best_mn: self.best_mn,
            };
            return Ok(Next::Stop);
        }
        self.taken += 1;
        // with a floor (many patterns): a level whose orientations cannot exceed it over the
        // tolerance box is evaluated only where the nominal pass evaluated it (stored), for
        // the pattern's own ranking, and skipped otherwise
        if self.robust && self.floor_mn > 0.0 {
            let reach = if w_mn <= self.floor_mn {
                w_mn
            } else {
                reach()?
            };
            let nominal_best = ranking
                .iter()
                .map(|c| c.score.nominal_to_mn)
                .fold(self.best_mn, f64::max);
            if reach <= self.floor_mn && w_mn < nominal_best && enough {
                self.skipped.push(li);
                return Ok(Next::Skip);
            }
        }
        Ok(Next::Evaluate)
    }

    /// Records a level's evaluation: the best exact limit of `ranking` (the stop rule then
    /// compares each level's load with it: a robust design may sit lower than its level).
    pub fn evaluated(&mut self, ranking: &[Candidate]) {
        self.best_mn = ranking
            .iter()
            .filter(|c| c.score.exact)
            .map(|c| c.score.superlubric_to_mn)
            .fold(self.best_mn, f64::max);
    }

    /// The floor (mN; 0: none).
    pub fn floor_mn(&self) -> f64 {
        self.floor_mn
    }

    /// Where the walk ended.
    pub fn end(self) -> Walked {
        Walked {
            taken: self.taken,
            skipped: self.skipped,
            stop: self.stop,
        }
    }
}
