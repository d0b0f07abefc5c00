//! Stage 5 of a design, the robust search: the robust limits over the tolerance box, best
//! first ([`RobustStage`]).
//!
//! Every candidate superlubric at its nominal (θ, α) starts with an upper bound, its nominal
//! limit. The stage repeatedly refines the candidate with the highest bound
//! ([`RobustSearch::step`]: the bound falls, or becomes exact) until the best
//! `max(confirm, 3)` robust limits are exact and no other candidate's bound exceeds the last of
//! them. The others keep an upper bound (`exact: false`): they cannot enter that top. Windows
//! are computed for the exact designs and for the nominal optimum (the report names it).
//! Cost: about one single-load path per sample to disprove a bound, and one path per sample to
//! verify a limit; docs/validation/tolerance-cost.md.

use super::params::RobustParams;
use super::searches::{DesignKey, Searches};
use crate::study::design::model::rank::{self, Candidate, CornerEstimate, Key};
use crate::study::design::model::{DesignScene, Level};
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use crate::study::load::Loads;
use crate::study::rows::label;
use crate::study::tolerance::{RobustSearch, ToleranceBox};
use anyhow::Result;
use rayon::prelude::*;
use std::time::Instant;
use surrogate::solver::Solver;
use surrogate::units::n_to_mn;

/// What the search knows of a candidate so far.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Known {
    /// Upper bound of its robust limit (count of loads).
    bound: usize,
    /// Whether the bound is the limit.
    exact: bool,
    /// θ window (degrees), where computed.
    theta_window_deg: Option<f64>,
    /// Direction window (degrees), where computed.
    direction_window_deg: Option<f64>,
}

/// A candidate's place in the best-first order of the search: its best possible score.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Pending {
    /// Index into the ranking.
    index: usize,
    /// Nothing left to refine (exact with its windows, or bounded at the floor).
    settled: bool,
    /// Its best possible score in the ranking's order: its bound as the limit, its windows (the
    /// whole tolerance where not computed), its μ and contacts.
    key: Key,
}

/// Every estimate search `s` made at a corner of `bx` on the design's own substrate (seed 0).
fn corner_estimates(bx: &ToleranceBox, s: &RobustSearch) -> Vec<CornerEstimate> {
    let corners = bx.corners();
    s.state
        .samples
        .iter()
        .filter(|x| {
            x.seed == 0
                && corners.contains(&(x.theta_offset_deg + 0.0, x.direction_offset_deg + 0.0))
        })
        .flat_map(|x| {
            x.rows.iter().flatten().map(|r| CornerEstimate {
                theta_offset_deg: x.theta_offset_deg + 0.0,
                direction_offset_deg: x.direction_offset_deg + 0.0,
                row: r.clone(),
            })
        })
        .collect()
}

/// The highest load (mN; 0: none) up to which a candidate of `level` could stay superlubric over
/// the tolerance box `bx`: the level's load, or lower where the coating fails at the placement of
/// every pick at some θ offset of the box (the robust limit of a sample never exceeds its
/// placement's intact load: [`crate::study::tolerance::placement_intact`]). An upper bound,
/// for skipping a level below the floor of many patterns (the pipeline's plan). `all` the
/// design's loads (N). Cost: one placement solve per pick, θ offset and load up to the level's.
pub fn level_reach(solver: &Solver, level: &Level, bx: &ToleranceBox, all: &Loads) -> f64 {
    let w = label(n_to_mn(level.load));
    let n = all.count_upto(w);
    let loads = &all[..n];
    let reach = level
        .picks
        .par_iter()
        .map(|o| {
            bx.theta_offsets_deg
                .iter()
                .map(|&dt| {
                    crate::study::tolerance::placement_intact(
                        solver,
                        surrogate::units::deg_to_rad(label(o.theta_deg + dt)),
                        loads,
                    )
                })
                .min()
                .unwrap_or(n)
        })
        .max()
        .unwrap_or(0);
    all.limit_mn(reach)
}

/// Marks `c` as never refined over the box: its nominal limit is its bound (`exact: false`),
/// its windows and corner estimates unknown.
fn unsearched(c: &mut Candidate) {
    c.corners = Vec::new();
    c.score.exact = false;
    c.score.theta_window_deg = None;
    c.score.direction_window_deg = None;
}

/// The loads (count) up to `mn` (mN).
fn count(loads: &Loads, mn: f64) -> usize {
    loads.count_upto(mn)
}

/// The load (mN label; 0: none) of a limit counted in loads.
fn load_mn(loads: &Loads, n: usize) -> f64 {
    loads.limit_mn(n)
}

