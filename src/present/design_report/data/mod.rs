//! [`ReportData`]: every string and number `report.md.j2` prints, computed from the design's
//! outcome. The template holds the prose and the layout (loops and ifs only); every number is
//! formatted here, so the template does no arithmetic and no number formatting.

mod dem;
mod lines;

use dem::dem_section;
pub use lines::{
    DemLine, DemSection, DemWall, LevelLine, RankingLine, Reproduce, ReproduceTheta, ResonanceLine,
    ScreenLine, StudyCheck, WallLine,
};

use super::commands::slide_command;
use super::commands::{corrugation_command, friction_command, loads_text, screen_command};
use super::rows::{dem_rows, DemRow};
use super::words::{fmt_g, opt};
use crate::study::design::symmetry_words::SymmetryWords;
use crate::study::design::{tolerance_box, DesignOutcome, DesignParams};
use crate::study::friction::resonance_note;
use crate::study::rows::label;
use serde::Serialize;
use surrogate::units::n_to_mn;

/// Everything `report.md` shows, in its order.
#[derive(Debug, Clone, Serialize)]
pub struct ReportData {
    /// The version, date and command line that made the report ([`super::stamp::Made`]).
    pub made: super::stamp::Made,
    /// The pattern names, comma separated.
    pub patterns: String,
    /// The loads (mN), comma separated.
    pub loads_mn: String,
    /// The superlubric limit on μ.
    pub mu_superlubric: String,
    /// What a limit between two loads of the ladder means, on this design's numbers
    /// (`limit_example`).
    pub limit_example: String,
    /// The answer table: one row per pattern ([`super::top::top_rows`]).
    pub top: Vec<super::top::TopRow>,
    /// The yield stage's column head and plots (`None`: it did not run).
    pub fab_yield: Option<super::yields::YieldHead>,
    /// One short paragraph per pattern's answer ([`super::top::paragraph`]).
    pub answers: Vec<String>,
    /// How to run each answer: its scene file and commands ([`super::top::answer_runs`]).
    pub runs: Vec<super::top::AnswerRun>,
    /// The fabrication tolerance in words (`θ ±0.1° × pull direction ±0.5°`; empty without one).
    pub tolerance: String,
    /// Largest measured μ_est/μ_DEM of a mount in resonance
    /// ([`surrogate::friction::RESONANCE_DROP_MAX`]).
    pub resonance_drop: String,
    /// The patterns with a tolerance map around their answer (`tolerance_<p>.png`).
    pub maps: Vec<String>,
    /// The patterns side by side (`patterns.csv`), when more than one was designed.
    pub compared: Vec<super::patterns::PatternLine>,
    /// The fairness rule of the comparison, one sentence ([`super::patterns::fairness`]).
    pub fairness: String,
    /// The recipes of `design --vary` ([`super::recipes::section`]); `None` without recipes.
    pub recipes: Option<super::recipes::RecipeSection>,
    /// The best patterns with a contact map (`contacts_<p>.png`), best first.
    pub contact_maps: Vec<String>,
    /// Whether the DEM stage ran.
    pub dem_ran: bool,
    /// The DEM comparison (when the DEM ran and had runs).
    pub dem: Option<DemSection>,
    /// The best 10 candidates per pattern.
    pub ranking: Vec<RankingLine>,
    /// How the ranking's tolerance box is sampled, in words (empty without a tolerance).
    pub sampling: String,
    /// The verdict's band in words ([`crate::study::verdict::band_words`]), per pattern's P_crit.
    pub band: String,
    /// Patterns with candidates on a mount in resonance.
    pub resonance: Vec<ResonanceLine>,
    /// The screen and shortlist of each pattern.
    pub screens: Vec<ScreenLine>,
    /// Wall times of tiers 1–2 per pattern.
    pub walls: Vec<WallLine>,
    /// Wall time of the DEM tier (when it ran and had runs).
    pub dem_wall: Option<DemWall>,
    /// The commands reproducing the surrogate rows, per pattern.
    pub reproduce: Vec<Reproduce>,
    /// The commands reproducing the DEM runs.
    pub slides: Vec<String>,
}

/// A window cell: `±w` (degrees), `0` for none, `–` where not computed.
fn window(w: Option<f64>) -> String {
    match w {
        None => "–".into(),
        Some(0.0) => "0".into(),
        Some(w) => format!("±{w}"),
    }
}

