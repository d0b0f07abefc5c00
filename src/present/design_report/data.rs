//! [`ReportData`]: every string and number `report.md.j2` prints, computed from the design's
//! outcome. The template holds the prose and the layout (loops and ifs only); every number is
//! formatted here, so the template does no arithmetic and no number formatting.

use super::commands::slide_command;
use super::commands::{corrugation_command, friction_command, loads_text, screen_command};
use super::rows::{dem_rows, DemRow};
use super::top::{angle, angle_decimals};
use super::words::{fmt_g, opt, protocol_words, which_design};
use crate::study::design::{tolerance_box, DesignOutcome, DesignParams};
use crate::study::friction::resonance_note;
use crate::study::rows::label;
use serde::Serialize;
use surrogate::units::{m_to_um, n_to_mn};

/// Everything `report.md` shows, in its order.
#[derive(Debug, Clone, Serialize)]
pub struct ReportData {
    /// The pattern names, comma separated.
    pub patterns: String,
    /// The loads (mN), comma separated.
    pub loads_mn: String,
    /// The superlubric limit on μ.
    pub mu_superlubric: String,
    /// The answer table: one row per pattern ([`super::top::top_rows`]).
    pub top: Vec<super::top::TopRow>,
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

/// The DEM comparison: protocol, its measured difference from the study's, one row per run.
#[derive(Debug, Clone, Serialize)]
pub struct DemSection {
    /// The confirmation protocol in words.
    pub protocol: String,
    /// The confirmation protocol is the study's.
    pub study_protocol: bool,
    /// The DEM model and reductions in words.
    pub model: String,
    /// The study-protocol checks.
    pub checks: Vec<StudyCheck>,
    /// No check and a protocol shorter than the study's (`--no-protocol-check`).
    pub unmeasured: bool,
    /// One row per DEM run.
    pub rows: Vec<DemLine>,
    /// Runs whose DEM and estimate verdicts agree.
    pub agree: usize,
    /// Runs with both verdicts.
    pub judged: usize,
    /// Friction path length (µm).
    pub path_um: String,
    /// The study DEM's slide length (µm).
    pub slid_um: String,
    /// Largest measured μ_est/μ_DEM of a mount in resonance
    /// ([`surrogate::friction::RESONANCE_DROP_MAX`]).
    pub resonance_drop: String,
}

/// One study-protocol run against the same run with the design's shorter protocol.
#[derive(Debug, Clone, Serialize)]
pub struct StudyCheck {
    /// Which design, in words.
    pub what: String,
    pub pattern: String,
    pub theta_deg: String,
    pub alpha_deg: String,
    pub load_mn: String,
    /// Both runs have a μ.
    pub measured: bool,
    /// μ of the short and the study protocol.
    pub mu_short: String,
    pub mu_study: String,
    /// (μ_short/μ_study − 1) in %, signed, one decimal.
    pub difference_pct: String,
    /// Both DEM verdicts are the same.
    pub same: bool,
    /// The verdicts in words (short, study).
    pub short_verdict: String,
    pub study_verdict: String,
    /// Why the study-protocol run did not complete.
    pub error: String,
}

/// One row of the DEM table (cells as printed).
#[derive(Debug, Clone, Serialize)]
pub struct DemLine {
    pub pattern: String,
    pub rank: usize,
    pub theta_deg: String,
    pub alpha_deg: String,
    /// `δθ, δdir` of a tolerance-corner run, `–` for the design itself.
    pub corner: String,
    pub load_mn: String,
    pub protocol: String,
    pub mu_est: String,
    pub mu_dem: String,
    pub ratio: String,
    pub verdict_est: String,
    pub verdict_dem: String,
    pub max_p_max_gpa: String,
    pub contacts: String,
    /// Status, with the error after a colon.
    pub status: String,
    pub wall_s: String,
}

/// One row of the ranking table (cells as printed).
#[derive(Debug, Clone, Serialize)]
pub struct RankingLine {
    pub pattern: String,
    pub rank: usize,
    pub theta_deg: String,
    pub alpha_deg: String,
    pub pull_deg: String,
    /// The robust limit (mN), `≤ x` where it is an upper bound (`robust_exact = false`).
    pub superlubric_to_mn: String,
    /// The limit at the nominal (θ, α) alone (mN).
    pub nominal_mn: String,
    /// The θ and direction windows (±degrees), `–` where not computed.
    pub theta_window_deg: String,
    pub direction_window_deg: String,
    /// The worst verdict up to the robust limit.
    pub verdict: String,
    pub mu_worst: String,
    pub contacts: String,
    pub intact_to_mn: String,
    pub screen_intact_to_mn: String,
    pub corrugation_nm: String,
    pub reason: String,
}

/// Candidates of a pattern with failed contacts on a mount in resonance.
#[derive(Debug, Clone, Serialize)]
pub struct ResonanceLine {
    pub pattern: String,
    pub flagged: usize,
    pub candidates: usize,
    /// The resonance in words.
    pub note: String,
}

/// The screen and the shortlist levels of one pattern.
#[derive(Debug, Clone, Serialize)]
pub struct ScreenLine {
    pub pattern: String,
    /// The symmetry cut in words.
    pub symmetry: String,
    pub thetas: usize,
    /// First and last θ screened (empty when none).
    pub theta_first: String,
    pub theta_last: String,
    pub loads: usize,
    /// The levels, highest first.
    pub levels: Vec<LevelLine>,
    /// Why the evaluation stopped.
    pub stop: String,
}

/// One shortlist level.
#[derive(Debug, Clone, Serialize)]
pub struct LevelLine {
    pub load_mn: String,
    pub size: usize,
    pub kept: usize,
    pub evaluated: bool,
}

/// Wall times of the screen and the evaluation of one pattern.
#[derive(Debug, Clone, Serialize)]
pub struct WallLine {
    pub pattern: String,
    pub thetas: usize,
    pub loads: usize,
    pub screen_s: String,
    pub evaluated: usize,
    pub scan_paths: usize,
    pub friction_paths: usize,
    pub estimates: usize,
    pub evaluation_s: String,
}

/// Wall time of the DEM tier.
#[derive(Debug, Clone, Serialize)]
pub struct DemWall {
    pub runs: usize,
    pub jobs: usize,
    pub sum_s: String,
    pub elapsed_s: String,
}

/// The reproduction commands of one pattern's surrogate stages.
#[derive(Debug, Clone, Serialize)]
pub struct Reproduce {
    pub pattern: String,
    pub screen: String,
    pub evaluated: Vec<ReproduceTheta>,
}

/// The commands of one evaluated θ.
#[derive(Debug, Clone, Serialize)]
pub struct ReproduceTheta {
    pub theta_deg: String,
    pub corrugation: String,
    pub friction: String,
}

fn verdict_word(v: Option<bool>) -> &'static str {
    match v {
        Some(true) => "superlubric",
        Some(false) => "not superlubric",
        None => "no verdict",
    }
}

