//! The design's final outputs: `report.md` (the answer first), the CSVs behind it, the PNGs —
//! each with its sidecar, each rewritten only when its bytes change.
//!
//! | file | content |
//! |---|---|
//! | `report.md` | the answer per pattern, how sure (DEM vs estimate), ranking, shortlist, wall times, reproduction commands |
//! | `ranking.csv` | [`RankingRow`] per candidate, best first within each pattern |
//! | `shortlist_<p>.csv` | [`ShortlistRow`] per screened θ: coating-intact load, P_max and contacts there, level, kept, evaluated |
//! | `screen_<p>.csv` | the screen (the `screen` schema; a stage file) |
//! | `corrugation_<p>.csv` | the α scans of the evaluated θ (the `corrugation` schema) |
//! | `friction_<p>.csv` | the friction estimates of every candidate (the `friction` schema) |
//! | `dem.csv` | [`DemRow`] per DEM run: μ_DEM next to μ_est |
//! | `pmax_<p>.png`, `corrugation_<p>.png`, `mu_<p>.png` | P_max vs θ per load with P_crit; corrugation vs α of the finalists; μ vs load, surrogate lines and DEM markers |

use super::answer::{Answer, Check};
use super::rank::{Candidate, RankingRow};
use super::{DesignOutcome, DesignParams, PatternResult};
use crate::plot::design::{chart_png, Chart, Colour, Curve, Style};
use crate::study::friction::resonance_note;
use crate::study::meta::Inputs;
use crate::study::progress::Progress;
use crate::study::rows::{label, CorrugationRow, FrictionRow};
use crate::study::sink::csv_bytes;
use crate::study::Outputs;
use anyhow::Result;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use surrogate::units::{m_to_um, n_to_mn, pa_to_gpa, rad_to_deg, s_to_us};

use super::store::Store;

/// One screened orientation of `shortlist_<p>.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ShortlistRow {
    /// θ (degrees).
    pub theta_deg: f64,
    /// Highest load up to which the coating is intact at every load (mN; 0: none).
    pub coating_intact_to_mN: f64,
    /// P_max there (GPa; at the lowest load when none).
    pub p_max_GPa: f64,
    /// Contacts there.
    pub contacts: usize,
    /// Kept on the shortlist of its level.
    pub shortlisted: bool,
    /// Evaluated (α scan and friction estimate).
    pub evaluated: bool,
}

/// One DEM run of `dem.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct DemRow {
    /// Pattern.
    pub pattern: String,
    /// Rank of the design in its pattern.
    pub rank: usize,
    /// θ (degrees).
    pub theta_deg: f64,
    /// α (degrees from the contact line).
    pub alpha_deg: f64,
    /// θ offset (degrees) from the design of its rank for a tolerance-corner run (0: the
    /// design itself).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees, substrate frame) for a tolerance-corner run.
    pub direction_offset_deg: f64,
    /// Load (mN).
    pub load_mN: f64,
    /// `design` (the design's confirmation protocol) or `study` (10 + 10 + 300 µs).
    pub protocol: String,
    /// `ok`, `locked-in` or `failed`.
    pub status: String,
    /// Friction coefficient of the DEM run.
    pub mu_dem: Option<f64>,
    /// The surrogate estimate at the same (θ, α, W).
    pub mu_est: Option<f64>,
    /// μ_est / μ_DEM.
    pub ratio_est_dem: Option<f64>,
    /// DEM verdict: μ_DEM < the superlubric limit, no contact above P_crit, not locked in.
    pub superlubric_dem: Option<bool>,
    /// Surrogate verdict at this load (coating intact on the path, μ_est < the limit).
    pub superlubric_est: Option<bool>,
    /// Both verdicts agree.
    pub verdicts_agree: Option<bool>,
    /// Mean spring force (mN).
    pub friction_mN: Option<f64>,
    /// Its standard deviation (mN).
    pub friction_std_mN: Option<f64>,
    /// Mean contacts over the window.
    pub mean_contacts: Option<f64>,
    /// Largest P_max over the window (GPa).
    pub max_p_max_GPa: Option<f64>,
    /// Slider advance / support advance.
    pub advance_ratio: Option<f64>,
    /// Wall time of the run (s).
    pub wall_s: Option<f64>,
    /// Run directory (relative to the design's directory).
    pub run_dir: String,
    /// Why the run failed.
    pub error: String,
}

/// `v` with `digits` significant digits (plain notation from 1e-3 to 1e4).
fn fmt_g(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if (1e-3..1e4).contains(&a) {
        let mag = a.log10().floor() as i32;
        let d = (digits as i32 - 1 - mag).max(0) as usize;
        format!("{v:.d$}")
    } else {
        format!("{v:.2e}")
    }
}

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or("–".into(), |x| fmt_g(x, digits))
}

/// The friction row of a candidate at load `w_mn`.
fn row_at(c: &Candidate, w_mn: f64) -> Option<&FrictionRow> {
    c.friction.iter().find(|r| (r.load_mN - w_mn).abs() < 1e-12)
}

