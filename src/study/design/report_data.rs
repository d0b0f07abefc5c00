//! Stage 7 of a design, the report data: what the report is built from — each
//! pattern's answer (its ranking checked against the DEM, [`super::answer`]), the tolerance
//! map around the answers ([`tolerance_map`]) and, with recipes, the best named recipe's limit
//! against the coating's strength ([`super::p_crit`]). Cost: one tolerance map per mapped
//! answer (17 × 9 points at the design's loads) and one robust search per other P_crit.

use super::answer;
use super::best;
use super::ctx::Ctx;
use super::dem_entry::DemEntry;
use super::limit::{limit_record, tolerance_box};
use super::observer::Event;
use super::outcome::DesignOutcome;
use super::params::DesignScene;
use super::pattern_result::{AnswerMap, PatternResult};
use super::rank::Candidate;
use crate::runs::meta::{scene_file, Inputs};
use crate::study::rows::label;
use crate::study::tolerance::MapParams;
use anyhow::Result;
use serde_json::json;
use surrogate::solver::Solver;
use surrogate::units::deg_to_rad;

/// The report data stage (see the module docs).
pub struct ReportDataStage<'a> {
    ctx: Ctx<'a>,
}

impl<'a> ReportDataStage<'a> {
    /// The stage in `ctx`.
    pub fn new(ctx: Ctx<'a>) -> Self {
        ReportDataStage { ctx }
    }

    /// The outcome of `patterns` (trimmed) and their DEM runs `dem`: each pattern's answer,
    /// the tolerance maps (every pattern's answer, or with `cross`, across many patterns, the
    /// best patterns' only) and the P_crit sweep of the best named recipe.
    pub fn run(
        &self,
        patterns: Vec<PatternResult>,
        dem: Vec<DemEntry>,
        cross: bool,
    ) -> Result<DesignOutcome> {
        let Ctx { p, store, obs } = self.ctx;
        let answers = patterns
            .iter()
            .map(|pr| answer::answer(pr, &dem, !p.confirm.no_dem, p))
            .collect();
        let mut o = DesignOutcome {
            patterns,
            dem,
            dem_ran: !p.confirm.no_dem,
            answers,
            maps: Vec::new(),
            p_crit: None,
            yields: Vec::new(),
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
                    Some(tolerance_map(self.ctx, &pr.scene, c)?)
                }
                _ => None,
            });
        }
        // the best named recipe's limit against the coating's strength
        let decisions = super::recipe_answer::decisions(&o);
        if let Some(d) = decisions.iter().find(|d| d.naming.nameable()) {
            let pr = &o.patterns[d.pattern];
            let c = &pr.ranking[d.design];
            obs.event(&Event::PCritSweep {
                pattern: &pr.scene.name,
            });
            o.p_crit = Some(super::p_crit::p_crit_sweep(&pr.scene, c, p, store)?);
        }
        Ok(o)
    }
}

/// The tolerance map around the answer `c` of `ds`: θ ±2·tol in 17 points × direction ±2·tol
/// in 9 points (at least ±0.1° and ±0.5°), at the design's loads; stored
/// (`stages/<name>/tolerance_map.json`) and reused. Cost: 153 points, each the friction
/// estimate at every load up to its limit.
pub fn tolerance_map(ctx: Ctx, ds: &DesignScene, c: &Candidate) -> Result<AnswerMap> {
    let Ctx { p, store, obs } = ctx;
    let progress = obs.progress();
    let grid = |tol: f64, min: f64, n: usize| -> Vec<f64> {
        let r = (2.0 * tol).max(min);
        (0..n)
            .map(|k| label(-r + 2.0 * r * k as f64 / (n - 1) as f64))
            .collect()
    };
    let mp = MapParams {
        theta_deg: c.theta_deg,
        direction_deg: c.direction_deg,
        theta_offsets_deg: grid(p.tolerance.theta_tol_deg, 0.1, 17),
        direction_offsets_deg: grid(p.tolerance.direction_tol_deg, 0.5, 9),
        limit: p.limit(),
    };
    let inputs = Inputs {
        workflow: "design/tolerance-map".into(),
        scene: Some(scene_file(&ds.scene.with_theta(deg_to_rad(c.theta_deg)))),
        params: json!({
            "theta_deg": c.theta_deg,
            "direction_deg": c.direction_deg,
            "theta_offsets_deg": mp.theta_offsets_deg,
            "direction_offsets_deg": mp.direction_offsets_deg,
            "limit": limit_record(p),
        }),
    };
    let rel = format!("stages/{}/tolerance_map.json", ds.name);
    if let Some(m) = store.load_json::<AnswerMap>(&rel, &inputs)? {
        return Ok(m);
    }
    let mut sc = ds.scene.clone();
    sc.slider.theta = 0.0;
    let solver = Solver::new(&sc)?;
    let n = mp.theta_offsets_deg.len() * mp.direction_offsets_deg.len();
    obs.event(&Event::ToleranceMap {
        pattern: &ds.name,
        points: n as u64,
    });
    let rows = crate::study::tolerance::map(&solver, &mp, &|| progress.advance(1))?;
    progress.finish();
    let m = AnswerMap {
        nominal: (c.theta_deg, c.direction_deg),
        theta_points: mp.theta_offsets_deg.len(),
        rows,
    };
    store.save_json(&rel, &inputs, &m)?;
    Ok(m)
}
