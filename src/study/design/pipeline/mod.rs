//! The design pipeline: [`Pipeline::run`] is the flat list of the stages, in the order of
//! `docs/commands/design.md`. Each stage lives in its own folder with its own params and a
//! value holding only what it reads (its params, the shared [`LimitKnobs`], the store and the
//! observer: [`StageEnv`]), all of one shape, `XStage::new(env, &params).run(input)`:
//!
//! per pattern, in the [`Order`] of the plan: 1. [`ScreenStage`] → 2. [`ShortlistStage`] →
//! per shortlist level as the [`LevelWalk`] takes them 3–4. [`EvaluateStage`] (the α scan,
//! the estimate) and 5. [`RobustStage`] → 5. [`RankStage`] (the score's order, the limits
//! below the ladder, then with `--rank-by yield` the ranking by yield) → 6. the estimates the
//! DEM is compared with ([`ConfirmStage::estimates`]) → the pattern's files (the hook) and
//! its trim; then 6. the DEM runs ([`ConfirmStage::run`]) → 7. [`ReportDataStage`] → 8.
//! [`YieldStage`]. The cross-stage rules (how many designs are kept, the floor across many
//! patterns) are the [`Plan`], computed once. The stages tell one [`Observer`] what they find
//! as typed events (no wording here).

mod order;
mod pattern;
mod plan;
mod search;

pub use plan::{Floor, Plan, MIN_KEPT};
pub use search::{Order, Search};

use super::confirm::{BatchRunner, ConfirmStage, DemRunner};
use super::inputs::inputs;
#[cfg(doc)]
use super::limit::LimitKnobs;
use super::model::{rank, DesignOutcome, DesignScene, PatternResult};
use super::observer::{Event, Observer};
use super::params::DesignParams;
use super::ranking::RankStage;
use super::report_data::{ReportDataInput, ReportDataStage};
use super::stage_env::StageEnv;
use super::store::Store;
use super::yield_stage::YieldStage;
#[cfg(doc)]
use super::{
    evaluate::EvaluateStage, robust::RobustStage, screen::ScreenStage, shortlist::walk::LevelWalk,
    shortlist::ShortlistStage,
};
use anyhow::Result;

/// What [`super::design`] calls with each pattern's complete result (its friction estimates
/// for the DEM included), in pattern order, before trimming it: the command writes the
/// pattern's own files there. Not called in a DEM shard (`--shard`: no outputs).
pub type PatternHook<'a> = &'a dyn Fn(&PatternResult) -> Result<()>;

/// The design of a set of patterns under one set of parameters, its stages stored under one
/// output folder and reported to one observer.
pub struct Pipeline<'a> {
    p: &'a DesignParams,
    plan: Plan,
    store: &'a Store,
    obs: &'a dyn Observer,
    runner: &'a dyn DemRunner,
}

impl<'a> Pipeline<'a> {
    /// The pipeline of `p`, storing into `store`, telling `obs`, its DEM runs through the
    /// study layer's batch runner. Cost: the plan ([`Plan::new`]).
    pub fn new(p: &'a DesignParams, store: &'a Store, obs: &'a dyn Observer) -> Self {
        Pipeline {
            p,
            plan: Plan::new(p),
            store,
            obs,
            runner: &BatchRunner,
        }
    }

    /// The same pipeline with its DEM runs through `runner` (a test's oracle).
    pub fn with_runner(self, runner: &'a dyn DemRunner) -> Self {
        Pipeline { runner, ..self }
    }

    /// The plan the stages run under.
    pub fn plan(&self) -> &Plan {
        &self.plan
    }

    /// The environment every stage runs in.
    fn env(&self) -> StageEnv<'_> {
        StageEnv {
            limit: &self.plan.limit,
            store: self.store,
            obs: self.obs,
        }
    }

    /// The DEM confirmation stage.
    fn confirm(&self) -> ConfirmStage<'_> {
        ConfirmStage::new(self.env(), &self.p.confirm, self.runner)
    }

    /// Runs the design (module docs): the stages in the order of the list below.
    pub fn run(&self, scenes: &[DesignScene], on_pattern: PatternHook) -> Result<DesignOutcome> {
        self.claim(scenes)?;
        let order = self.order(scenes)?;
        // 1–5 and the DEM's estimates, per pattern; each one's files, then its trim
        let patterns = self.patterns(scenes, &order, on_pattern)?;
        let cp = &self.p.confirm;
        if !cp.no_dem && !cp.dem_shard.is_all() {
            self.confirm().shard(&patterns)?;
            return Ok(DesignOutcome::without_report(patterns));
        }
        // 6. the DEM
        let dem = self.confirm().run(&patterns)?;
        // 7. the report data: the answers, the tolerance maps, the P_crit sweep
        let mut o = ReportDataStage::new(self.env(), &self.plan.report).run(ReportDataInput {
            patterns,
            dem,
            cross: order.cross,
        })?;
        // 8. the yield of each answer
        if let Some(y) = &self.plan.fab_yield {
            o.yields = YieldStage::new(self.env(), y).run(&o)?;
        }
        Ok(o)
    }

    /// Checks that every pattern's paths fit on its substrate (before any work), then claims
    /// the store for the design's inputs (a re-run with the same reuses it).
    fn claim(&self, scenes: &[DesignScene]) -> Result<()> {
        for ds in scenes {
            crate::study::friction::check_every_direction(&ds.scene, &self.p.friction)
                .map_err(|e| anyhow::anyhow!("pattern `{}`: {e:#}", ds.name))?;
        }
        if self.store.claim(&inputs(scenes, self.p, false))? {
            self.obs.event(&Event::Reusing {
                dir: self.store.dir(),
            });
        }
        Ok(())
    }

    /// Every pattern's stages in `order` ([`Pipeline::pattern`]: 1–5), each robust search
    /// above the [`Floor`] of the best patterns so far (across many patterns); then the
    /// ranking by yield (5, `--rank-by yield`) and the estimates the DEM is compared with (6);
    /// each pattern handed to `on_pattern` when complete and then trimmed
    /// ([`PatternResult::trim`]: memory flat in the number of patterns). In the order given.
    fn patterns(
        &self,
        scenes: &[DesignScene],
        order: &Order,
        on_pattern: PatternHook,
    ) -> Result<Vec<PatternResult>> {
        let rank_stage = RankStage::new(self.env(), &self.plan.rank);
        let confirm = self.confirm();
        let mut done: Vec<Option<PatternResult>> = vec![None; scenes.len()];
        let mut floor = Floor::new(order.cross);
        for &i in &order.patterns {
            // 1–5: screen, shortlist, per level evaluate and robust search, ranking
            let search = Search::Robust(self.plan.robust(floor.mn(), order.cross));
            let mut pr = self.pattern(&scenes[i], search)?;
            floor.record(&pr);
            // 5. with `--rank-by yield`, the top designs ranked by their yield
            rank_stage.by_yield(&mut pr)?;
            // 6. the estimates the DEM is compared with, in the pattern's files
            confirm.estimates(&mut pr)?;
            pr.resonance_flagged = rank::resonance_flagged(&pr.ranking);
            if self.p.confirm.dem_shard.is_all() {
                on_pattern(&pr)?;
            }
            pr.trim(self.plan.confirmed);
            done[i] = Some(pr);
        }
        Ok(done.into_iter().flatten().collect())
    }
}

#[cfg(test)]
mod tests;
