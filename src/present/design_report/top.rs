//! The top of the report: one table row per pattern's answer ([`TopRow`]: what to make, how
//! precisely, up to which load, how sure, what the DEM said), one short paragraph per answer in
//! plain words ([`paragraph`]), and how to run each answer ([`AnswerRun`]: its scene file
//! `answer_<p>.toml` with θ set, and the exact `slide`, `tolerance` and `export-lammps` command
//! lines with its pull direction). The definitions the cells rely on are in the template's
//! "How to read this", once.

use super::commands::{line_flag, loads_text, protocol_flags};
use super::rows::{row_at, DemProtocol, DemRow};
use super::words::{fmt_g, opt};
use crate::study::design::answer::{Answer, Check};
use crate::study::design::rank::Candidate;
use crate::study::design::{DesignOutcome, DesignParams, PatternResult};
use crate::study::load::LoadKey;
use crate::study::rows::label;
use crate::study::verdict::Verdict;
use serde::Serialize;
use std::fmt::Write as _;
use surrogate::scene::SceneFile;
use surrogate::units::{deg_to_rad, m_to_um, n_to_mn, pa_to_gpa, s_to_us};

/// One row of the answer table (cells as printed).
#[derive(Debug, Clone, Serialize)]
pub struct TopRow {
    pub pattern: String,
    /// `θ ± tol` (degrees): the orientation and the fabrication tolerance the robust limit holds
    /// over; θ alone without a tolerance; `–` without a design.
    pub theta: String,
    /// Pull direction from the substrate x axis `d ± tol` (degrees).
    pub pull_x: String,
    /// Pull direction from the slider's contact line α (degrees).
    pub alpha: String,
    /// The robust limit (mN), `≤ x` for an upper bound.
    pub limit_mn: String,
    /// The verdict up to the robust limit (`superlubric`, `borderline`, `not`).
    pub verdict: String,
    /// The DEM at the design itself: `held at 0.35, 1.75 mN`, `failed at 2.1 mN`, …
    pub dem_centre: String,
    /// The DEM at the corners of the tolerance box: `4 of 4 held at 1.75 mN`, …
    pub dem_corners: String,
    /// The nominal optimum where its limit exceeds the robust one, with its own window; else
    /// `the same design`.
    pub nominal: String,
    /// The load at yield q with its bound ([`super::yields::cell`]); empty without the yield
    /// stage.
    pub fab_yield: String,
}

/// How to run one pattern's answer: its scene file and three command lines.
#[derive(Debug, Clone, Serialize)]
pub struct AnswerRun {
    pub pattern: String,
    /// `answer_<p>.toml` (beside the report).
    pub scene_file: String,
    /// `superlube slide …` at the answer's limit load (the design's DEM protocol).
    pub slide: String,
    /// `superlube tolerance …`: the map `tolerance_<p>.csv` over the box.
    pub tolerance: String,
    /// `superlube export-lammps …` at the answer's limit load.
    pub export: String,
}

/// The scene file name of a pattern's answer.
pub fn scene_file_name(pattern: &str) -> String {
    format!("answer_{pattern}.toml")
}

/// The scene of `pr` with the slider at the design `c`'s θ, as a `--scene` file.
pub fn answer_scene(pr: &PatternResult, c: &Candidate) -> SceneFile {
    surrogate::scene::scene_file(&pr.scene.scene.with_theta(deg_to_rad(c.theta_deg)))
}

/// The TOML text of [`answer_scene`] (a comment line first naming the design).
pub fn answer_toml(pr: &PatternResult, c: &Candidate) -> String {
    let body = toml::to_string(&answer_scene(pr, c)).unwrap_or_default();
    format!(
        "# {}'s answer of `superlube design`: θ = {}°, pull at {}° from the substrate x axis (α = {}° from the contact line)\n{body}",
        pr.scene.name, c.theta_deg, c.direction_deg, c.alpha_deg
    )
}