/// The DEM rows of the outcome.
pub fn dem_rows(o: &DesignOutcome, p: &DesignParams) -> Vec<DemRow> {
    o.dem
        .iter()
        .map(|e| {
            let pr = o.patterns.iter().find(|pr| pr.scene.name == e.pattern);
            let w = label(n_to_mn(e.load));
            let cand = pr.and_then(|pr| {
                pr.ranking
                    .iter()
                    .find(|c| c.theta_deg == e.theta_deg && c.alpha_deg == e.alpha_deg)
            });
            let fr = cand.and_then(|c| row_at(c, w));
            let p_crit = pr.map_or(4e9, |pr| pr.scene.scene.coating.p_crit);
            let r = e.outcome.result.as_ref();
            let mu_est = fr.and_then(|f| f.mu_est);
            let sl_dem = r.map(|r| {
                r.mu < p.mu_superlubric && r.max_p_max_GPa <= pa_to_gpa(p_crit) && !r.locked_in
            });
            let sl_est = fr.map(|f| super::rank::superlubric(f, p_crit, p.mu_superlubric));
            DemRow {
                pattern: e.pattern.clone(),
                rank: e.rank,
                theta_deg: e.theta_deg,
                alpha_deg: e.alpha_deg,
                theta_offset_deg: e.theta_offset_deg,
                direction_offset_deg: e.direction_offset_deg,
                load_mN: w,
                protocol: if e.study_protocol { "study" } else { "design" }.into(),
                status: match (r, &e.outcome.error) {
                    (Some(r), _) if r.locked_in => "locked-in".into(),
                    (Some(_), _) => "ok".into(),
                    _ => "failed".into(),
                },
                mu_dem: r.map(|r| r.mu),
                mu_est,
                ratio_est_dem: match (mu_est, r) {
                    (Some(m), Some(r)) if r.mu != 0.0 => Some(m / r.mu),
                    _ => None,
                },
                superlubric_dem: sl_dem,
                superlubric_est: sl_est,
                verdicts_agree: match (sl_dem, sl_est) {
                    (Some(a), Some(b)) => Some(a == b),
                    _ => None,
                },
                friction_mN: r.map(|r| r.friction_mN),
                friction_std_mN: r.map(|r| r.friction_std_mN),
                mean_contacts: r.map(|r| r.mean_contacts),
                max_p_max_GPa: r.map(|r| r.max_p_max_GPa),
                advance_ratio: r.and_then(|r| r.advance_ratio),
                wall_s: r.map(|r| r.wall_s),
                run_dir: format!("dem/{}", e.outcome.name),
                error: e.outcome.error.clone().unwrap_or_default(),
            }
        })
        .collect()
}

/// `--pattern P …` or `--scene F …` of a pattern, as one string.
fn flags(pr: &PatternResult) -> String {
    pr.scene.flags.join(" ")
}

/// A θ list as the shortest exact `--theta` text: a range `a:b:s` if it parses back to the
/// same values, else the list.
fn theta_text(v: &[f64]) -> String {
    let list = v
        .iter()
        .map(|t| format!("{t}"))
        .collect::<Vec<_>>()
        .join(",");
    if v.len() >= 3 {
        let step = label(v[1] - v[0]);
        let range = format!("{}:{}:{}", v[0], v[v.len() - 1], step);
        if crate::study::range::parse_list_or_range(&range, "--theta").is_ok_and(|r| r == v) {
            return range;
        }
    }
    list
}

fn loads_text(p: &DesignParams) -> String {
    p.loads
        .iter()
        .map(|&w| format!("{}", label(n_to_mn(w))))
        .collect::<Vec<_>>()
        .join(",")
}

/// The DEM protocol flags of the design's runs (or the study's).
fn protocol_flags(p: &DesignParams, study: bool) -> String {
    let s = &p.dem.sim;
    let mut f = String::new();
    if !study {
        let _ = write!(
            f,
            " --equilibrate-us {} --relax-us {} --slide-us {} --speed-m-s {}",
            label(s_to_us(s.equilibrate_time)),
            label(s_to_us(s.relax_time)),
            label(s_to_us(s.slide_time)),
            s.support_speed
        );
    }
    if let Some(dt) = s.dt {
        let _ = write!(f, " --dt-us {}", label(s_to_us(dt)));
    }
    f += &p.dem_flags;
    f
}

/// The protocol in words (`equilibrate 2 + relax 2 + slide 60 µs at 0.1 m/s`).
pub fn protocol_words(p: &DesignParams) -> String {
    let s = &p.dem.sim;
    format!(
        "equilibrate {} + relax {} + slide {} µs at {} m/s, friction over the last two thirds of the slide",
        label(s_to_us(s.equilibrate_time)),
        label(s_to_us(s.relax_time)),
        label(s_to_us(s.slide_time)),
        s.support_speed
    )
}