/// Stage 5 of a design, the robust search (module docs): the robust limits of a
/// pattern's candidates over the tolerance box.
/// Its knobs are [`RobustParams`]; it reads the shared loads and tolerance.
pub struct RobustStage<'a> {
    env: StageEnv<'a>,
    params: &'a RobustParams,
}

impl<'a> RobustStage<'a> {
    /// The stage in `env` with `params`.
    pub fn new(env: StageEnv<'a>, params: &'a RobustParams) -> Self {
        RobustStage { env, params }
    }

    /// The stage on every candidate so far (`ranking`, all levels, sorted here): refines best
    /// first (module docs), writes the robust limits, windows and verdicts into the scores,
    /// and stores the searches. A candidate at or below the floor keeps an upper bound
    /// (`exact: false`, windows unknown), since it cannot exceed the robust limits of the
    /// patterns that set the floor.
    pub fn run(
        &self,
        (ds, ranking, searches): (&DesignScene, &mut [Candidate], &mut Searches),
    ) -> Result<()> {
        let StageEnv { limit, store, obs } = self.env;
        let RobustParams { floor_mn, keep } = *self.params;
        let keep = keep.max(1);
        ranking.sort_by(rank::compare);
        searches.begin_level(ranking);
        let todo: Vec<usize> = (0..ranking.len())
            .filter(|&i| ranking[i].score.nominal_to_mn > floor_mn.max(0.0))
            .collect();
        // at or below the floor: upper bounds, never searched
        for c in ranking.iter_mut() {
            if c.score.nominal_to_mn > 0.0 && c.score.nominal_to_mn <= floor_mn {
                unsearched(c);
            }
        }
        if todo.is_empty() {
            // nothing to search (the pattern's own note names the floor)
            return searches.save(store, ranking);
        }
        obs.event(&Event::Robust {
            pattern: &ds.name,
            theta_tol_deg: limit.tolerance.theta_tol_deg,
            direction_tol_deg: limit.tolerance.direction_tol_deg,
            substrates: searches.solvers.len(),
            designs: keep.min(todo.len()) as u64,
        });
        let t0 = Instant::now();
        let mut paths = self.refine(ranking, searches, &todo, keep)?;
        paths += self.windows(ranking, searches, &todo)?;
        let (seed_limits, n) = self.seed_limits(ranking, searches, &todo)?;
        paths += n;
        self.scores(ranking, searches, &todo, &seed_limits);
        obs.progress().finish();
        searches.save(store, ranking)?;
        let exact = todo.iter().filter(|&&i| ranking[i].score.exact).count();
        obs.event(&Event::RobustDone {
            pattern: &ds.name,
            exact,
            searched: todo.len(),
            wall_s: t0.elapsed().as_secs_f64(),
            paths,
        });
        Ok(())
    }

    /// What the search knows of candidate `c`.
    fn known(&self, s: &Searches, c: &Candidate) -> Known {
        match s.live.iter().find(|(k, _)| *k == DesignKey::of(c)) {
            Some((_, r)) => Known {
                bound: r.state.bound,
                exact: r.settled(),
                theta_window_deg: r.state.theta_window_deg,
                direction_window_deg: r.state.direction_window_deg,
            },
            None => Known {
                bound: count(&self.env.limit.loads, c.score.nominal_to_mn),
                exact: false,
                theta_window_deg: None,
                direction_window_deg: None,
            },
        }
    }

    /// The candidates of `todo`, best possible score first (ordered as the ranking orders:
    /// [`Key::reachable`]); `limits_mn[n]` is the label (mN) of a limit of `n` loads.
    fn order(
        &self,
        ranking: &[Candidate],
        searches: &Searches,
        todo: &[usize],
        limits_mn: &[f64],
    ) -> Vec<Pending> {
        let limit = self.env.limit;
        let floor_mn = self.params.floor_mn;
        // a bound at or below the floor is as far as a search needs to go
        let floor_n = count(&limit.loads, floor_mn);
        let mut order: Vec<Pending> = todo
            .iter()
            .map(|&i| {
                let c = &ranking[i];
                let k = self.known(searches, c);
                let b = k.bound;
                Pending {
                    index: i,
                    settled: (k.exact && (b == 0 || k.theta_window_deg.is_some()))
                        || (floor_mn > 0.0 && b <= floor_n),
                    key: Key::reachable(
                        c,
                        limits_mn[b],
                        k.theta_window_deg.unwrap_or(limit.tolerance.theta_tol_deg),
                        k.direction_window_deg
                            .unwrap_or(limit.tolerance.direction_tol_deg),
                    ),
                }
            })
            .collect();
        order.sort_by(|x, y| x.key.order(&y.key));
        order
    }