fn dem_line(d: &DemRow, dec: usize) -> DemLine {
    let verdict = |v: Option<bool>| match v {
        Some(true) => "superlubric",
        Some(false) => "not",
        None => "–",
    };
    DemLine {
        pattern: d.pattern.clone(),
        rank: d.rank,
        theta_deg: angle(d.theta_deg, dec),
        alpha_deg: angle(d.alpha_deg, dec),
        corner: if d.theta_offset_deg == 0.0 && d.direction_offset_deg == 0.0 {
            "–".to_string()
        } else {
            format!("{:+}, {:+}", d.theta_offset_deg, d.direction_offset_deg)
        },
        load_mn: format!("{}", d.load_mN),
        protocol: d.protocol.clone(),
        mu_est: opt(d.mu_est, 3),
        mu_dem: opt(d.mu_dem, 3),
        ratio: opt(d.ratio_est_dem, 3),
        verdict_est: verdict(d.superlubric_est).into(),
        verdict_dem: verdict(d.superlubric_dem).into(),
        max_p_max_gpa: opt(d.max_p_max_GPa, 3),
        contacts: opt(d.mean_contacts, 3),
        status: if d.error.is_empty() {
            d.status.clone()
        } else {
            format!("{}: {}", d.status, d.error.replace('|', "/"))
        },
        wall_s: opt(d.wall_s, 3),
    }
}

