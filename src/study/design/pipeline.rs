//! The design pipeline, stage by stage in one place: [`Pipeline::run`] takes the patterns through
//! [`Stage::Screen`] → [`Stage::Shortlist`] → [`Stage::AlphaScan`] → [`Stage::Estimate`] →
//! [`Stage::RobustSearch`] (per pattern, the middle three once per shortlist level) →
//! [`Stage::DemConfirmation`] → [`Stage::ReportData`], telling one [`Observer`] each stage it
//! enters and what it finds (no wording here).

use super::best;
use super::confirm::{confirm_estimates, confirm_jobs, confirm_stage, run_batch, SlideOutcome};
use super::observer::{Event, Observer, Stage};
use super::rank::{self, Candidate};
use super::robust;
use super::scan;
use super::shortlist::{self, Level};
use super::stages::{eval_level, screen_stage, seed_solvers};
use super::store::Store;
use super::trim;
use super::{
    answer, answer_map, cut, inputs, line_note, solver_of, theta_note, tolerance_box,
    DesignOutcome, DesignParams, DesignScene, Evaluated, PatternHook, PatternResult, Stop,
};
use crate::study::rows::label;
use crate::study::tolerance::LimitParams;
use anyhow::Result;
use surrogate::solver::Solver;
use surrogate::units::n_to_mn;

/// How [`Pipeline::pattern`] searches the tolerance box.
#[derive(Debug, Clone, Copy)]
pub enum Search {
    /// No robust search: the nominal limits only (the first pass of [`Pipeline::order`]).
    Nominal,
    /// The robust search ([`robust::robust_stage`]) above `floor_mn` (mN; 0: none), until the
    /// best `keep` designs of the pattern are exact.
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
    p: &'a DesignParams,
    store: &'a Store,
    obs: &'a dyn Observer,
}

impl<'a> Pipeline<'a> {
    /// The pipeline of `p`, storing into `store`, telling `obs`.
    pub fn new(p: &'a DesignParams, store: &'a Store, obs: &'a dyn Observer) -> Self {
        Pipeline { p, store, obs }
    }

