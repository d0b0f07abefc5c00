//! Stages 3 and 4 of a design on one shortlist level: the α scan ([`super::alpha_scan`]) and
//! the friction estimate ([`super::estimate`])
//! of the level's orientations, each stage over every orientation side by side (each also
//! parallel inside), results in order. Each orientation's evaluation is stored
//! (`stages/<name>/theta_<θ>.json`) and reused when finished. Cost: [`paths_per_scan`] paths
//! per orientation for the scan plus one friction path per best α and chunk of loads.

use super::alpha_scan::{paths_per_scan, scan_alpha, AlphaScan, Target};
use super::estimate::estimate;
use super::params::AlphaScanParams;
use super::record::{eval_inputs, evaluation_record};
use crate::runs::meta::Inputs;
use crate::runs::progress::Progress;
use crate::study::design::model::{
    DesignScene, EvalStage, Evaluated, Level, Orientation, Pick, ThetaEval,
};
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use crate::study::design::store::tag;
use crate::study::design::symmetry_words::PairSymmetry;
use crate::study::rows::{label, FrictionRow};
use anyhow::Result;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};
use std::time::Instant;
use surrogate::solver::Solver;
use surrogate::units::{n_to_mn, rad_to_deg};

/// A shortlist level of one pattern, as the evaluation takes it.
#[derive(Clone, Copy)]
pub struct LevelInput<'a> {
    /// The pattern.
    pub ds: &'a DesignScene,
    /// The level (its load is the scan load of its orientations).
    pub level: &'a Level,
    /// The pair's symmetry (the α period of the scan).
    pub sym: &'a PairSymmetry,
    /// The pattern's solver (slider at θ = 0).
    pub solver: &'a Solver,
}

/// The α scan and estimate stages of a design on a shortlist level (see the module docs):
/// its knobs are [`AlphaScanParams`]; the estimate's are the shared limit knobs.
pub struct EvaluateStage<'a> {
    env: StageEnv<'a>,
    params: &'a AlphaScanParams,
}

/// The progress of a level's orientations: at most `per` ticks each, the rest when it is done.
struct Ticks<'a> {
    progress: &'a dyn Progress,
    per: usize,
    done: Vec<AtomicUsize>,
}

impl Ticks<'_> {
    fn tick(&self, k: usize) {
        if self.done[k].fetch_add(1, Relaxed) < self.per {
            self.progress.advance(1);
        }
    }
    fn finish(&self, k: usize) {
        let done = self.done[k].load(Relaxed);
        if done < self.per {
            self.progress.advance((self.per - done) as u64);
        }
    }
}

impl<'a> EvaluateStage<'a> {
    /// The stages in `env` with the α scan's knobs.
    pub fn new(env: StageEnv<'a>, params: &'a AlphaScanParams) -> Self {
        EvaluateStage { env, params }
    }

    /// The evaluated orientations of level `l`, in the level's order (stored ones reused),
    /// each with why it was shortlisted.
    pub fn run(&self, l: &LevelInput) -> Result<Vec<Evaluated>> {
        let obs = self.env.obs;
        let level = l.level;
        let reason = if level.top {
            Pick::Top
        } else {
            Pick::Level(level.load)
        };
        let per = paths_per_scan(self.params, l.sym) + self.params.alphas_per_theta;
        obs.event(&Event::Level {
            pattern: &l.ds.name,
            load: level.load,
            picks: level.picks.len(),
            size: level.size,
            paths: (level.picks.len() * per) as u64,
        });
        let done = self.evaluations(l, per)?;
        obs.progress().finish();
        Ok(level
            .picks
            .iter()
            .zip(done)
            .map(|(o, st)| Evaluated {
                orientation: o.clone(),
                reason,
                scan_alphas_deg: st.0.eval.scan.iter().map(|r| r.alpha_deg).collect(),
                estimates: st.0.eval.friction.len(),
                eval: st.0.eval,
                wall_s: st.0.wall_s,
                reused: st.1,
            })
            .collect())
    }

    /// Per pick of `l` (in order) its stored evaluation where finished, else its α scan (every
    /// such orientation side by side), then its estimate (likewise), stored; with whether it
    /// was reused. `per` paths per orientation go to the observer's bar.
    fn evaluations(&self, l: &LevelInput, per: usize) -> Result<Vec<(EvalStage, bool)>> {
        let StageEnv { limit, store, obs } = self.env;
        let picks = &l.level.picks;
        let loads_mn = limit.load_labels_mn();
        let rel = |o: &Orientation| format!("stages/{}/theta_{}.json", l.ds.name, tag(o.theta_deg));
        let inputs: Vec<Inputs> = picks
            .iter()
            .map(|o| {
                let knobs = evaluation_record(self.params, &limit.friction);
                eval_inputs(l.ds, (o.theta_deg, l.level.load), l.sym, &loads_mn, knobs)
            })
            .collect();
        let stored: Vec<Option<EvalStage>> = picks
            .iter()
            .zip(&inputs)
            .map(|(o, i)| store.load_json::<EvalStage>(&rel(o), i))
            .collect::<Result<_>>()?;
        let reused = stored.iter().flatten().count();
        if reused > 0 {
            obs.progress().advance((reused * per) as u64);
        }
        let ticks = Ticks {
            progress: obs.progress(),
            per,
            done: picks.iter().map(|_| AtomicUsize::new(0)).collect(),
        };
        let todo: Vec<usize> = (0..picks.len()).filter(|&k| stored[k].is_none()).collect();
        let target = |k: usize| Target {
            solver: l.solver,
            scene: &l.ds.scene,
            theta_deg: picks[k].theta_deg,
            scan_load: l.level.load,
        };
        let scans: Vec<(AlphaScan, f64)> = todo
            .par_iter()
            .map(|&k| {
                let t0 = Instant::now();
                let s = scan_alpha(&target(k), self.params, l.sym, &|| ticks.tick(k))?;
                Ok((s, t0.elapsed().as_secs_f64()))
            })
            .collect::<Vec<Result<_>>>()
            .into_iter()
            .collect::<Result<_>>()?;
        let limits = limit.limit();
        let estimates: Vec<Result<(Vec<FrictionRow>, f64)>> = todo
            .par_iter()
            .zip(&scans)
            .map(|(&k, (s, _))| {
                let t0 = Instant::now();
                let f = estimate(&target(k), s, &limits, &|| ticks.tick(k))?;
                Ok((f, t0.elapsed().as_secs_f64()))
            })
            .collect();
        let mut out: Vec<Option<(EvalStage, bool)>> =
            stored.into_iter().map(|s| s.map(|s| (s, true))).collect();
        for ((&k, (s, scan_s)), e) in todo.iter().zip(scans).zip(estimates) {
            let (friction, est_s) = e?;
            ticks.finish(k);
            let st = EvalStage {
                eval: ThetaEval {
                    theta_deg: label(picks[k].theta_deg),
                    scan_load_mN: label(n_to_mn(l.level.load)),
                    line_deg: rad_to_deg(s.line),
                    scan: s.scan,
                    alphas_deg: s.alphas_deg,
                    friction,
                },
                wall_s: scan_s + est_s,
            };
            store.save_json(&rel(&picks[k]), &inputs[k], &st)?;
            out[k] = Some((st, false));
        }
        out.into_iter()
            .map(|o| {
                o.ok_or_else(|| anyhow::anyhow!("an orientation was neither stored nor evaluated"))
            })
            .collect()
    }
}