fn dem_section(o: &DesignOutcome, p: &DesignParams, dem: &[DemRow]) -> DemSection {
    let study: Vec<&DemRow> = dem.iter().filter(|d| d.protocol == "study").collect();
    let checks = study
        .iter()
        .map(|s| {
            let short = dem.iter().find(|d| {
                d.protocol == "design"
                    && d.pattern == s.pattern
                    && d.theta_deg == s.theta_deg
                    && d.alpha_deg == s.alpha_deg
                    && d.load_mN == s.load_mN
            });
            let mus = (short.and_then(|d| d.mu_dem), s.mu_dem);
            let (short_verdict, study_verdict) = (
                verdict_word(short.and_then(|d| d.superlubric_dem)),
                verdict_word(s.superlubric_dem),
            );
            StudyCheck {
                what: which_design(o, s),
                pattern: s.pattern.clone(),
                theta_deg: format!("{}", s.theta_deg),
                alpha_deg: format!("{}", s.alpha_deg),
                load_mn: format!("{}", s.load_mN),
                measured: matches!(mus, (Some(_), Some(_))),
                mu_short: mus.0.map_or(String::new(), |a| fmt_g(a, 4)),
                mu_study: mus.1.map_or(String::new(), |b| fmt_g(b, 4)),
                difference_pct: match mus {
                    (Some(a), Some(b)) => format!("{:+.1}", 100.0 * (a / b - 1.0)),
                    _ => String::new(),
                },
                same: short_verdict == study_verdict,
                short_verdict: short_verdict.into(),
                study_verdict: study_verdict.into(),
                error: s.error.clone(),
            }
        })
        .collect();
    DemSection {
        protocol: protocol_words(p),
        study_protocol: p.dem_is_study_protocol,
        model: p.dem_words.clone(),
        checks,
        unmeasured: study.is_empty() && !p.dem_is_study_protocol,
        rows: dem.iter().map(|d| dem_line(d, angle_decimals(p))).collect(),
        agree: dem
            .iter()
            .filter(|d| d.verdicts_agree == Some(true))
            .count(),
        judged: dem.iter().filter(|d| d.verdicts_agree.is_some()).count(),
        path_um: format!("{}", label(m_to_um(p.friction.length))),
        slid_um: format!(
            "{}",
            label(m_to_um(p.friction.speed * p.friction.slide_time))
        ),
        resonance_drop: format!("{}", surrogate::friction::RESONANCE_DROP_MAX),
    }
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
        axis(p.theta_tol_deg, &bx.theta_offsets_deg),
        axis(p.direction_tol_deg, &bx.direction_offsets_deg)
    );
    if !p.seeds.is_empty() {
        m.push_str(&format!(
            " × the substrate seeds {} besides the scene's own",
            p.seeds
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

impl ReportData {
    /// The report's data from the outcome `o` of the design with parameters `p`.
    /// Cost: a pass over the ranking, the DEM runs and the evaluated θ.
    pub fn new(o: &DesignOutcome, p: &DesignParams) -> Self {
        // the patterns side by side, once (a slider site list per pattern)
        let pats = (o.patterns.len() > 1).then(|| super::patterns::pattern_rows(o));
        let dem = dem_rows(o, p);
        let has_dem = o.dem_ran && !dem.is_empty();
        let ranking = o
            .patterns
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
                        reason: c.reason.clone(),
                    })
            })
            .collect();
        let resonance = o
            .patterns
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
            .collect();
        let screens = o
            .patterns
            .iter()
            .map(|pr| ScreenLine {
                pattern: pr.scene.name.clone(),
                symmetry: {
                    let mut t = match crate::study::design::theta_note(&pr.sym, &pr.thetas_deg, p) {
                        None => pr.sym.describe(),
                        Some(n) if n.uncovered => format!("{}; **{}**", pr.sym.describe(), n.text),
                        Some(n) => format!("{}; {}", pr.sym.describe(), n.text),
                    };
                    if let Some(n) = crate::study::design::line_note(&pr.scene, p) {
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
                stop: pr.stop.clone(),
            })
            .collect();
        let walls = o
            .patterns
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
            .collect();
        let dem_wall = has_dem.then(|| {
            let sum: f64 = dem.iter().filter_map(|d| d.wall_s).sum();
            DemWall {
                runs: dem.len(),
                jobs: p.jobs,
                sum_s: fmt_g(sum, 3),
                elapsed_s: fmt_g(sum / p.jobs.min(dem.len()).max(1) as f64, 3),
            }
        });
        let reproduce = o
            .patterns
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
            .collect();
        let slides = dem
            .iter()
            .zip(&o.dem)
            .filter_map(|(d, e)| {
                let pr = o.patterns.iter().find(|pr| pr.scene.name == d.pattern)?;
                Some(slide_command(pr, d, e.study_protocol, p))
            })
            .collect();
        ReportData {
            patterns: o
                .patterns
                .iter()
                .map(|pr| pr.scene.name.as_str())
                .collect::<Vec<_>>()
                .join(", "),
            loads_mn: loads_text(p),
            mu_superlubric: format!("{}", p.mu_superlubric),
            top: super::top::top_rows(o, p, &dem),
            answers: o
                .patterns
                .iter()
                .zip(&o.answers)
                .map(|(pr, a)| super::top::paragraph(pr, a, p))
                .collect(),
            runs: super::top::answer_runs(o, p),
            tolerance: if tolerance_box(p).is_point() {
                String::new()
            } else {
                format!(
                    "θ ±{}° × pull direction ±{}°",
                    p.theta_tol_deg, p.direction_tol_deg
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
            recipes: pats.as_ref().and_then(|rows| super::recipes::section(rows)),
            compared: pats
                .as_ref()
                .map_or(Vec::new(), |rows| rows.iter().map(Into::into).collect()),
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