/// The answer of one pattern as a Markdown list item (also the final log line).
pub fn answer_line(
    pr: &PatternResult,
    a: &Answer,
    dem: &[DemRow],
    p: &DesignParams,
    w_top: f64,
) -> String {
    let name = &pr.scene.name;
    let pc = pa_to_gpa(pr.scene.scene.coating.p_crit);
    let mut m = String::new();
    let Some(b) = a.index.and_then(|i| pr.ranking.get(i)) else {
        return format!(
            "- **{name}**: no design — no orientation keeps the coating intact (P_max ≤ {pc} GPa) even at the lowest load."
        );
    };
    if b.score.superlubric_to_mn == 0.0 {
        let _ = write!(
            m,
            "- **{name}**: no design is superlubric even at the lowest load; the best candidate, θ = {}°, α = {}°, has μ_est = {} there (coating intact on its path up to {} mN).",
            b.theta_deg,
            b.alpha_deg,
            fmt_g(b.score.mu_worst, 3),
            b.score.intact_to_mn
        );
    } else {
        let fr = row_at(b, b.score.superlubric_to_mn);
        let _ = write!(
            m,
            "- **{name}**: θ = **{}°**, α = **{}°** from the contact line (pull at {}° from the substrate x axis; contact line at {}°) stays superlubric up to **{} mN**{}: μ_est ≤ {}, P_max ≤ {} GPa on the path at {} mN (P_crit = {pc} GPa), {} contacts on average; rank {} of the estimate.",
            b.theta_deg,
            b.alpha_deg,
            fmt_g(b.direction_deg, 4),
            fmt_g(b.line_deg, 4),
            b.score.superlubric_to_mn,
            if b.score.superlubric_to_mn == w_top {
                " (the highest load asked)"
            } else {
                ""
            },
            fmt_g(b.score.mu_worst, 3),
            opt(fr.and_then(|f| f.p_max_GPa), 3),
            b.score.superlubric_to_mn,
            fmt_g(b.score.contacts, 3),
            a.index.unwrap_or(0) + 1
        );
    }
    m.push_str(&tolerance_words(pr, b, p));
    let runs: Vec<String> = dem
        .iter()
        .filter(|d| {
            d.pattern == *name
                && d.theta_deg == b.theta_deg
                && d.alpha_deg == b.alpha_deg
                && d.protocol == "design"
        })
        .map(|d| match d.mu_dem {
            Some(mu) => format!(
                "{} mN: μ_DEM = {}{}",
                d.load_mN,
                fmt_g(mu, 3),
                match d.superlubric_dem {
                    Some(true) => " (superlubric)",
                    _ => " (not superlubric)",
                }
            ),
            None => format!("{} mN: failed", d.load_mN),
        })
        .collect();
    match &a.check {
        Check::NoDem => {
            let _ = write!(m, " Not checked with the DEM (`--no-dem`).");
        }
        Check::Confirmed(loads) => {
            let _ = write!(
                m,
                " **Confirmed by the DEM** at {} mN ({}).",
                loads
                    .iter()
                    .map(|w| format!("{w}"))
                    .collect::<Vec<_>>()
                    .join(", "),
                runs.join("; ")
            );
        }
        Check::Contradicted(why) => {
            let _ = write!(
                m,
                " **Not confirmed**: no DEM-checked design of the top {} is; this one's DEM run says {why} ({}).",
                p.confirm,
                runs.join("; ")
            );
        }
        Check::Unchecked => {
            let _ = write!(
                m,
                " Not checkable with the DEM at the confirmation loads ({}).",
                if runs.is_empty() {
                    "none up to its superlubric load".to_string()
                } else {
                    runs.join("; ")
                }
            );
        }
    }
    let corners: Vec<&DemRow> = dem
        .iter()
        .filter(|d| {
            d.pattern == *name
                && a.index == Some(0)
                && (d.theta_offset_deg != 0.0 || d.direction_offset_deg != 0.0)
        })
        .collect();
    if !corners.is_empty() {
        let at = |w: f64| {
            let c: Vec<&&DemRow> = corners.iter().filter(|d| d.load_mN == w).collect();
            let ok = c.iter().filter(|d| d.superlubric_dem == Some(true)).count();
            format!("{ok} of {} superlubric at {w} mN", c.len())
        };
        let mut loads: Vec<f64> = corners.iter().map(|d| d.load_mN).collect();
        loads.dedup();
        let _ = write!(
            m,
            " DEM at the corners of the tolerance box: {}.",
            loads.iter().map(|&w| at(w)).collect::<Vec<_>>().join("; ")
        );
    }
    for (rank, c) in &a.others {
        if let (Some(d), Check::Contradicted(why)) = (pr.ranking.get(rank - 1), c) {
            let _ = write!(
                m,
                " The estimate's rank {rank} (θ = {}°, α = {}°, superlubric to {} mN by the estimate) is contradicted by the DEM: {why}.",
                d.theta_deg, d.alpha_deg, d.score.superlubric_to_mn
            );
        }
    }
    m
}

/// The tolerance sentences of the answer `b`: the robust limit over the box and the window at
/// the nominal limit, the verdict where borderline, and the nominal optimum where it differs.
fn tolerance_words(pr: &PatternResult, b: &Candidate, p: &DesignParams) -> String {
    let within = |w: Option<f64>, step: f64| match w {
        Some(w) if w > 0.0 => format!("±{w}°"),
        Some(_) => format!("less than ±{step}° (the first sample)"),
        None => "(window not computed)".to_string(),
    };
    let mut m = String::new();
    let sc = &b.score;
    if p.theta_tol_deg > 0.0 || p.direction_tol_deg > 0.0 {
        let _ = write!(
            m,
            " Over the fabrication tolerance θ ±{}° × pull direction ±{}° (the pull direction stays fixed in the substrate frame when the slider is misaligned) it holds to **{} mN**",
            p.theta_tol_deg, p.direction_tol_deg, sc.superlubric_to_mn
        );
        if sc.nominal_to_mn > sc.superlubric_to_mn {
            let _ = write!(
                m,
                "; its nominal {} mN holds only within θ {}, direction {}.",
                sc.nominal_to_mn,
                within(
                    sc.theta_window_deg,
                    p.theta_tol_step_deg.min(p.theta_tol_deg)
                ),
                within(
                    sc.direction_window_deg,
                    p.direction_tol_step_deg.min(p.direction_tol_deg)
                )
            );
        } else {
            m.push('.');
        }
    }
    if sc.superlubric_to_mn > 0.0 && sc.verdict != crate::study::verdict::Verdict::Superlubric {
        let _ = write!(
            m,
            " **Borderline** at {} mN: within the estimate's measured uncertainty of a threshold ({}).",
            sc.superlubric_to_mn,
            crate::study::verdict::band_words(p.mu_superlubric, pr.scene.scene.coating.p_crit)
        );
    }
    if let Some(n) = pr
        .ranking
        .iter()
        .filter(|c| c.score.nominal_to_mn > sc.superlubric_to_mn)
        .fold(None::<&Candidate>, |best, c| match best {
            Some(b) if b.score.nominal_to_mn >= c.score.nominal_to_mn => Some(b),
            _ => Some(c),
        })
    {
        let _ = write!(
            m,
            " The nominal optimum differs: θ = {}°, α = {}° reaches {} mN only within θ {} (direction {}), {}{} mN over the tolerance.",
            n.theta_deg,
            n.alpha_deg,
            n.score.nominal_to_mn,
            within(n.score.theta_window_deg, p.theta_tol_step_deg.min(p.theta_tol_deg)),
            within(
                n.score.direction_window_deg,
                p.direction_tol_step_deg.min(p.direction_tol_deg)
            ),
            if n.score.exact { "" } else { "≤ " },
            n.score.superlubric_to_mn
        );
    }
    m
}

