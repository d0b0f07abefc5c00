//! The design pipeline: [`Pipeline::run`] takes the patterns through the stages in order,
//! each a type in its own file with a `run` that takes the previous stage's output —
//! [`ScreenStage`] → [`ShortlistStage`] → per shortlist level as the [`LevelWalk`] takes
//! them, [`EvaluateStage`] (the α scan, the estimate) and [`RobustStage`] → the DEM
//! confirmation ([`super::confirm`]) → the report data ([`ReportDataStage`]) → when asked for,
//! the yield of each answer ([`YieldStage`]) — telling one [`Observer`] what it finds as typed
//! events (no wording here).

use super::below_ladder;
use super::best;
use super::confirm::{confirm_estimates, confirm_jobs, confirm_stage, run_batch, SlideOutcome};
use super::ctx::Ctx;
use super::evaluate::{EvaluateStage, LevelInput};
use super::inputs::inputs;
use super::limit::{seed_solvers, solver_of, tolerance_box};
use super::observer::{Event, Observer};
use super::outcome::DesignOutcome;
use super::params::{DesignParams, DesignScene};
use super::pattern_result::{Evaluated, PatternResult};
use super::rank::{self, Candidate};
use super::report_data::ReportDataStage;
use super::robust::{self, RobustParams, RobustStage};
use super::robust_searches::Searches;
use super::screen::ScreenStage;
use super::shortlist::ShortlistStage;
use super::store::Store;
use super::walk::{LevelWalk, Next, Walked};
use super::yield_params::RankBy;
use super::yield_rank::YieldRank;
use super::yield_stage::YieldStage;
use crate::study::rows::label;
use anyhow::Result;
use surrogate::solver::Solver;
use surrogate::units::n_to_mn;

/// What [`super::design`] calls with each pattern's complete result (its friction estimates
/// for the DEM included), in pattern order, before trimming it: the command writes the
/// pattern's own files there. Not called in a DEM shard (`--shard`: no outputs).
pub type PatternHook<'a> = &'a dyn Fn(&PatternResult) -> Result<()>;

/// How [`Pipeline::pattern`] searches the tolerance box.
#[derive(Debug, Clone, Copy)]
pub enum Search {
    /// No robust search: the nominal limits only (the first pass of [`Pipeline::order`]).
    Nominal,
    /// The robust search ([`RobustStage`]) above `floor_mn` (mN; 0: none), until the best
    /// `keep` designs of the pattern are exact.
    Robust {
        /// The floor (mN; 0: none).
        floor_mn: f64,
        /// Designs that must be exact.
        keep: usize,
    },
}

/// The order [`Pipeline::run`] takes the patterns in, and whether a robust floor applies
/// across them.
#[derive(Debug, Clone, PartialEq)]
pub struct Order {
    /// Indices into the patterns, in the order taken.
    pub patterns: Vec<usize>,
    /// Whether the patterns are taken best nominal design first, each robust search above the
    /// floor of the best [`best::BEST_PATTERNS`] found so far.
    pub cross: bool,
}

/// The design of a set of patterns under one set of parameters, its stages stored under one
/// output folder and reported to one observer.
pub struct Pipeline<'a> {
    ctx: Ctx<'a>,
}

impl<'a> Pipeline<'a> {
    /// The pipeline of `p`, storing into `store`, telling `obs`.
    pub fn new(p: &'a DesignParams, store: &'a Store, obs: &'a dyn Observer) -> Self {
        Pipeline {
            ctx: Ctx { p, store, obs },
        }
    }