    /// Refines the candidate with the best possible score until the best `keep` are settled
    /// (every other candidate's best possible score is below theirs). Returns the paths
    /// solved.
    fn refine(
        &self,
        ranking: &[Candidate],
        searches: &mut Searches,
        todo: &[usize],
        keep: usize,
    ) -> Result<usize> {
        let progress = self.env.obs.progress();
        // the label (mN) of each bound, counted in loads: once, not per candidate and step
        let loads = &self.env.limit.loads;
        let limits_mn: Vec<f64> = (0..=loads.len()).map(|n| load_mn(loads, n)).collect();
        let mut paths = 0usize;
        let mut done = 0u64;
        loop {
            let order = self.order(ranking, searches, todo, &limits_mn);
            let exact_top = order.iter().take_while(|x| x.settled).count().min(keep) as u64;
            if exact_top > done {
                progress.advance(exact_top - done);
                done = exact_top;
            }
            let Some(i) = order
                .iter()
                .take(keep)
                .find(|x| !x.settled)
                .map(|x| x.index)
            else {
                return Ok(paths);
            };
            let ((), n) = searches.counted(&ranking[i], |s| {
                if s.settled() {
                    s.windows()
                } else {
                    s.step()
                }
            })?;
            paths += n;
        }
    }

    /// The windows of the exact designs and of the nominal optimum (highest nominal limit).
    /// Returns the paths solved.
    fn windows(
        &self,
        ranking: &[Candidate],
        searches: &mut Searches,
        todo: &[usize],
    ) -> Result<usize> {
        let floor_mn = self.params.floor_mn;
        let floor_n = count(&self.env.limit.loads, floor_mn);
        let top = todo
            .iter()
            .map(|&i| ranking[i].score.nominal_to_mn)
            .fold(0.0f64, f64::max);
        let mut paths = 0usize;
        for &i in todo {
            let c = &ranking[i];
            let Known {
                bound: b,
                exact: settled,
                ..
            } = self.known(searches, c);
            if (settled && b > 0)
                || (c.score.nominal_to_mn == top && (floor_mn == 0.0 || b > floor_n))
            {
                paths += searches.counted(c, |s| s.windows())?.1;
            }
        }
        Ok(paths)
    }

    /// The spread over substrate seeds of the exact designs: each one's per-seed limits (mN),
    /// and the paths solved. Empty with one substrate.
    #[allow(clippy::type_complexity)]
    fn seed_limits(
        &self,
        ranking: &[Candidate],
        searches: &mut Searches,
        todo: &[usize],
    ) -> Result<(Vec<(DesignKey, Vec<f64>)>, usize)> {
        let loads = &self.env.limit.loads;
        let mut out: Vec<(DesignKey, Vec<f64>)> = Vec::new();
        let mut paths = 0usize;
        if searches.solvers.len() <= 1 {
            return Ok((out, paths));
        }
        for &i in todo {
            let c = &ranking[i];
            let Known {
                bound: b,
                exact: settled,
                ..
            } = self.known(searches, c);
            if settled && b > 0 {
                let (v, n) = searches.counted(c, |s| s.seed_limits())?;
                paths += n;
                out.push((
                    DesignKey::of(c),
                    v.into_iter().map(|n| load_mn(loads, n)).collect(),
                ));
            }
        }
        Ok((out, paths))
    }

    /// Writes the searches' results into the scores of `todo` (an unsearched candidate keeps
    /// its nominal limit as an upper bound).
    fn scores(
        &self,
        ranking: &mut [Candidate],
        searches: &Searches,
        todo: &[usize],
        seed_limits: &[(DesignKey, Vec<f64>)],
    ) {
        let loads = &self.env.limit.loads;
        for &i in todo {
            let key = DesignKey::of(&ranking[i]);
            let c = &mut ranking[i];
            match searches.live.iter().find(|(k, _)| *k == key) {
                Some((_, s)) => {
                    let r = s.result();
                    c.score.superlubric_to_mn = load_mn(loads, r.superlubric_to);
                    c.score.theta_window_deg = r.theta_window_deg;
                    c.score.direction_window_deg = r.direction_window_deg;
                    c.score.verdict = r.verdict;
                    c.score.exact = r.exact;
                    c.score.seed_limits_mn = seed_limits
                        .iter()
                        .find(|(k, _)| *k == key)
                        .map(|(_, v)| v.clone());
                    c.corners = corner_estimates(&searches.bx, s);
                }
                None => unsearched(c),
            }
        }
    }
}