/// What the study-protocol run `s` is run on, in words: the recommended design (a pattern's
/// answer, confirmed by the DEM or not) or another design.
fn which_design(o: &DesignOutcome, s: &DemRow) -> String {
    let found = o.patterns.iter().zip(&o.answers).find_map(|(pr, a)| {
        let c = pr.ranking.get(a.index?)?;
        (pr.scene.name == s.pattern && c.theta_deg == s.theta_deg && c.alpha_deg == s.alpha_deg)
            .then_some(a)
    });
    match found.map(|a| &a.check) {
        Some(Check::Confirmed(_)) => format!(
            "the recommended design ({}'s answer, confirmed by the DEM)",
            s.pattern
        ),
        Some(_) => format!(
            "the recommended design ({}'s answer; not confirmed by the DEM)",
            s.pattern
        ),
        None => "a design that is not the report's answer".to_string(),
    }
}

/// The whole `report.md`.
pub fn markdown(o: &DesignOutcome, p: &DesignParams) -> String {
    let mut m = String::new();
    let names: Vec<&str> = o.patterns.iter().map(|pr| pr.scene.name.as_str()).collect();
    let w_top = label(n_to_mn(*p.loads.last().unwrap_or(&0.0)));
    let dem = dem_rows(o, p);
    let _ = writeln!(m, "# superlube design: {}\n", names.join(", "));
    let _ = writeln!(
        m,
        "Loads {} mN; superlubric = coating intact on the whole sliding path (P_max ≤ P_crit) and μ_est < {} at every load up to the one named.\n",
        loads_text(p),
        p.mu_superlubric
    );
    // 1. The answer
    let _ = writeln!(m, "## Answer\n");
    for (pr, a) in o.patterns.iter().zip(&o.answers) {
        let _ = writeln!(m, "{}", answer_line(pr, a, &dem, p, w_top));
    }
    // 2. How sure
    for (pr, tm) in o.patterns.iter().zip(&o.maps) {
        if tm.is_some() {
            let _ = writeln!(
                m,
                "\n![{0}: superlubric limit over θ × pull direction around the answer, tolerance box drawn](tolerance_{0}.png)",
                pr.scene.name
            );
        }
    }
    let _ = writeln!(m, "\n## How sure: surrogate estimate against the DEM\n");
    if !o.dem_ran {
        let _ = writeln!(
            m,
            "Not confirmed with the DEM (`--no-dem`). Run the same command without `--no-dem` and the same `--out` to add the DEM confirmation (the surrogate stages are reused).\n"
        );
    } else if dem.is_empty() {
        let _ = writeln!(m, "No design to confirm.\n");
    } else {
        let _ = writeln!(
            m,
            "Confirmation protocol: {}{} (model and reductions: {}). The study's protocol is equilibrate 10 + relax 10 + slide 300 µs at 0.1 m/s (friction over 100–300 µs).\n",
            protocol_words(p),
            if p.dem_is_study_protocol {
                " — the study's protocol"
            } else {
                " — **shorter than the study's**"
            },
            p.dem_words
        );
        let study: Vec<&DemRow> = dem.iter().filter(|d| d.protocol == "study").collect();
        for s in &study {
            let short = dem.iter().find(|d| {
                d.protocol == "design"
                    && d.pattern == s.pattern
                    && d.theta_deg == s.theta_deg
                    && d.alpha_deg == s.alpha_deg
                    && d.load_mN == s.load_mN
            });
            let what = which_design(o, s);
            match (short.and_then(|d| d.mu_dem), s.mu_dem) {
                (Some(a), Some(b)) => {
                    let word = |v: Option<bool>| match v {
                        Some(true) => "superlubric",
                        Some(false) => "not superlubric",
                        None => "no verdict",
                    };
                    let (x, y) = (
                        word(short.and_then(|d| d.superlubric_dem)),
                        word(s.superlubric_dem),
                    );
                    let verdicts = if x == y {
                        format!("same DEM verdict ({y})")
                    } else {
                        format!("**the DEM verdicts differ**: {x} (short) vs {y} (study protocol)")
                    };
                    let _ = writeln!(
                        m,
                        "Measured difference of the shorter protocol on {what}, {} θ = {}°, α = {}°, {} mN: μ = {} (short) vs {} (study protocol): {:+.1} %; {verdicts}.\n",
                        s.pattern,
                        s.theta_deg,
                        s.alpha_deg,
                        s.load_mN,
                        fmt_g(a, 4),
                        fmt_g(b, 4),
                        100.0 * (a / b - 1.0)
                    );
                }
                _ => {
                    let _ = writeln!(
                        m,
                        "The study-protocol check on {} θ = {}°, α = {}°, {} mN did not complete: {}\n",
                        s.pattern, s.theta_deg, s.alpha_deg, s.load_mN, s.error
                    );
                }
            }
        }
        if study.is_empty() && !p.dem_is_study_protocol {
            let _ = writeln!(
                m,
                "The shorter protocol's difference from the study's was not measured in this run (`--no-protocol-check`).\n"
            );
        }
        let _ = writeln!(
            m,
            "| pattern | rank | θ (°) | α (°) | tolerance corner δθ, δdir (°) | W (mN) | protocol | μ_est | μ_DEM | μ_est/μ_DEM | verdict est / DEM | max P_max DEM, any step (GPa) | contacts DEM | status | wall (s) |"
        );
        let _ = writeln!(
            m,
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
        );
        let verdict = |v: Option<bool>| match v {
            Some(true) => "superlubric",
            Some(false) => "not",
            None => "–",
        };
        for d in &dem {
            let _ = writeln!(
                m,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} / {} | {} | {} | {}{} | {} |",
                d.pattern,
                d.rank,
                d.theta_deg,
                d.alpha_deg,
                if d.theta_offset_deg == 0.0 && d.direction_offset_deg == 0.0 {
                    "–".to_string()
                } else {
                    format!("{:+}, {:+}", d.theta_offset_deg, d.direction_offset_deg)
                },
                d.load_mN,
                d.protocol,
                opt(d.mu_est, 3),
                opt(d.mu_dem, 3),
                opt(d.ratio_est_dem, 3),
                verdict(d.superlubric_est),
                verdict(d.superlubric_dem),
                opt(d.max_p_max_GPa, 3),
                opt(d.mean_contacts, 3),
                d.status,
                if d.error.is_empty() {
                    String::new()
                } else {
                    format!(": {}", d.error.replace('|', "/"))
                },
                opt(d.wall_s, 3)
            );
        }
        let agree = dem
            .iter()
            .filter(|d| d.verdicts_agree == Some(true))
            .count();
        let judged = dem.iter().filter(|d| d.verdicts_agree.is_some()).count();
        let (path, slid) = (
            label(m_to_um(p.friction.length)),
            label(m_to_um(p.friction.speed * p.friction.slide_time)),
        );
        let _ = writeln!(
            m,
            "\nVerdicts agree on {agree} of {judged} runs with a result. Known limits of the estimate (README, \"superlube friction\"): rigid slider on the static path (the slider's centre of mass moves along it with the DEM's mass and damping, but neither vertically nor in tilt: where contacts fail and the springs mount's tilt mode is tuned to the stuck contact pairs' lateral mode, column `mount_resonance` of `friction_<p>.csv`, μ_est may be an upper bound: up to 2.8× μ_DEM measured, 0.96–1.46× off the resonance), no lock-in; its P_max is the static path's, while on a path that sticks and slips (η > 1) the DEM's slider rings vertically in the fast slips and its P_max at some step is higher (+0.02 to +0.78 GPa on six such runs with μ_DEM < 0.02; README, \"Pressure peaks between samples\"); a quasi-periodic path covers {path} µm where the study's DEM slides {slid} µm, so a failing region further along can be missed (README, \"Path length, a known limit\").\n"
        );
    }
    // 3. Ranking
    let _ = writeln!(m, "## Ranking\n");
    let _ = writeln!(
        m,
        "Score: (1) highest load up to which superlubric, (2) then the largest μ_est up to it (lower is better), (3) then the path-averaged contact number there (more is better). All candidates in `ranking.csv`; the best 10 per pattern:\n"
    );
    let _ = writeln!(
        m,
        "| pattern | rank | θ (°) | α (°) | pull (° from x) | superlubric to (mN) | μ_est worst | contacts | coating intact on path to (mN) | screen intact to (mN) | corrugation (nm) | shortlisted as |"
    );
    let _ = writeln!(m, "|---|---|---|---|---|---|---|---|---|---|---|---|");
    for pr in &o.patterns {
        for (k, c) in pr.ranking.iter().take(10).enumerate() {
            let _ = writeln!(
                m,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                c.pattern,
                k + 1,
                c.theta_deg,
                c.alpha_deg,
                fmt_g(c.direction_deg, 4),
                c.score.superlubric_to_mn,
                fmt_g(c.score.mu_worst, 3),
                fmt_g(c.score.contacts, 3),
                c.score.intact_to_mn,
                c.screen_intact_to_mn,
                fmt_g(c.corrugation_nm, 3),
                c.reason
            );
        }
    }
    for pr in &o.patterns {
        let flagged = pr
            .ranking
            .iter()
            .filter(|c| c.friction.iter().any(|r| r.mount_resonance == Some(true)))
            .count();
        if let (Some(note), true) = (resonance_note(&pr.scene.scene, &p.friction), flagged > 0) {
            let _ = writeln!(
                m,
                "\n{}: {flagged} of {} candidates have loads with failed contacts on a mount in resonance; {note}. Their verdicts stand (μ_est may be an upper bound there).",
                pr.scene.name,
                pr.ranking.len()
            );
        }
    }
    // 4. Screen and shortlist
    let _ = writeln!(m, "\n## Screen and shortlist\n");
    for pr in &o.patterns {
        let _ = writeln!(
            m,
            "**{}**: {}. Screened {} θ ({}{}) × {} loads. Shortlist levels (coating intact up to W_c at the screened placement): {}. {}.\n",
            pr.scene.name,
            pr.sym.describe(),
            pr.thetas_deg.len(),
            pr.thetas_deg.first().map_or(String::new(), |t| format!("{t}°")),
            pr.thetas_deg.last().map_or(String::new(), |t| format!(" … {t}°")),
            p.loads.len(),
            if pr.levels.is_empty() {
                "none".to_string()
            } else {
                pr.levels
                    .iter()
                    .enumerate()
                    .map(|(k, l)| {
                        format!(
                            "{} mN: {} θ ({} kept{})",
                            label(n_to_mn(l.load)),
                            l.size,
                            l.picks.len(),
                            if k < pr.levels_evaluated {
                                ", evaluated"
                            } else {
                                ""
                            }
                        )
                    })
                    .collect::<Vec<_>>()
                    .join("; ")
            },
            pr.stop
        );
    }
    // 5. Wall time
    let _ = writeln!(m, "## Wall time per tier\n");
    let _ = writeln!(
        m,
        "As measured when each stage was computed (a reused stage keeps its original time).\n"
    );
    let _ = writeln!(m, "| tier | pattern | what | wall (s) |");
    let _ = writeln!(m, "|---|---|---|---|");
    for pr in &o.patterns {
        let _ = writeln!(
            m,
            "| 1. screen | {} | {} θ × {} loads | {} |",
            pr.scene.name,
            pr.thetas_deg.len(),
            p.loads.len(),
            opt(pr.screen_wall_s, 3)
        );
        let w: f64 = pr.evaluated.iter().map(|e| e.wall_s).sum();
        let paths: usize = pr.evaluated.iter().map(|e| e.eval.scan.len()).sum();
        let _ = writeln!(
            m,
            "| 2. α scan + friction estimate | {} | {} θ: {} scan paths, {} friction paths, {} (θ, α, W) estimates | Σ {} over θ (evaluated side by side) |",
            pr.scene.name,
            pr.evaluated.len(),
            paths,
            pr.evaluated.iter().map(|e| e.eval.alphas_deg.len()).sum::<usize>(),
            pr.evaluated.iter().map(|e| e.eval.friction.len()).sum::<usize>(),
            fmt_g(w, 3)
        );
    }
    if o.dem_ran && !dem.is_empty() {
        let sum: f64 = dem.iter().filter_map(|d| d.wall_s).sum();
        let _ = writeln!(
            m,
            "| 3. DEM confirmation | all | {} runs, {} side by side (one thread each) | Σ {} (≈ {} elapsed) |",
            dem.len(),
            p.jobs,
            fmt_g(sum, 3),
            fmt_g(sum / p.jobs.min(dem.len()).max(1) as f64, 3)
        );
    }
    // 6. Reproduce
    let _ = writeln!(m, "\n## Reproduce any row\n");
    let _ = writeln!(m, "```sh");
    for pr in &o.patterns {
        let f = flags(pr);
        let _ = writeln!(
            m,
            "# {}: the screen (= screen_{}.csv, same input_hash)\nsuperlube screen {f} --theta {} --load-mn {} --out screen_{}.csv",
            pr.scene.name,
            pr.scene.name,
            theta_text(&pr.thetas_deg),
            loads_text(p),
            pr.scene.name
        );
        let line = p
            .line
            .map_or(String::new(), |l| format!(" --line-deg {}", rad_to_deg(l)));
        for e in &pr.evaluated {
            let alphas: Vec<String> = e
                .eval
                .scan
                .iter()
                .map(|r| format!("{}", r.alpha_deg))
                .collect();
            let _ = writeln!(
                m,
                "# θ = {}°: α scan (corrugation_{}.csv rows) and the friction estimate of its best α\nsuperlube corrugation {f} --theta {} --load-mn {} --alpha {} --distance-um {} --step-um {}{line}\nsuperlube friction {f} --theta {} --alpha {} --load-mn {}{line} --length-um {} --max-period-um {} --step-um {} --transient-um {} --k0-n-m {} --transverse-um {}",
                e.eval.theta_deg,
                pr.scene.name,
                e.eval.theta_deg,
                e.eval.scan_load_mN,
                alphas.join(","),
                label(m_to_um(p.scan_length)),
                label(m_to_um(p.scan_step)),
                e.eval.theta_deg,
                e.eval
                    .alphas_deg
                    .iter()
                    .map(|a| format!("{a}"))
                    .collect::<Vec<_>>()
                    .join(","),
                loads_text(p),
                label(m_to_um(p.friction.length)),
                label(m_to_um(p.friction.max_period)),
                label(m_to_um(p.friction.step)),
                label(m_to_um(p.friction.transient)),
                p.friction.k0,
                label(m_to_um(p.friction.transverse))
            );
        }
    }
    for (d, e) in dem.iter().zip(&o.dem) {
        let Some(pr) = o.patterns.iter().find(|pr| pr.scene.name == d.pattern) else {
            continue;
        };
        let line = p
            .line
            .map_or(String::new(), |l| format!(" --line-deg {}", rad_to_deg(l)));
        let _ = writeln!(
            m,
            "superlube slide {} --theta {} --alpha {} --load-mn {}{line}{} --json {}/slide.json --out {}/slide.csv",
            flags(pr),
            d.theta_deg,
            d.alpha_deg,
            d.load_mN,
            protocol_flags(p, e.study_protocol),
            d.run_dir,
            d.run_dir
        );
    }
    let _ = writeln!(m, "```\n");
    // 7. Files
    let _ = writeln!(
        m,
        "## Files\n\nEvery file has a sidecar `FILE.meta.json` (inputs, input hash, command line). `ranking.csv` (all candidates), `shortlist_<p>.csv` (every screened θ), `screen_<p>.csv`, `corrugation_<p>.csv` (α scans), `friction_<p>.csv` (estimates of every candidate at every load), `dem.csv` and `dem/<run>/slide.{{json,csv}}` (DEM runs), `pmax_<p>.png`, `corrugation_<p>.png`, `mu_<p>.png`; `design.json` (the inputs), `stages/` (cached stages). Columns and units: README, \"superlube design\"."
    );
    m
}