    /// Runs the design (module docs of [`super`]): every pattern's stages in [`Order`], each
    /// pattern handed to `on_pattern` and trimmed when complete, then the DEM confirmation,
    /// the report data and, when asked for, the yield of each answer.
    pub fn run(&self, scenes: &[DesignScene], on_pattern: PatternHook) -> Result<DesignOutcome> {
        let Ctx { p, store, obs } = self.ctx;
        // every pattern's paths fit on its substrate, checked before any work
        for ds in scenes {
            crate::study::friction::check_every_direction(&ds.scene, &p.friction)
                .map_err(|e| anyhow::anyhow!("pattern `{}`: {e:#}", ds.name))?;
        }
        if store.claim(&inputs(scenes, p, false))? {
            obs.event(&Event::Reusing { dir: store.dir() });
        }
        let order = self.order(scenes)?;
        let patterns = self.patterns(scenes, &order, on_pattern)?;
        if !p.confirm.no_dem && !p.confirm.dem_shard.is_all() {
            return self.dem_shard(patterns);
        }
        let dem = if p.confirm.no_dem {
            Vec::new()
        } else {
            confirm_stage(&patterns, p, store, obs)?
        };
        let mut o = ReportDataStage::new(self.ctx).run(patterns, dem, order.cross)?;
        if let Some(y) = &p.fab_yield {
            o.yields = YieldStage::new(self.ctx, y).run(&o)?;
        }
        Ok(o)
    }

    /// Every pattern's stages ([`Pipeline::pattern`]) in `order`, each robust search above the
    /// floor of the best patterns so far (across many patterns), the pattern's estimates for
    /// the DEM added; each pattern handed to `on_pattern` when complete and then trimmed
    /// ([`PatternResult::trim`]: memory flat in the number of patterns). In the order given.
    fn patterns(
        &self,
        scenes: &[DesignScene],
        order: &Order,
        on_pattern: PatternHook,
    ) -> Result<Vec<PatternResult>> {
        let Ctx { p, store, .. } = self.ctx;
        let mut done: Vec<Option<PatternResult>> = vec![None; scenes.len()];
        let mut best_robust: Vec<f64> = Vec::new();
        for &i in &order.patterns {
            // the floor: the BEST_PATTERNS-th best robust limit so far (across many patterns)
            let floor_mn = if order.cross && best_robust.len() >= best::BEST_PATTERNS {
                best_robust[best::BEST_PATTERNS - 1]
            } else {
                0.0
            };
            let search = Search::Robust {
                floor_mn,
                // across many patterns only each one's best counts (without the DEM, which
                // confirms each pattern's top designs)
                keep: if order.cross && p.confirm.no_dem {
                    1
                } else {
                    p.confirm.designs.max(3)
                },
            };
            let mut pr = self.pattern(&scenes[i], search)?;
            if let Some(c) = pr.ranking.first().filter(|c| c.score.exact) {
                best_robust.push(c.score.superlubric_to_mn);
                best_robust.sort_by(|a, b| b.total_cmp(a));
            }
            if let Some(y) = p.fab_yield.as_ref().filter(|y| y.rank_by == RankBy::Yield) {
                YieldRank::new(self.ctx, y).run(&mut pr)?;
            }
            if !p.confirm.no_dem {
                confirm_estimates(std::slice::from_mut(&mut pr), p, store)?;
            }
            pr.resonance_flagged = rank::resonance_flagged(&pr.ranking);
            if p.confirm.dem_shard.is_all() {
                on_pattern(&pr)?;
            }
            pr.trim(p);
            done[i] = Some(pr);
        }
        Ok(done.into_iter().flatten().collect())
    }