/// The tolerance box and its sampling in words, e.g. `θ ±0.1° sampled every 0.02° (11 offsets)
/// × pull direction ±0.5° every 0.25° (5 offsets)`, plus the seeds; empty without a tolerance.
/// The step stated is the one used: the tolerance over the offsets on each side (≤ the
/// `--…-tol-step` asked).
pub fn sampling_words(p: &DesignParams) -> String {
    let bx = tolerance_box(p);
    if bx.is_point() {
        return String::new();
    }
    let axis = |tol: f64, o: &[f64]| {
        if o.len() < 2 {
            format!("±{tol}° (not sampled)")
        } else {
            let step = label(o[1] - o[0]);
            format!("±{tol}° sampled every {step}° ({} offsets)", o.len())
        }
    };
    let mut m = format!(
        "θ {} × pull direction {}",
        axis(p.tolerance.theta_tol_deg, &bx.theta_offsets_deg),
        axis(p.tolerance.direction_tol_deg, &bx.direction_offsets_deg)
    );
    if !p.tolerance.seeds.is_empty() {
        m.push_str(&format!(
            " × the substrate seeds {} besides the scene's own",
            p.tolerance
                .seeds
                .iter()
                .map(|s| s.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    m
}

/// The verdict's band in words for the patterns' P_crit (one sentence per distinct P_crit).
fn band_text(o: &DesignOutcome, p: &DesignParams) -> String {
    let mut seen: Vec<f64> = Vec::new();
    let mut parts: Vec<String> = Vec::new();
    for pr in &o.patterns {
        let pc = pr.scene.scene.coating.p_crit;
        if !seen.contains(&pc) {
            seen.push(pc);
            parts.push(crate::study::verdict::band_words(p.mu_superlubric, pc));
        }
    }
    parts.join("; ")
}

/// What a limit between two loads of the ladder means, in words, on the first answer whose limit
/// lies below the top load (`a limit of 1.75 mN means superlubric at 1.75 mN and every load
/// below it, not at the next load tried, 2.1 mN`), else on the ladder's first two loads.
fn limit_example(o: &DesignOutcome, p: &DesignParams) -> String {
    let ladder: Vec<f64> = p.loads.iter().map(|&w| label(n_to_mn(w))).collect();
    let said = |l: f64, next: f64| {
        format!(
            "a limit of {l} mN means superlubric at {l} mN and at every load below it, and not at the next load tried, {next} mN"
        )
    };
    for (pr, a) in o.patterns.iter().zip(&o.answers) {
        let Some(c) = a.index.and_then(|i| pr.ranking.get(i)) else {
            continue;
        };
        let l = c.score.superlubric_to_mn;
        if let Some(&next) = ladder.iter().find(|&&x| x > l).filter(|_| l > 0.0) {
            return said(l, next);
        }
    }
    match ladder.as_slice() {
        [a, b, ..] => said(*a, *b),
        _ => String::new(),
    }
}

impl ReportData {
    /// The report's data from the outcome `o` of the design with parameters `p`.
    /// Cost: a pass over the ranking, the DEM runs and the evaluated θ.
    pub fn new(o: &DesignOutcome, p: &DesignParams) -> Self {
        // the patterns side by side, once (a slider site list per pattern)
        let pats = (o.patterns.len() > 1).then(|| super::patterns::pattern_rows(o));
        let dem = dem_rows(o, p);
        let has_dem = o.dem_ran && !dem.is_empty();
        let ranking = ranking_lines(o);
        let resonance = resonance_lines(o, p);
        let screens = screen_lines(o, p);
        let walls = wall_lines(o, p);
        let dem_wall = has_dem.then(|| {
            let sum: f64 = dem.iter().filter_map(|d| d.wall_s).sum();
            DemWall {
                runs: dem.len(),
                jobs: p.confirm.jobs,
                sum_s: fmt_g(sum, 3),
                elapsed_s: fmt_g(sum / p.confirm.jobs.min(dem.len()).max(1) as f64, 3),
            }
        });
        let reproduce = reproduce_lines(o, p);
        let slides = slide_lines(o, p, &dem);
        let mut top = super::top::top_rows(o, p, &dem);
        for (r, y) in top.iter_mut().zip(&o.yields) {
            r.fab_yield = super::yields::cell(y.as_ref());
        }
        let recipes = pats
            .as_ref()
            .and_then(|rows| super::recipes::section(rows, o, &top));
        ReportData {
            made: super::stamp::Made::now(),
            limit_example: limit_example(o, p),
            patterns: o
                .patterns
                .iter()
                .map(|pr| pr.scene.name.as_str())
                .collect::<Vec<_>>()
                .join(", "),
            loads_mn: loads_text(p),
            mu_superlubric: format!("{}", p.mu_superlubric),
            top,
            answers: answer_paragraphs(o, p),
            runs: super::top::answer_runs(o, p),
            tolerance: if tolerance_box(p).is_point() {
                String::new()
            } else {
                format!(
                    "θ ±{}° × pull direction ±{}°",
                    p.tolerance.theta_tol_deg, p.tolerance.direction_tol_deg
                )
            },
            resonance_drop: format!("{}", surrogate::friction::RESONANCE_DROP_MAX),
            maps: o
                .patterns
                .iter()
                .zip(&o.maps)
                .filter(|(_, m)| m.is_some())
                .map(|(pr, _)| pr.scene.name.clone())
                .collect(),
            contact_maps: if o.patterns.len() > 1 {
                crate::study::design::best::best_order(o, super::patterns::CONTACT_MAPS)
                    .into_iter()
                    .map(|i| o.patterns[i].scene.name.clone())
                    .collect()
            } else {
                Vec::new()
            },
            fairness: pats
                .as_ref()
                .map_or(String::new(), |rows| super::patterns::fairness(o, rows)),
            recipes,
            compared: pats
                .as_ref()
                .map_or(Vec::new(), |rows| rows.iter().map(Into::into).collect()),
            fab_yield: super::yields::head(o, p),
            dem_ran: o.dem_ran,
            dem: has_dem.then(|| dem_section(o, p, &dem)),
            ranking,
            sampling: sampling_words(p),
            band: band_text(o, p),
            resonance,
            screens,
            walls,
            dem_wall,
            reproduce,
            slides,
        }
    }
}

/// The ten best candidates of each pattern, as the ranking table shows them.
fn ranking_lines(o: &DesignOutcome) -> Vec<RankingLine> {
    o.patterns
        .iter()
        .flat_map(|pr| {
            pr.ranking
                .iter()
                .take(10)
                .enumerate()
                .map(|(k, c)| RankingLine {
                    pattern: c.pattern.clone(),
                    rank: k + 1,
                    theta_deg: format!("{}", c.theta_deg),
                    alpha_deg: format!("{}", c.alpha_deg),
                    pull_deg: fmt_g(c.direction_deg, 4),
                    superlubric_to_mn: format!(
                        "{}{}",
                        if c.score.exact { "" } else { "≤ " },
                        c.score.superlubric_to_mn
                    ),
                    nominal_mn: format!("{}", c.score.nominal_to_mn),
                    theta_window_deg: window(c.score.theta_window_deg),
                    direction_window_deg: window(c.score.direction_window_deg),
                    verdict: c.score.verdict.to_string(),
                    mu_worst: fmt_g(c.score.mu_worst, 3),
                    contacts: fmt_g(c.score.contacts, 3),
                    intact_to_mn: format!("{}", c.score.intact_to_mn),
                    screen_intact_to_mn: format!("{}", c.screen_intact_to_mn),
                    corrugation_nm: fmt_g(c.corrugation_nm, 3),
                    reason: super::words::pick_words(c.reason),
                })
        })
        .collect()
}

/// The patterns with candidates flagged near a resonance, with the note that explains it.
fn resonance_lines(o: &DesignOutcome, p: &DesignParams) -> Vec<ResonanceLine> {
    o.patterns
        .iter()
        .filter_map(|pr| {
            let flagged = pr.resonance_flagged;
            let note = resonance_note(&pr.scene.scene, &p.friction)?;
            (flagged > 0).then(|| ResonanceLine {
                pattern: pr.scene.name.clone(),
                flagged,
                candidates: pr.ranking.len(),
                note,
            })
        })
        .collect()
}

/// Each pattern's screen: its symmetry, θ range, loads and shortlist levels.
fn screen_lines(o: &DesignOutcome, p: &DesignParams) -> Vec<ScreenLine> {
    o.patterns
        .iter()
        .map(|pr| ScreenLine {
            pattern: pr.scene.name.clone(),
            symmetry: {
                let mut t =
                    match crate::study::design::theta_note(&pr.sym, &pr.thetas_deg, &p.screen) {
                        None => pr.sym.describe(),
                        Some(n) if n.uncovered() => format!(
                            "{}; **{}**",
                            pr.sym.describe(),
                            super::words::theta_note(&n, &pr.sym)
                        ),
                        Some(n) => format!(
                            "{}; {}",
                            pr.sym.describe(),
                            super::words::theta_note(&n, &pr.sym)
                        ),
                    };
                if let Some(n) = crate::study::design::line_note(&pr.scene, p.alpha_scan.line) {
                    t = format!("{t}. The {}", n.trim_start_matches("the "));
                }
                crate::present::inputs::to_flags(&t)
            },
            thetas: pr.thetas_deg.len(),
            theta_first: pr
                .thetas_deg
                .first()
                .map_or(String::new(), |t| format!("{t}")),
            theta_last: pr
                .thetas_deg
                .last()
                .map_or(String::new(), |t| format!("{t}")),
            loads: p.loads.len(),
            levels: pr
                .levels
                .iter()
                .enumerate()
                .map(|(k, l)| LevelLine {
                    load_mn: format!("{}", label(n_to_mn(l.load))),
                    size: l.size,
                    kept: l.picks.len(),
                    evaluated: k < pr.levels_evaluated && !pr.levels_skipped.contains(&k),
                })
                .collect(),
            stop: super::log::pattern_stop(pr),
        })
        .collect()
}

/// Each pattern's work and wall times.
fn wall_lines(o: &DesignOutcome, p: &DesignParams) -> Vec<WallLine> {
    o.patterns
        .iter()
        .map(|pr| WallLine {
            pattern: pr.scene.name.clone(),
            thetas: pr.thetas_deg.len(),
            loads: p.loads.len(),
            screen_s: opt(pr.screen_wall_s, 3),
            evaluated: pr.evaluated.len(),
            scan_paths: pr.evaluated.iter().map(|e| e.scan_alphas_deg.len()).sum(),
            friction_paths: pr.evaluated.iter().map(|e| e.eval.alphas_deg.len()).sum(),
            estimates: pr.evaluated.iter().map(|e| e.estimates).sum(),
            evaluation_s: fmt_g(pr.evaluated.iter().map(|e| e.wall_s).sum(), 3),
        })
        .collect()
}

/// The commands that reproduce each pattern's screen and each evaluated θ.
fn reproduce_lines(o: &DesignOutcome, p: &DesignParams) -> Vec<Reproduce> {
    o.patterns
        .iter()
        .map(|pr| Reproduce {
            pattern: pr.scene.name.clone(),
            screen: screen_command(pr, p),
            evaluated: pr
                .evaluated
                .iter()
                .map(|e| ReproduceTheta {
                    theta_deg: format!("{}", e.eval.theta_deg),
                    corrugation: corrugation_command(pr, e, p),
                    friction: friction_command(pr, e, p),
                })
                .collect(),
        })
        .collect()
}

/// The `slide` command of each DEM run.
fn slide_lines(o: &DesignOutcome, p: &DesignParams, dem: &[DemRow]) -> Vec<String> {
    dem.iter()
        .zip(&o.dem)
        .filter_map(|(d, e)| {
            let pr = o.patterns.iter().find(|pr| pr.scene.name == d.pattern)?;
            Some(slide_command(pr, d, e.run.protocol, p))
        })
        .collect()
}

/// Each pattern's answer paragraph, with its yield sentence when the yield stage ran.
fn answer_paragraphs(o: &DesignOutcome, p: &DesignParams) -> Vec<String> {
    o.patterns
        .iter()
        .zip(&o.answers)
        .zip(o.yields.iter().chain(std::iter::repeat(&None)))
        .map(|((pr, a), y)| {
            let mut t = super::top::paragraph(pr, a, p);
            if let Some(s) = super::yields::sentence(pr, a, y.as_ref()) {
                t.push(' ');
                t.push_str(&s);
            }
            t
        })
        .collect()
}

#[cfg(test)]
mod tests {
    /// A window cell: a half-width with its ±, none as 0, not computed as a dash.
    #[test]
    fn window_cells() {
        assert_eq!(super::window(Some(0.25)), "±0.25");
        assert_eq!(super::window(Some(0.0)), "0");
        assert_eq!(super::window(None), "–");
    }
}