/// Decimals of the angles in the answer and DEM tables: what the tolerance can resolve (its
/// sampling step; at least 2, at most 6).
pub fn angle_decimals(p: &DesignParams) -> usize {
    let mut res: f64 = 0.01;
    if p.tolerance.theta_tol_deg > 0.0 {
        res = res.min(
            p.tolerance
                .theta_tol_step_deg
                .min(p.tolerance.theta_tol_deg),
        );
    }
    if p.tolerance.direction_tol_deg > 0.0 {
        res = res.min(
            p.tolerance
                .direction_tol_step_deg
                .min(p.tolerance.direction_tol_deg),
        );
    }
    ((-res.log10()).ceil().max(0.0) as usize).clamp(2, 6)
}

/// An angle (degrees) with `decimals` decimals, trailing zeros dropped (`119.66`, `90`), never
/// `-0`.
pub fn angle(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// The load (mN) an answer's claim names: the robust limit, or the nominal one where the box
/// was not searched to the end; 0 where it is superlubric nowhere.
pub fn claim_mn(c: &Candidate) -> f64 {
    if c.score.exact {
        c.score.superlubric_to_mn
    } else {
        c.score.nominal_to_mn
    }
}

/// The DEM runs of the design `c` itself (no corner offset, the design's protocol).
fn centre_runs<'d>(dem: &'d [DemRow], name: &str, c: &Candidate) -> Vec<&'d DemRow> {
    let mut v: Vec<&DemRow> = dem
        .iter()
        .filter(|d| {
            d.pattern == name
                && d.theta_deg == c.theta_deg
                && d.alpha_deg == c.alpha_deg
                && d.theta_offset_deg == 0.0
                && d.direction_offset_deg == 0.0
                && d.protocol == DemProtocol::Design
        })
        .collect();
    v.sort_by(|a, b| a.load_mN.total_cmp(&b.load_mN));
    v
}

/// The corner runs of the design at `rank` (1-based).
fn corner_runs<'d>(dem: &'d [DemRow], name: &str, rank: usize) -> Vec<&'d DemRow> {
    let mut v: Vec<&DemRow> = dem
        .iter()
        .filter(|d| {
            d.pattern == name
                && d.rank == rank
                && d.protocol == DemProtocol::Design
                && (d.theta_offset_deg != 0.0 || d.direction_offset_deg != 0.0)
        })
        .collect();
    v.sort_by(|a, b| a.load_mN.total_cmp(&b.load_mN));
    v
}