    /// The order in which [`Pipeline::run`] takes the patterns ([`Order`]).
    ///
    /// With more than [`best::BEST_PATTERNS`] patterns and a tolerance, every pattern is first
    /// evaluated at its nominal orientation only (no robust search; stored, so the second pass
    /// reuses them): the patterns are then taken best nominal design first
    /// ([`rank::compare`]), and a pattern's candidates whose nominal limit is at most the
    /// [`best::BEST_PATTERNS`]-th best robust limit found so far are not searched over the
    /// tolerance box (the robust limit never exceeds the nominal one, so they cannot enter the
    /// top). Otherwise the order given, no floor. Cost: the nominal pass, about the design at
    /// tolerance 0 (docs/validation/tolerance-cost.md).
    pub fn order(&self, scenes: &[DesignScene]) -> Result<Order> {
        let given: Vec<usize> = (0..scenes.len()).collect();
        if tolerance_box(self.ctx.p).is_point() || scenes.len() <= best::BEST_PATTERNS {
            return Ok(Order {
                patterns: given,
                cross: false,
            });
        }
        self.ctx.obs.event(&Event::NominalFirst {
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

    /// The stages of one pattern, in order: the screen ([`ScreenStage`], with the symmetry
    /// cut), the shortlist ([`ShortlistStage`]), then per shortlist level as the [`LevelWalk`]
    /// takes them the α scan and the estimate ([`EvaluateStage`]) and, with a tolerance, the
    /// robust search ([`RobustStage`]); then the ranking.
    pub fn pattern(&self, ds: &DesignScene, search: Search) -> Result<PatternResult> {
        let p = self.ctx.p;
        let screened = ScreenStage::new(self.ctx).run(ds)?;
        let short = ShortlistStage::new(self.ctx).run(ds, &screened);
        let bx = tolerance_box(p);
        let robust = match search {
            Search::Nominal => None,
            Search::Robust { floor_mn, keep } => {
                (!bx.is_point()).then_some(RobustParams { floor_mn, keep })
            }
        };
        let floor_mn = match search {
            Search::Nominal => 0.0,
            Search::Robust { floor_mn, .. } => floor_mn,
        };
        let limit = p.limit();
        let solvers: Vec<Solver> = match robust {
            Some(_) => seed_solvers(ds, p, None)?,
            None => Vec::new(),
        };
        let mut searches = Searches::new(ds, p, &solvers, &limit, self.ctx.store)?;
        let mut solver: Option<Solver> = None;
        let mut walk = LevelWalk::new(p.confirm.designs.max(3), floor_mn, robust.is_some());
        let mut evaluated: Vec<Evaluated> = Vec::new();
        let mut ranking: Vec<Candidate> = Vec::new();
        for (li, level) in short.levels.iter().enumerate() {
            let reach = || {
                let s = solver_of(&mut solver, ds)?;
                Ok(robust::level_reach(s, level, &bx, p))
            };
            match walk.next(li, level.load, &ranking, reach)? {
                Next::Stop => break,
                Next::Skip => continue,
                Next::Evaluate => {}
            }
            let from = ranking.len();
            let l = LevelInput {
                ds,
                level,
                sym: &screened.sym,
                solver: solver_of(&mut solver, ds)?,
            };
            for e in EvaluateStage::new(self.ctx).run(&l)? {
                ranking.extend(rank::candidates(
                    &ds.name,
                    &e.eval,
                    label(n_to_mn(level.load)),
                    e.reason,
                    ds.scene.coating.p_crit,
                    p.mu_superlubric,
                ));
                evaluated.push(e);
            }
            // the robust limits of this level's candidates (the walk's stop rule then compares
            // each level's bound with the best robust limit: a robust design may sit lower)
            if let Some(rp) =
                robust.filter(|_| ranking[from..].iter().any(|c| c.score.nominal_to_mn > 0.0))
            {
                RobustStage::new(self.ctx, rp).run(ds, &mut ranking, &mut searches)?;
            }
            walk.evaluated(&ranking);
        }
        ranking.sort_by(rank::compare);
        self.below_ladder(
            ds,
            robust.is_some() || bx.is_point(),
            &solvers,
            &mut ranking,
        )?;
        let walked = walk.end();
        self.tell_ranking(
            ds,
            &ranking,
            &evaluated,
            &walked,
            robust.is_some(),
            floor_mn,
        );
        Ok(PatternResult {
            scene: ds.clone(),
            sym: screened.sym,
            thetas_deg: screened.thetas_deg,
            screen: screened.rows,
            screen_wall_s: screened.wall_s,
            orientations: short.orientations,
            levels: short.levels,
            levels_evaluated: walked.taken,
            levels_skipped: walked.skipped,
            stop: walked.stop,
            evaluated,
            ranking,
            resonance_flagged: 0,
            robust_floor_mn: floor_mn,
            trimmed: false,
        })
    }

    /// Where no design of the pattern holds the ladder's first load over its box (the best
    /// robust limit 0, exact), the best [`below_ladder::BELOW_LADDER_DESIGNS`] designs' limits
    /// located below it ([`below_ladder::locate`]) and the ranking re-sorted; `searched`:
    /// whether this pass searches the box (not the nominal-only first pass). `solvers`: the
    /// seeds' (empty: built here).
    fn below_ladder(
        &self,
        ds: &DesignScene,
        searched: bool,
        solvers: &[Solver],
        ranking: &mut [Candidate],
    ) -> Result<()> {
        let p = self.ctx.p;
        if !searched || !below_ladder::needed(ranking) {
            return Ok(());
        }
        let built;
        let solvers = if solvers.is_empty() {
            built = seed_solvers(ds, p, None)?;
            &built[..]
        } else {
            solvers
        };
        for c in ranking.iter_mut().take(below_ladder::BELOW_LADDER_DESIGNS) {
            if c.score.exact && c.score.superlubric_to_mn == 0.0 {
                let b = below_ladder::locate(c, solvers, p)?;
                c.score.below_ladder_mn = Some(label(n_to_mn(b.holds_to)));
            }
        }
        ranking.sort_by(rank::compare);
        Ok(())
    }

    /// Tells the observer of a pattern's ranking: the designs left at the floor (with a
    /// robust search) and the best design.
    fn tell_ranking(
        &self,
        ds: &DesignScene,
        ranking: &[Candidate],
        evaluated: &[Evaluated],
        walked: &Walked,
        robust: bool,
        floor_mn: f64,
    ) {
        let obs = self.ctx.obs;
        let floored = ranking
            .iter()
            .filter(|c| {
                c.score.nominal_to_mn > 0.0
                    && !c.score.exact
                    && c.score.superlubric_to_mn <= floor_mn
            })
            .count();
        if robust && floored > 0 {
            obs.event(&Event::Floored {
                pattern: &ds.name,
                designs: floored,
                floor_mn,
            });
        }
        if let Some(b) = ranking.first() {
            obs.event(&Event::Best {
                pattern: &ds.name,
                design: b,
                evaluated: evaluated.len(),
                stop: &walked.stop,
                skipped: walked.skipped.len(),
                floor_mn,
            });
        }
    }

    /// A shard of the DEM stage: its share of the runs, no report (an outcome without DEM
    /// entries or answers).
    fn dem_shard(&self, patterns: Vec<PatternResult>) -> Result<DesignOutcome> {
        let p = self.ctx.p;
        let (jobs, _) = confirm_jobs(&patterns, p);
        let part = p.confirm.dem_shard.range(jobs.len());
        let dir = self.ctx.store.path("dem");
        self.ctx.obs.event(&Event::DemShard {
            index: p.confirm.dem_shard.index,
            count: p.confirm.dem_shard.count,
            start: part.start,
            end: part.end,
            runs: jobs.len(),
            dir: &dir,
        });
        let dem: Vec<SlideOutcome> = if part.is_empty() {
            Vec::new()
        } else {
            run_batch(&jobs[part], p.confirm.jobs, &dir, self.ctx.obs.progress())?
        };
        let failed = dem.iter().filter(|o| o.error.is_some()).count();
        if failed > 0 {
            self.ctx.obs.event(&Event::DemShardFailed { failed });
        }
        Ok(DesignOutcome {
            patterns,
            dem: Vec::new(),
            dem_ran: false,
            answers: Vec::new(),
            maps: Vec::new(),
            p_crit: None,
            yields: Vec::new(),
        })
    }
}
