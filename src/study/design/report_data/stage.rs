//! Stage 7 of a design, the report data: what the report is built from — each
//! pattern's answer (its ranking checked against the DEM, [`crate::study::design::model::answer`]), the tolerance
//! map around the answers ([`super::tolerance_map()`]) and, with recipes, the best named recipe's limit
//! against the coating's strength ([`super::p_crit`]). Cost: one tolerance map per mapped
//! answer (17 × 9 points at the design's loads) and one robust search per other P_crit.

use super::best;
use super::p_crit::p_crit_sweep;
use super::recipe_answer;
use super::tolerance_map::tolerance_map;
use crate::study::design::model::answer::{answer, AnswerRule};
use crate::study::design::model::{DemEntry, DesignOutcome, PatternResult};
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use anyhow::Result;

/// The report data's knobs: how the answers are decided and whether the DEM ran.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReportDataParams {
    /// The rule of each pattern's answer.
    pub answer: AnswerRule,
    /// Whether the DEM stage ran (not `--no-dem`).
    pub dem_ran: bool,
}

/// What the report data is made of: the (trimmed) patterns, their DEM runs and whether the
/// patterns were taken across many (then only the best patterns' answers are mapped).
pub struct ReportDataInput {
    /// Every pattern's result, in the order given.
    pub patterns: Vec<PatternResult>,
    /// The DEM runs (empty without the DEM).
    pub dem: Vec<DemEntry>,
    /// Whether the patterns were taken across many, best first (the pipeline's plan).
    pub cross: bool,
}

/// The report data stage (see the module docs); its knobs are [`ReportDataParams`]; it reads
/// the shared limit knobs (the tolerance box, the ladder).
pub struct ReportDataStage<'a> {
    env: StageEnv<'a>,
    params: &'a ReportDataParams,
}

impl<'a> ReportDataStage<'a> {
    /// The stage in `env` with its knobs.
    pub fn new(env: StageEnv<'a>, params: &'a ReportDataParams) -> Self {
        ReportDataStage { env, params }
    }

    /// The outcome of the patterns (trimmed) and their DEM runs: each pattern's answer, the
    /// tolerance maps (every pattern's answer, or with `cross`, across many patterns, the
    /// best patterns' only) and the P_crit sweep of the best named recipe.
    pub fn run(&self, input: ReportDataInput) -> Result<DesignOutcome> {
        let StageEnv { limit, store, obs } = self.env;
        let ReportDataInput {
            patterns,
            dem,
            cross,
        } = input;
        let dem_ran = self.params.dem_ran;
        let answers = patterns
            .iter()
            .map(|pr| answer(pr, &dem, dem_ran, &self.params.answer))
            .collect();
        let mut o = DesignOutcome {
            patterns,
            dem,
            dem_ran,
            answers,
            maps: Vec::new(),
            p_crit: None,
            yields: Vec::new(),
        };
        let mapped = best::best_order(&o, best::BEST_PATTERNS);
        let point = limit.tolerance_box().is_point();
        for (i, (pr, a)) in o.patterns.iter().zip(&o.answers).enumerate() {
            let c = a.index.and_then(|i| pr.ranking.get(i));
            o.maps.push(match c {
                Some(c)
                    if !point && c.score.nominal_to_mn > 0.0 && (!cross || mapped.contains(&i)) =>
                {
                    Some(tolerance_map(self.env, &pr.scene, c)?)
                }
                _ => None,
            });
        }
        // the best named recipe's limit against the coating's strength
        let decisions = recipe_answer::decisions(&o);
        if let Some(d) = decisions.iter().find(|d| d.naming.nameable()) {
            let pr = &o.patterns[d.pattern];
            let c = &pr.ranking[d.design];
            obs.event(&Event::PCritSweep {
                pattern: &pr.scene.name,
            });
            o.p_crit = Some(p_crit_sweep(&pr.scene, c, limit, store)?);
        }
        Ok(o)
    }
}