fn loads_list(v: &[f64]) -> String {
    v.iter()
        .map(|w| format!("{w}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// `held at 0.35, 1.75 mN; failed at 2.1 mN` of the runs `runs` (a run without a DEM verdict
/// counts as failed).
fn centre_cell(runs: &[&DemRow]) -> String {
    if runs.is_empty() {
        return "no run".into();
    }
    let held: Vec<f64> = runs
        .iter()
        .filter(|d| d.superlubric_dem == Some(true))
        .map(|d| d.load_mN)
        .collect();
    let failed: Vec<f64> = runs
        .iter()
        .filter(|d| d.superlubric_dem != Some(true))
        .map(|d| d.load_mN)
        .collect();
    let mut parts = Vec::new();
    if !held.is_empty() {
        parts.push(format!("held at {} mN", loads_list(&held)));
    }
    if !failed.is_empty() {
        parts.push(format!("failed at {} mN", loads_list(&failed)));
    }
    parts.join("; ")
}

/// `4 of 4 held at 1.75 mN; 1 of 4 held at 2.1 mN` of the corner runs, per load.
fn corners_cell(runs: &[&DemRow]) -> String {
    let mut loads: Vec<f64> = runs.iter().map(|d| d.load_mN).collect();
    loads.dedup();
    loads
        .iter()
        .map(|&w| {
            let at: Vec<&&DemRow> = runs
                .iter()
                .filter(|d| LoadKey::of_mn(d.load_mN) == LoadKey::of_mn(w))
                .collect();
            let ok = at
                .iter()
                .filter(|d| d.superlubric_dem == Some(true))
                .count();
            format!("{ok} of {} held at {w} mN", at.len())
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// A window in words: `±w°`, `less than ±step°` for none, `not computed`.
fn window(w: Option<f64>, step: f64) -> String {
    match w {
        Some(w) if w > 0.0 => format!("±{w}°"),
        Some(_) => format!("less than ±{step}°"),
        None => "window not computed".into(),
    }
}

/// The nominal optimum of `pr` when its nominal limit exceeds the answer `b`'s robust limit
/// (the design with the highest nominal limit; the answer itself when that is its own).
pub fn nominal_optimum<'a>(pr: &'a PatternResult, b: &Candidate) -> Option<&'a Candidate> {
    pr.ranking
        .iter()
        .filter(|c| c.score.nominal_to_mn > b.score.superlubric_to_mn)
        .fold(None::<&Candidate>, |best, c| match best {
            Some(x) if x.score.nominal_to_mn >= c.score.nominal_to_mn => Some(x),
            _ => Some(c),
        })
}

fn nominal_cell(pr: &PatternResult, b: &Candidate, p: &DesignParams, dec: usize) -> String {
    let Some(n) = nominal_optimum(pr, b) else {
        return "the same design".into();
    };
    let who = if std::ptr::eq(n, b) {
        "this design".to_string()
    } else {
        format!(
            "θ = {}°, pull {}° (α = {}°)",
            n.theta_deg,
            angle(n.direction_deg, dec),
            angle(n.alpha_deg, dec)
        )
    };
    format!(
        "{who}: {} mN within θ {}, direction {}",
        n.score.nominal_to_mn,
        window(
            n.score.theta_window_deg,
            p.tolerance
                .theta_tol_step_deg
                .min(p.tolerance.theta_tol_deg)
        ),
        window(
            n.score.direction_window_deg,
            p.tolerance
                .direction_tol_step_deg
                .min(p.tolerance.direction_tol_deg)
        )
    )
}

/// The answer table's rows, one per pattern (see [`TopRow`]).
pub fn top_rows(o: &DesignOutcome, p: &DesignParams, dem: &[DemRow]) -> Vec<TopRow> {
    let dec = angle_decimals(p);
    let boxed = p.tolerance.theta_tol_deg > 0.0 || p.tolerance.direction_tol_deg > 0.0;
    let pm = |v: String, tol: f64| {
        if boxed {
            format!("{v} ± {tol}")
        } else {
            v
        }
    };
    o.patterns
        .iter()
        .zip(&o.answers)
        .map(|(pr, a)| {
            let name = pr.scene.name.clone();
            let Some(b) = a.index.and_then(|i| pr.ranking.get(i)) else {
                let dash = || "–".to_string();
                return TopRow {
                    pattern: name,
                    theta: dash(),
                    pull_x: dash(),
                    alpha: dash(),
                    limit_mn: "0".into(),
                    verdict: "no design".into(),
                    dem_centre: dash(),
                    dem_corners: dash(),
                    nominal: dash(),
                    fab_yield: String::new(),
                };
            };
            let rank = a.index.unwrap_or(0) + 1;
            let (centre, corners) = if !o.dem_ran {
                ("not run (`--no-dem`)".to_string(), "not run".to_string())
            } else {
                let c = corner_runs(dem, &name, rank);
                (
                    centre_cell(&centre_runs(dem, &name, b)),
                    if !boxed {
                        "no tolerance box".into()
                    } else if c.is_empty() {
                        "no run".into()
                    } else {
                        corners_cell(&c)
                    },
                )
            };
            TopRow {
                theta: pm(format!("{}", b.theta_deg), p.tolerance.theta_tol_deg),
                pull_x: pm(angle(b.direction_deg, dec), p.tolerance.direction_tol_deg),
                alpha: angle(b.alpha_deg, dec),
                limit_mn: match b.score.below_ladder_mn {
                    // located below the ladder's first load ([`super::words::below_ladder_words`])
                    Some(w) if b.score.superlubric_to_mn == 0.0 && w > 0.0 => {
                        format!("{} (below the ladder)", super::words::fmt_g(w, 3))
                    }
                    Some(_) if b.score.superlubric_to_mn == 0.0 => "0 (below the floor)".into(),
                    _ => format!(
                        "{}{}",
                        if b.score.exact { "" } else { "≤ " },
                        b.score.superlubric_to_mn
                    ),
                },
                verdict: b.score.verdict.to_string(),
                dem_centre: centre,
                dem_corners: corners,
                nominal: nominal_cell(pr, b, p, dec),
                fab_yield: String::new(),
                pattern: name,
            }
        })
        .collect()
}

/// One short paragraph in plain words on the answer `a` of `pr` (the definitions are in "How
/// to read this").
pub fn paragraph(pr: &PatternResult, a: &Answer, p: &DesignParams) -> String {
    let name = &pr.scene.name;
    let pc = pa_to_gpa(pr.scene.scene.coating.p_crit);
    let dec = angle_decimals(p);
    let Some(b) = a.index.and_then(|i| pr.ranking.get(i)) else {
        return format!(
            "**{name}**: no design: no orientation keeps the coating intact (P_max ≤ {pc} GPa) even at the lowest load."
        );
    };
    let mut m = format!(
        "**{name}**: make the slider at θ = {}° and pull it at {}° from the substrate x axis ({}° from its contact line)",
        b.theta_deg,
        angle(b.direction_deg, dec),
        angle(b.alpha_deg, dec)
    );
    if p.tolerance.theta_tol_deg > 0.0 || p.tolerance.direction_tol_deg > 0.0 {
        let _ = write!(
            m,
            ", each within the fabrication tolerance θ ±{}° × pull direction ±{}°",
            p.tolerance.theta_tol_deg, p.tolerance.direction_tol_deg
        );
    }
    let w = claim_mn(b);
    let sc = &b.score;
    if w == 0.0 {
        if sc.nominal_to_mn > 0.0 {
            let _ = write!(
                m,
                ". No design stays superlubric over the whole box even at the lowest load; this one is superlubric up to {} mN at its nominal orientation only.",
                sc.nominal_to_mn
            );
            m.push_str(&super::words::below_ladder_words(b, p));
        } else {
            let _ = write!(
                m,
                ". No design is superlubric even at the lowest load: this one has μ_est = {} there.",
                fmt_g(sc.mu_worst, 3)
            );
            m.push_str(&super::words::below_ladder_words(b, p));
        }
    } else {
        let how = match sc.verdict {
            Verdict::Superlubric => "stays superlubric",
            _ => "is only [**borderline**](#how-to-read-this) superlubric",
        };
        let nominal_only = if sc.exact {
            ""
        } else {
            " at its nominal orientation (its box was not searched to the end)"
        };
        let fr = row_at(b, w);
        let _ = write!(
            m,
            ". It {how} up to **{w} mN**{nominal_only}: there μ_est ≤ {} and P_max ≤ {} GPa on the path (P_crit {pc} GPa); rank {} of {} candidates.",
            fmt_g(sc.mu_worst, 3),
            opt(fr.and_then(|f| f.p_max_GPa), 3),
            a.index.unwrap_or(0) + 1,
            pr.ranking.len()
        );
    }
    match &a.check {
        Check::NoDem => m.push_str(" Not checked with the DEM."),
        Check::Confirmed(_) => m.push_str(" The DEM confirms it (the table's DEM columns)."),
        Check::Contradicted(why) => {
            let _ = write!(m, " The DEM does **not** confirm it: {why}.");
        }
        Check::Unchecked => m.push_str(" The DEM did not run at a load up to its limit."),
    }
    if let Some(n) = nominal_optimum(pr, b) {
        if !std::ptr::eq(n, b) {
            let _ = write!(
                m,
                " A higher nominal limit exists ({} mN at θ = {}°) but only in a narrower window (the table's last column).",
                n.score.nominal_to_mn, n.theta_deg
            );
        } else if w > 0.0 {
            let _ = write!(
                m,
                " Aligned more precisely it holds to {} mN (the table's last column).",
                sc.nominal_to_mn
            );
        }
    }
    m
}

/// How to run each pattern's answer (patterns without a design have none).
pub fn answer_runs(o: &DesignOutcome, p: &DesignParams) -> Vec<AnswerRun> {
    o.patterns
        .iter()
        .zip(&o.answers)
        .filter_map(|(pr, a)| {
            let c = pr.ranking.get(a.index?)?;
            Some(answer_run(pr, c, p))
        })
        .collect()
}

/// The load (mN) the answer's `slide` and `export-lammps` run at: its claimed limit, else the
/// lowest load.
pub fn run_load_mn(c: &Candidate, p: &DesignParams) -> f64 {
    let w = claim_mn(c);
    if w > 0.0 {
        w
    } else {
        label(n_to_mn(p.loads.first().copied().unwrap_or(0.0)))
    }
}

/// The scene file and commands of the design `c` of `pr`.
pub fn answer_run(pr: &PatternResult, c: &Candidate, p: &DesignParams) -> AnswerRun {
    let name = &pr.scene.name;
    let file = scene_file_name(name);
    let w = run_load_mn(c, p);
    let line = line_flag(p);
    let slide = format!(
        "superlube slide --scene {file} --alpha-deg {} --load-mn {w}{line}{} --json answer_{name}/slide.json --out answer_{name}/slide.csv",
        c.alpha_deg,
        protocol_flags(
            p,
            false,
            crate::study::design::confirm::dem_model(pr, c, &p.confirm).request
        )
    );
    let range = |tol: f64, min: f64| label((2.0 * tol).max(min));
    let f = &p.friction;
    let tolerance = format!(
        "superlube tolerance --scene {file} --direction-deg {} --theta-range-deg {} --theta-points 17 --direction-range-deg {} --direction-points 9 --theta-tol-deg {} --direction-tol-deg {} --load-mn {} --mu-superlubric {}{line} --length-um {} --max-period-um {} --step-um {} --transient-um {} --k0-n-m {} --transverse-um {} --out-dir answer_{name}/tolerance",
        c.direction_deg,
        range(p.tolerance.theta_tol_deg, 0.1),
        range(p.tolerance.direction_tol_deg, 0.5),
        p.tolerance.theta_tol_deg,
        p.tolerance.direction_tol_deg,
        loads_text(p),
        p.mu_superlubric,
        label(m_to_um(f.length)),
        label(m_to_um(f.max_period)),
        label(m_to_um(f.step)),
        label(m_to_um(f.transient)),
        f.k0,
        label(m_to_um(f.transverse))
    );
    let s = &p.confirm.dem.sim;
    let export = format!(
        "superlube export-lammps --scene {file} --alpha-deg {} --load-mn {w}{line} --equilibrate-us {} --relax-us {} --slide-us {} --speed-m-s {} --out-dir answer_{name}/lammps",
        c.alpha_deg,
        label(s_to_us(s.protocol.equilibrate_time)),
        label(s_to_us(s.protocol.relax_time)),
        label(s_to_us(s.protocol.slide_time)),
        s.protocol.support_speed
    );
    AnswerRun {
        pattern: name.clone(),
        scene_file: file,
        slide,
        tolerance,
        export,
    }
}

#[cfg(test)]
mod tests {
    use super::angle;

    #[test]
    fn angles_print_what_the_tolerance_resolves() {
        assert_eq!(angle(119.656879452, 2), "119.66");
        assert_eq!(angle(90.0, 2), "90");
        assert_eq!(angle(12.30000001, 2), "12.3");
        assert_eq!(angle(-0.001, 2), "0");
        assert_eq!(angle(-45.5, 3), "-45.5");
    }
}