/// Writes every final output of the design (see the module docs).
pub fn write(
    store: &Store,
    record: &Inputs,
    p: &DesignParams,
    o: &DesignOutcome,
    progress: &dyn Progress,
) -> Result<()> {
    let mut outs = Outputs::new(record.clone(), vec![]);
    let mut wrote = Vec::new();
    // ranking
    let ranking: Vec<RankingRow> = o
        .patterns
        .iter()
        .flat_map(|pr| {
            pr.ranking
                .iter()
                .enumerate()
                .map(|(k, c)| RankingRow::new(k + 1, c, (p.theta_tol_deg, p.direction_tol_deg)))
        })
        .collect();
    if store.write_if_changed(
        &mut outs,
        "ranking.csv",
        csv_bytes(&ranking),
        Some(ranking.len() as u64),
    ) {
        wrote.push("ranking.csv".to_string());
    }
    for pr in &o.patterns {
        let name = &pr.scene.name;
        // shortlist
        let evaluated: Vec<f64> = pr.evaluated.iter().map(|e| e.eval.theta_deg).collect();
        let kept: Vec<f64> = pr
            .levels
            .iter()
            .flat_map(|l| l.picks.iter().map(|o| o.theta_deg))
            .collect();
        let sl: Vec<ShortlistRow> = pr
            .orientations
            .iter()
            .map(|or| ShortlistRow {
                theta_deg: or.theta_deg,
                coating_intact_to_mN: label(n_to_mn(or.w_intact)),
                p_max_GPa: pa_to_gpa(or.p_max),
                contacts: or.contacts,
                shortlisted: kept.contains(&or.theta_deg),
                evaluated: evaluated.contains(&or.theta_deg),
            })
            .collect();
        let rel = format!("shortlist_{name}.csv");
        if store.write_if_changed(&mut outs, &rel, csv_bytes(&sl), Some(sl.len() as u64)) {
            wrote.push(rel);
        }
        // corrugation scans
        let scans: Vec<CorrugationRow> = pr
            .evaluated
            .iter()
            .flat_map(|e| e.eval.scan.iter().cloned())
            .collect();
        let rel = format!("corrugation_{name}.csv");
        let scans_changed =
            store.write_if_changed(&mut outs, &rel, csv_bytes(&scans), Some(scans.len() as u64));
        if scans_changed {
            wrote.push(rel);
        }
        // friction
        let fr: Vec<FrictionRow> = pr
            .ranking
            .iter()
            .flat_map(|c| c.friction.iter().cloned())
            .collect();
        let rel = format!("friction_{name}.csv");
        if store.write_if_changed(&mut outs, &rel, csv_bytes(&fr), Some(fr.len() as u64)) {
            wrote.push(rel);
        }
        // PNGs (redrawn when missing or their data changed)
        let png = |rel: &str| store.path(rel);
        let pmax = format!("pmax_{name}.png");
        if !png(&pmax).exists() || wrote.iter().any(|w| w == &format!("shortlist_{name}.csv")) {
            outs.attempt(&pmax, &png(&pmax), || {
                chart_png(&png(&pmax), &pmax_chart(pr, p))
            });
            wrote.push(pmax);
        }
        let corr = format!("corrugation_{name}.png");
        if !png(&corr).exists() || scans_changed {
            outs.attempt(&corr, &png(&corr), || {
                chart_png(&png(&corr), &corrugation_chart(pr))
            });
            wrote.push(corr);
        }
    }
    // DEM
    let dem = dem_rows(o, p);
    let dem_changed = o.dem_ran
        && store.write_if_changed(
            &mut outs,
            "dem.csv",
            csv_bytes(&dem),
            Some(dem.len() as u64),
        );
    if dem_changed {
        wrote.push("dem.csv".into());
    }
    for pr in &o.patterns {
        let rel = format!("mu_{}.png", pr.scene.name);
        let fr_changed = wrote
            .iter()
            .any(|w| w == &format!("friction_{}.csv", pr.scene.name));
        if !store.path(&rel).exists() || fr_changed || dem_changed {
            outs.attempt(&rel, &store.path(&rel), || {
                chart_png(&store.path(&rel), &mu_chart(pr, &dem, p))
            });
            wrote.push(rel);
        }
    }
    // tolerance maps around the answers
    for (pr, m) in o.patterns.iter().zip(&o.maps) {
        let Some(m) = m else { continue };
        let name = &pr.scene.name;
        let rel = format!("tolerance_{name}.csv");
        let changed = store.write_if_changed(
            &mut outs,
            &rel,
            csv_bytes(&m.rows),
            Some(m.rows.len() as u64),
        );
        if changed {
            wrote.push(rel);
        }
        let rel = format!("tolerance_{name}.png");
        if !store.path(&rel).exists() || changed {
            let title = format!(
                "{name}: superlubric limit around the answer θ = {}°, direction {}° (box ±{}° × ±{}°)",
                m.nominal.0,
                fmt_g(m.nominal.1, 4),
                p.theta_tol_deg,
                p.direction_tol_deg
            );
            outs.attempt(&rel, &store.path(&rel), || {
                crate::plot::tolerance::tolerance_png(
                    &store.path(&rel),
                    &title,
                    &m.rows,
                    m.theta_points,
                    m.nominal,
                    (p.theta_tol_deg, p.direction_tol_deg),
                )
            });
            wrote.push(rel);
        }
    }
    let md = markdown(o, p);
    if store.write_if_changed(&mut outs, "report.md", Ok(md.into_bytes()), None) {
        wrote.push("report.md".into());
    }
    outs.finish()?;
    progress.note(&if wrote.is_empty() {
        format!(
            "{}: every output already up to date (nothing rewritten)",
            store.dir().display()
        )
    } else {
        format!("{}: wrote {}", store.dir().display(), wrote.join(", "))
    });
    Ok(())
}

