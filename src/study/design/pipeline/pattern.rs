//! The stages of one pattern up to its ranking ([`Pipeline::pattern`]): 1. the screen, 2. the
//! shortlist, then per level as the [`LevelWalk`] takes them 3–4. the evaluation and 5. the
//! robust search, then 5. the ranking.

use super::search::Search;
use super::Pipeline;
use crate::study::design::evaluate::{EvaluateStage, LevelInput};
use crate::study::design::limit::{seed_solvers, solver_of};
use crate::study::design::model::{rank, Candidate, DesignScene, Evaluated, PatternResult};
use crate::study::design::observer::Event;
use crate::study::design::ranking::{RankInput, RankStage};
use crate::study::design::robust::searches::Searches;
use crate::study::design::robust::{level_reach, RobustParams, RobustStage};
use crate::study::design::screen::{ScreenStage, Screened};
use crate::study::design::shortlist::walk::{LevelWalk, Next, Walked};
use crate::study::design::shortlist::{ShortlistStage, Shortlisted};
use crate::study::rows::label;
use anyhow::Result;
use surrogate::solver::Solver;
use surrogate::units::n_to_mn;

/// What the levels of one pattern gave: the evaluated orientations, the candidates and where
/// the walk ended.
struct Levels {
    evaluated: Vec<Evaluated>,
    ranking: Vec<Candidate>,
    walked: Walked,
}

impl Pipeline<'_> {
    /// The stages of one pattern, in order: 1. the screen ([`ScreenStage`], with the symmetry
    /// cut), 2. the shortlist ([`ShortlistStage`]), then per shortlist level as the
    /// [`LevelWalk`] takes them 3–4. the α scan and the estimate ([`EvaluateStage`]) and,
    /// with a tolerance, 5. the robust search ([`RobustStage`]); then 5. the ranking
    /// ([`RankStage::run`]).
    pub fn pattern(&self, ds: &DesignScene, search: Search) -> Result<PatternResult> {
        let p = self.p;
        let screened = ScreenStage::new(self.env(), &p.screen).run(ds)?;
        let short = ShortlistStage::new(self.env(), &p.shortlist).run((ds, &screened))?;
        let point = self.plan.limit.tolerance_box().is_point();
        let (robust, floor_mn) = match search {
            Search::Nominal => (None, 0.0),
            Search::Robust(rp) => ((!point).then_some(rp), rp.floor_mn),
        };
        let solvers: Vec<Solver> = match robust {
            Some(_) => seed_solvers(ds, &self.plan.limit.tolerance.seeds, None)?,
            None => Vec::new(),
        };
        let mut levels = self.levels(ds, (&screened, &short), robust, floor_mn, &solvers)?;
        RankStage::new(self.env(), &self.plan.rank).run(RankInput {
            ds,
            searched: robust.is_some() || point,
            solvers: &solvers,
            ranking: &mut levels.ranking,
        })?;
        let Levels {
            evaluated,
            ranking,
            walked,
        } = levels;
        self.tell_ranking(
            ds,
            &ranking,
            (&evaluated, &walked),
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

    /// The shortlist's levels of `ds` as the [`LevelWalk`] takes them: each level's α scan
    /// and estimate ([`EvaluateStage`]) and, with `robust`, the robust limits of the
    /// candidates so far ([`RobustStage`]); `solvers`: the seeds' (empty without `robust`).
    fn levels(
        &self,
        ds: &DesignScene,
        (screened, short): (&Screened, &Shortlisted),
        robust: Option<RobustParams>,
        floor_mn: f64,
        solvers: &[Solver],
    ) -> Result<Levels> {
        let knobs = &self.plan.limit;
        let bx = knobs.tolerance_box();
        let limit = knobs.limit();
        let mut searches = Searches::new(ds, knobs, (solvers, &limit), self.store)?;
        let evaluate = EvaluateStage::new(self.env(), &self.p.alpha_scan);
        let mut solver: Option<Solver> = None;
        let mut walk = LevelWalk::new(self.plan.keep, floor_mn, robust.is_some());
        let mut evaluated: Vec<Evaluated> = Vec::new();
        let mut ranking: Vec<Candidate> = Vec::new();
        for (li, level) in short.levels.iter().enumerate() {
            let reach = || {
                let s = solver_of(&mut solver, ds)?;
                Ok(level_reach(s, level, &bx, &knobs.loads))
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
            for e in evaluate.run(&l)? {
                ranking.extend(rank::candidates(
                    &ds.name,
                    &e.eval,
                    label(n_to_mn(level.load)),
                    e.reason,
                    ds.scene.coating.p_crit,
                    knobs.mu_superlubric,
                ));
                evaluated.push(e);
            }
            // the robust limits of this level's candidates (the walk's stop rule then compares
            // each level's bound with the best robust limit: a robust design may sit lower)
            if let Some(rp) = robust
                .as_ref()
                .filter(|_| ranking[from..].iter().any(|c| c.score.nominal_to_mn > 0.0))
            {
                RobustStage::new(self.env(), rp).run((ds, &mut ranking, &mut searches))?;
            }
            walk.evaluated(&ranking);
        }
        Ok(Levels {
            evaluated,
            ranking,
            walked: walk.end(),
        })
    }

    /// Tells the observer of a pattern's ranking: the designs left at the floor (with a
    /// robust search) and the best design.
    fn tell_ranking(
        &self,
        ds: &DesignScene,
        ranking: &[Candidate],
        (evaluated, walked): (&[Evaluated], &Walked),
        robust: bool,
        floor_mn: f64,
    ) {
        let floored = ranking
            .iter()
            .filter(|c| {
                c.score.nominal_to_mn > 0.0
                    && !c.score.exact
                    && c.score.superlubric_to_mn <= floor_mn
            })
            .count();
        if robust && floored > 0 {
            self.obs.event(&Event::Floored {
                pattern: &ds.name,
                designs: floored,
                floor_mn,
            });
        }
        if let Some(b) = ranking.first() {
            self.obs.event(&Event::Best {
                pattern: &ds.name,
                design: b,
                evaluated: evaluated.len(),
                stop: &walked.stop,
                skipped: walked.skipped.len(),
                floor_mn,
            });
        }
    }
}