    /// Runs the design (module docs of [`super`]): every pattern's stages in [`Order`], each
    /// pattern handed to `on_pattern` when complete and then trimmed
    /// ([`PatternResult::trim`]: memory flat in the number of patterns), then the DEM
    /// confirmation and the report data.
    pub fn run(&self, scenes: &[DesignScene], on_pattern: PatternHook) -> Result<DesignOutcome> {
        let p = self.p;
        // every pattern's paths fit on its substrate, checked before any work
        for ds in scenes {
            crate::study::friction::check_every_direction(&ds.scene, &p.friction)
                .map_err(|e| anyhow::anyhow!("pattern `{}`: {e:#}", ds.name))?;
        }
        if self.store.claim(&inputs(scenes, p, false))? {
            self.obs.event(&Event::Reusing {
                dir: self.store.dir(),
            });
        }
        let order = self.order(scenes)?;
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
                keep: if order.cross && p.no_dem {
                    1
                } else {
                    p.confirm.max(3)
                },
            };
            let mut pr = self.pattern(&scenes[i], search)?;
            if let Some(c) = pr.ranking.first().filter(|c| c.score.exact) {
                best_robust.push(c.score.superlubric_to_mn);
                best_robust.sort_by(|a, b| b.total_cmp(a));
            }
            if !p.no_dem {
                confirm_estimates(std::slice::from_mut(&mut pr), p, self.store)?;
            }
            pr.resonance_flagged = trim::resonance_flagged(&pr.ranking);
            if p.dem_shard.is_all() {
                on_pattern(&pr)?;
            }
            pr.trim(p);
            done[i] = Some(pr);
        }
        let patterns: Vec<PatternResult> = done.into_iter().flatten().collect();
        if !p.no_dem && !p.dem_shard.is_all() {
            return self.dem_shard(patterns);
        }
        let dem = if p.no_dem {
            Vec::new()
        } else {
            self.obs.stage(Stage::DemConfirmation, "");
            confirm_stage(&patterns, p, self.store, self.obs)?
        };
        self.obs.stage(Stage::ReportData, "");
        self.report_data(patterns, dem, order.cross)
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
        if tolerance_box(self.p).is_point() || scenes.len() <= best::BEST_PATTERNS {
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

    /// The stages of one pattern, in order: symmetry cut and [`Stage::Screen`],
    /// [`Stage::Shortlist`], then per shortlist level (from the top, until no lower level can
    /// beat the best found) [`Stage::AlphaScan`], [`Stage::Estimate`] and, with a tolerance,
    /// [`Stage::RobustSearch`]; then the ranking.
    pub fn pattern(&self, ds: &DesignScene, search: Search) -> Result<PatternResult> {
        let (p, obs) = (self.p, self.obs);
        let name = ds.name.as_str();
        // 1. symmetry cut and screen
        obs.stage(Stage::Screen, name);
        let (thetas_deg, sym) = cut(ds, p)?;
        let note = theta_note(&sym, &thetas_deg, p);
        obs.event(&Event::Symmetry {
            pattern: name,
            sym: &sym,
            screened: thetas_deg.len(),
            given: p.thetas_deg.len(),
            cut: p.symmetry_cut,
            note: note.as_ref(),
        });
        if let Some(n) = line_note(ds, p) {
            obs.event(&Event::LineNote {
                pattern: name,
                note: &n,
            });
        }
        if p.symmetry_cut
            && (ds.scene.substrate.sigma_h > 0.0 || ds.scene.slider.offset != [0.0; 2])
        {
            obs.event(&Event::ApproximateCut {
                pattern: name,
                offset: ds.scene.slider.offset != [0.0; 2],
            });
        }
        let (screen_rows, screen_wall_s) = screen_stage(ds, &thetas_deg, p, self.store, obs)?;
        // 2. shortlist
        obs.stage(Stage::Shortlist, name);
        let orientations = shortlist::orientations(&screen_rows, &p.loads, ds.scene.coating.p_crit);
        let levels = shortlist::levels(&orientations, &p.loads, p.per_level, p.max_top);
        if levels.is_empty() {
            obs.event(&Event::NoIntactOrientation { pattern: name });
        }
        // 3–5. level by level: α scan, estimate, robust search
        let bx = tolerance_box(p);
        let (robust, floor_mn, keep) = match search {
            Search::Nominal => (false, 0.0, 0),
            Search::Robust { floor_mn, keep } => (!bx.is_point(), floor_mn, keep),
        };
        let limit = LimitParams {
            loads: p.loads.clone(),
            mu_superlubric: p.mu_superlubric,
            line: p.line,
            friction: p.friction,
        };
        let solvers: Vec<Solver> = if robust {
            seed_solvers(ds, p, None)?
        } else {
            Vec::new()
        };
        let mut searches = robust::Searches::new(ds, p, &solvers, &limit, self.store)?;
        let mut solver: Option<Solver> = None;
        let need = p.confirm.max(3);
        let mut evaluated: Vec<Evaluated> = Vec::new();
        let mut ranking: Vec<Candidate> = Vec::new();
        let mut best = 0.0f64; // best superlubric load so far (mN)
        let mut levels_evaluated = 0;
        let mut levels_skipped: Vec<usize> = Vec::new();
        let mut stop = Stop::EveryLevel;
        for (li, level) in levels.iter().enumerate() {
            let from = ranking.len();
            let w_mn = label(n_to_mn(level.load));
            if w_mn < best && ranking.len() >= need {
                stop = Stop::Before {
                    level: level.load,
                    reach_mn: w_mn,
                    best_mn: best,
                };
                break;
            }
            // with a floor (many patterns): a level whose orientations cannot exceed it over
            // the tolerance box is evaluated only where the nominal pass evaluated it
            // (stored), for the pattern's own ranking, and skipped otherwise
            if robust && floor_mn > 0.0 {
                let reach = if w_mn <= floor_mn {
                    w_mn
                } else {
                    robust::level_reach(solver_of(&mut solver, ds)?, level, &bx, p)
                };
                let nominal_best = ranking
                    .iter()
                    .map(|c| c.score.nominal_to_mn)
                    .fold(best, f64::max);
                if reach <= floor_mn && w_mn < nominal_best && ranking.len() >= need {
                    levels_skipped.push(li);
                    levels_evaluated += 1;
                    continue;
                }
            }
            levels_evaluated += 1;
            // 3–4. α scan and estimate of the level's orientations
            let s = solver_of(&mut solver, ds)?;
            let found = self.evaluate(ds, level, &sym, s)?;
            for e in found {
                ranking.extend(rank::candidates(
                    name,
                    &e.eval,
                    label(n_to_mn(level.load)),
                    &e.reason,
                    ds.scene.coating.p_crit,
                    p.mu_superlubric,
                ));
                evaluated.push(e);
            }
            // 5. the robust limits of this level's candidates (the stop rule above then
            // compares each level's bound with the best robust limit: a robust design may sit
            // lower)
            if robust && ranking[from..].iter().any(|c| c.score.nominal_to_mn > 0.0) {
                obs.stage(Stage::RobustSearch, name);
                robust::robust_stage(
                    ds,
                    &mut ranking,
                    &mut searches,
                    p,
                    self.store,
                    obs,
                    floor_mn,
                    keep,
                )?;
            }
            best = ranking
                .iter()
                .filter(|c| c.score.exact)
                .map(|c| c.score.superlubric_to_mn)
                .fold(best, f64::max);
        }
        // the ranking (by the robust limit with a tolerance: computed level by level above)
        ranking.sort_by(rank::compare);
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
                pattern: name,
                designs: floored,
                floor_mn,
            });
        }
        if let Some(b) = ranking.first() {
            obs.event(&Event::Best {
                pattern: name,
                design: b,
                evaluated: evaluated.len(),
                stop: &stop,
                skipped: levels_skipped.len(),
                floor_mn,
            });
        }
        Ok(PatternResult {
            scene: ds.clone(),
            sym,
            thetas_deg,
            screen: screen_rows,
            screen_wall_s,
            orientations,
            levels,
            levels_evaluated,
            levels_skipped,
            stop,
            evaluated,
            ranking,
            resonance_flagged: 0,
            robust_floor_mn: floor_mn,
            trimmed: false,
        })
    }

    /// Stages 3 and 4 for one shortlist level: the α scan and the friction estimate of its
    /// orientations (side by side, each also parallel inside; results in order; stored ones
    /// reused).
    fn evaluate(
        &self,
        ds: &DesignScene,
        level: &Level,
        sym: &super::symmetry::PairSymmetry,
        solver: &Solver,
    ) -> Result<Vec<Evaluated>> {
        let p = self.p;
        let reason = if level.top {
            "survives the highest load".to_string()
        } else {
            format!("best of level {}", shortlist::mn(level.load))
        };
        let per = scan::paths_per_scan(p, sym) + p.alphas_per_theta;
        self.obs.event(&Event::Level {
            pattern: &ds.name,
            load: level.load,
            picks: level.picks.len(),
            size: level.size,
            paths: (level.picks.len() * per) as u64,
        });
        let done = eval_level(
            ds,
            &level.picks,
            level.load,
            sym,
            p,
            self.store,
            solver,
            per,
            self.obs,
        )?;
        self.obs.progress().finish();
        Ok(level
            .picks
            .iter()
            .zip(done)
            .map(|(o, (eval, wall_s, reused))| Evaluated {
                orientation: o.clone(),
                reason: reason.clone(),
                scan_alphas_deg: eval.scan.iter().map(|r| r.alpha_deg).collect(),
                estimates: eval.friction.len(),
                eval,
                wall_s,
                reused,
            })
            .collect())
    }

    /// A shard of the DEM stage: its share of the runs, no report (an outcome without DEM
    /// entries or answers).
    fn dem_shard(&self, patterns: Vec<PatternResult>) -> Result<DesignOutcome> {
        let p = self.p;
        let (jobs, _) = confirm_jobs(&patterns, p);
        let part = p.dem_shard.range(jobs.len());
        let dir = self.store.path("dem");
        self.obs.event(&Event::DemShard {
            index: p.dem_shard.index,
            count: p.dem_shard.count,
            start: part.start,
            end: part.end,
            runs: jobs.len(),
            dir: &dir,
        });
        let dem: Vec<SlideOutcome> = if part.is_empty() {
            Vec::new()
        } else {
            run_batch(&jobs[part], p.jobs, &dir, self.obs.progress())?
        };
        let failed = dem.iter().filter(|o| o.error.is_some()).count();
        if failed > 0 {
            self.obs.event(&Event::DemShardFailed { failed });
        }
        Ok(DesignOutcome {
            patterns,
            dem: Vec::new(),
            dem_ran: false,
            answers: Vec::new(),
            maps: Vec::new(),
            p_crit: None,
        })
    }

    /// The report data: each pattern's answer (its ranking checked against the DEM) and the
    /// tolerance maps (every pattern's answer, or across many patterns the best patterns'
    /// only).
    fn report_data(
        &self,
        patterns: Vec<PatternResult>,
        dem: Vec<super::DemEntry>,
        cross: bool,
    ) -> Result<DesignOutcome> {
        let p = self.p;
        let answers = patterns
            .iter()
            .map(|pr| answer::answer(pr, &dem, !p.no_dem, p))
            .collect();
        let mut o = DesignOutcome {
            patterns,
            dem,
            dem_ran: !p.no_dem,
            answers,
            maps: Vec::new(),
            p_crit: None,
        };
        let mapped = best::best_order(&o, best::BEST_PATTERNS);
        for (i, (pr, a)) in o.patterns.iter().zip(&o.answers).enumerate() {
            let c = a.index.and_then(|i| pr.ranking.get(i));
            o.maps.push(match c {
                Some(c)
                    if !tolerance_box(p).is_point()
                        && c.score.nominal_to_mn > 0.0
                        && (!cross || mapped.contains(&i)) =>
                {
                    Some(answer_map(&pr.scene, c, p, self.store, self.obs)?)
                }
                _ => None,
            });
        }
        // the best named recipe's limit against the coating's strength
        let decisions = super::recipe_answer::decisions(&o);
        if let Some(d) = decisions.iter().find(|d| d.naming.nameable()) {
            let pr = &o.patterns[d.pattern];
            let c = &pr.ranking[d.design];
            self.obs.event(&Event::PCritSweep {
                pattern: &pr.scene.name,
            });
            o.p_crit = Some(super::p_crit::p_crit_sweep(&pr.scene, c, p, self.store)?);
        }
        Ok(o)
    }
}