/// P_max versus θ, one curve per load (viridis), P_crit dashed.
fn pmax_chart(pr: &PatternResult, p: &DesignParams) -> Chart {
    let n = p.loads.len();
    let curves = p
        .loads
        .iter()
        .enumerate()
        .map(|(k, &w)| {
            let wm = label(n_to_mn(w));
            Curve {
                name: format!("W = {wm} mN"),
                points: pr
                    .screen
                    .iter()
                    .filter(|r| r.load_mN == wm)
                    .filter_map(|r| r.p_max_GPa.map(|pm| (r.theta_deg, pm)))
                    .collect(),
                colour: Colour::Scale(if n > 1 {
                    k as f64 / (n - 1) as f64
                } else {
                    0.0
                }),
                style: Style::Line,
            }
        })
        .collect();
    Chart {
        title: format!(
            "{}: maximum Hertz pressure versus orientation θ",
            pr.scene.name
        ),
        x_label: "slider rotation θ (°)".into(),
        y_label: "P_max (GPa)".into(),
        curves,
        hlines: vec![(
            pa_to_gpa(pr.scene.scene.coating.p_crit),
            "P_crit (coating fails above)".into(),
        )],
        log_y: false,
    }
}

/// Corrugation versus α of the finalists (the top 5 distinct θ of the ranking).
fn corrugation_chart(pr: &PatternResult) -> Chart {
    let mut thetas: Vec<f64> = Vec::new();
    for c in &pr.ranking {
        if !thetas.contains(&c.theta_deg) {
            thetas.push(c.theta_deg);
        }
        if thetas.len() == 5 {
            break;
        }
    }
    let curves = thetas
        .iter()
        .enumerate()
        .filter_map(|(k, &t)| {
            let e = pr.evaluated.iter().find(|e| e.eval.theta_deg == t)?;
            let mut pts: Vec<(f64, f64)> = e
                .eval
                .scan
                .iter()
                .map(|r| (r.alpha_deg, r.corrugation_nm))
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            Some(Curve {
                name: format!("θ = {t}° (at {} mN)", e.eval.scan_load_mN),
                points: pts,
                colour: Colour::Palette(k),
                style: Style::LinePoints,
            })
        })
        .collect();
    Chart {
        title: format!(
            "{}: corrugation versus pulling angle α (finalists)",
            pr.scene.name
        ),
        x_label: "α from the contact line (°)".into(),
        y_label: "corrugation (nm, log scale)".into(),
        curves,
        hlines: vec![],
        log_y: true,
    }
}

