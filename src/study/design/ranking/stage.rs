//! The ranking stage of one pattern ([`RankStage`]; module docs of [`super`]).

use super::below_ladder::{self, BELOW_LADDER_DESIGNS};
use super::by_yield;
use super::params::RankParams;
use crate::study::design::limit::seed_solvers;
use crate::study::design::model::rank::{self, Candidate};
use crate::study::design::model::{DesignScene, PatternResult};
use crate::study::design::stage_env::StageEnv;
use crate::study::rows::label;
use anyhow::Result;
use surrogate::solver::Solver;
use surrogate::units::n_to_mn;

/// What the ranking takes of a pattern after its levels: the pattern, whether this pass
/// searched the tolerance box (not the nominal-only first pass of many patterns), the seeds'
/// solvers (empty: built where needed) and its candidates.
pub struct RankInput<'r, 's> {
    /// The pattern.
    pub ds: &'r DesignScene,
    /// Whether the box was searched (or is a point).
    pub searched: bool,
    /// The substrates' solvers of the robust search (empty: none built).
    pub solvers: &'r [Solver],
    /// The candidates, every level's.
    pub ranking: &'s mut [Candidate],
}

/// Stage 5 of a design, the ranking (module docs of [`super`]); its knobs are [`RankParams`];
/// it reads the shared limit knobs.
pub struct RankStage<'a> {
    env: StageEnv<'a>,
    params: &'a RankParams,
}

impl<'a> RankStage<'a> {
    /// The stage in `env` with its knobs.
    pub fn new(env: StageEnv<'a>, params: &'a RankParams) -> Self {
        RankStage { env, params }
    }

    /// Sorts the candidates by the score; where no design of the pattern holds the ladder's
    /// first load over its box (the best robust limit 0, exact), the best
    /// [`BELOW_LADDER_DESIGNS`] designs' limits located below it ([`below_ladder::locate`])
    /// and the ranking sorted again. Cost: a sort, plus the below-ladder bisections where
    /// needed (one solver per seed built when `solvers` is empty).
    pub fn run(&self, input: RankInput) -> Result<()> {
        let RankInput {
            ds,
            searched,
            solvers,
            ranking,
        } = input;
        let limit = self.env.limit;
        ranking.sort_by(rank::compare);
        if !searched || !below_ladder::needed(ranking) {
            return Ok(());
        }
        let built;
        let solvers = if solvers.is_empty() {
            built = seed_solvers(ds, &limit.tolerance.seeds, None)?;
            &built[..]
        } else {
            solvers
        };
        for c in ranking.iter_mut().take(BELOW_LADDER_DESIGNS) {
            if c.score.exact && c.score.superlubric_to_mn == 0.0 {
                let b = below_ladder::locate(c, solvers, limit)?;
                c.score.below_ladder_mn = Some(label(n_to_mn(b.holds_to)));
            }
        }
        ranking.sort_by(rank::compare);
        Ok(())
    }

    /// With `--rank-by yield` ([`RankParams::by_yield`]), the pattern's top designs ranked by
    /// their yield ([`by_yield::rank_by_yield`]), after its robust search and before its
    /// files; otherwise nothing. Returns how many were ranked by yield.
    pub fn by_yield(&self, pr: &mut PatternResult) -> Result<usize> {
        match &self.params.by_yield {
            Some(y) => by_yield::rank_by_yield(self.env, y, self.params.keep, pr),
            None => Ok(0),
        }
    }
}