/// μ versus load: the surrogate estimate of the top 5 designs (lines) and the DEM runs
/// (markers), the superlubric limit dashed.
fn mu_chart(pr: &PatternResult, dem: &[DemRow], p: &DesignParams) -> Chart {
    let mut curves = Vec::new();
    for (k, c) in pr.ranking.iter().take(5).enumerate() {
        curves.push(Curve {
            name: format!(
                "#{} θ = {}°, α = {}°: μ_est",
                k + 1,
                c.theta_deg,
                c.alpha_deg
            ),
            points: c
                .friction
                .iter()
                .filter_map(|r| r.mu_est.map(|m| (r.load_mN, m)))
                .collect(),
            colour: Colour::Palette(k),
            style: Style::LinePoints,
        });
        let pts: Vec<(f64, f64)> = dem
            .iter()
            .filter(|d| {
                d.pattern == pr.scene.name
                    && d.rank == k + 1
                    && d.protocol == "design"
                    && d.mu_dem.is_some()
            })
            .map(|d| (d.load_mN, d.mu_dem.unwrap_or(f64::NAN)))
            .collect();
        if !pts.is_empty() {
            curves.push(Curve {
                name: format!("#{} DEM", k + 1),
                points: pts,
                colour: Colour::Palette(k),
                style: Style::Markers,
            });
        }
    }
    Chart {
        title: format!("{}: friction coefficient versus load", pr.scene.name),
        x_label: "normal load W (mN)".into(),
        y_label: "μ (log scale)".into(),
        curves,
        hlines: vec![(
            p.mu_superlubric,
            format!("superlubric limit μ = {}", p.mu_superlubric),
        )],
        log_y: true,
    }
}
