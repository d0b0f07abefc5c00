//! [`answer_line`]: the answer of one pattern as a Markdown list item (also the final log line):
//! its headline, its tolerance, what the DEM said at its centre and corners, and the estimate's
//! contradicted ranks.

use super::rows::{row_at, DemProtocol, DemRow};
use super::words::{below_ladder_words, fmt_g, opt, tolerance_words};
use crate::study::design::answer::{Answer, Check};
use crate::study::design::rank::Candidate;
use crate::study::design::{tolerance_box, DesignParams, PatternResult};
use crate::study::load::LoadKey;
use crate::study::verdict::{band_words, Verdict};
use std::fmt::Write as _;
use surrogate::units::pa_to_gpa;

/// The answer of one pattern as a Markdown list item (also the final log line). `dem`: the
/// design's DEM runs; `w_top` (mN): the highest load asked. Cost: a pass over `dem`.
pub fn answer_line(
    pr: &PatternResult,
    a: &Answer,
    dem: &[DemRow],
    p: &DesignParams,
    w_top: f64,
) -> String {
    let name = &pr.scene.name;
    let pc = pa_to_gpa(pr.scene.scene.coating.p_crit);
    let Some(b) = a.index.and_then(|i| pr.ranking.get(i)) else {
        return format!(
            "- **{name}**: no design — no orientation keeps the coating intact (P_max ≤ {pc} GPa) even at the lowest load."
        );
    };
    let mut m = headline(pr, a, b, p, w_top);
    m.push_str(&tolerance_words(pr, b, p));
    let runs = centre_runs(dem, name, b);
    m.push_str(&check_words(a, b, p, &runs));
    m.push_str(&corner_words(dem, name, a));
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

/// The answer's first sentence: the design `b` and up to which load it stays superlubric, or
/// why there is none.
fn headline(pr: &PatternResult, a: &Answer, b: &Candidate, p: &DesignParams, w_top: f64) -> String {
    let name = &pr.scene.name;
    let pc = pa_to_gpa(pr.scene.scene.coating.p_crit);
    let mut m = String::new();
    if b.score.superlubric_to_mn == 0.0 && b.score.nominal_to_mn > 0.0 {
        // superlubric at its nominal orientation, but not over its whole tolerance box
        let _ = write!(
            m,
            "- **{name}**: no design stays superlubric over its whole tolerance box even at the lowest load; the best candidate, θ = {}°, α = {}°, is superlubric up to {} mN at its nominal orientation only (μ_est ≤ {}).",
            b.theta_deg,
            b.alpha_deg,
            b.score.nominal_to_mn,
            fmt_g(b.score.mu_worst, 3),
        );
        m.push_str(&below_ladder_words(b, p));
    } else if b.score.superlubric_to_mn == 0.0 {
        let _ = write!(
            m,
            "- **{name}**: no design is superlubric even at the lowest load; the best candidate, θ = {}°, α = {}°, has μ_est = {} there (coating intact on its path up to {} mN).",
            b.theta_deg,
            b.alpha_deg,
            fmt_g(b.score.mu_worst, 3),
            b.score.intact_to_mn
        );
        m.push_str(&below_ladder_words(b, p));
    } else {
        // the claim's load: the robust limit, or the nominal one where the tolerance box was
        // not searched to the end (the floor of many patterns: [`tolerance_words`])
        let w = if b.score.exact {
            b.score.superlubric_to_mn
        } else {
            b.score.nominal_to_mn
        };
        let fr = row_at(b, w);
        // a borderline answer is never a plain yes: the qualifier is in the headline itself
        let claim = match (b.score.verdict == Verdict::Superlubric, b.score.exact) {
            (true, true) => "stays superlubric",
            (false, true) => "is only **borderline** superlubric",
            // not searched over its tolerance box (the floor: [`tolerance_words`])
            (true, false) => "stays superlubric at its nominal orientation",
            (false, false) => "is only **borderline** superlubric at its nominal orientation",
        };
        let _ = write!(
            m,
            "- **{name}**: θ = **{}°**, α = **{}°** from the contact line (pull at {}° from the substrate x axis; contact line at {}°) {claim} up to **{} mN**{}{}: μ_est ≤ {}, P_max ≤ {} GPa on the path at {} mN (P_crit = {pc} GPa), {} contacts on average; rank {} of the estimate.",
            b.theta_deg,
            b.alpha_deg,
            fmt_g(b.direction_deg, 4),
            fmt_g(b.line_deg, 4),
            w,
            if w == w_top {
                " (the highest load asked)"
            } else {
                ""
            },
            if b.score.verdict == Verdict::Superlubric {
                String::new()
            } else {
                format!(
                    " (the estimate is within its measured uncertainty of a threshold at a load up to it, so the DEM could place it either side: {}; docs/validation/verdict-band.md)",
                    band_words(p.mu_superlubric, pr.scene.scene.coating.p_crit)
                )
            },
            fmt_g(b.score.mu_worst, 3),
            opt(fr.and_then(|f| f.p_max_GPa), 3),
            w,
            fmt_g(b.score.contacts, 3),
            a.index.unwrap_or(0) + 1
        );
    }
    m
}

/// The design's own DEM runs (the centre of its tolerance box, the design protocol), one
/// `W mN: μ_DEM = …` each.
fn centre_runs(dem: &[DemRow], name: &str, b: &Candidate) -> Vec<String> {
    dem.iter()
        .filter(|d| {
            d.pattern == name
                && d.theta_deg == b.theta_deg
                && d.alpha_deg == b.alpha_deg
                && d.theta_offset_deg == 0.0
                && d.direction_offset_deg == 0.0
                && d.protocol == DemProtocol::Design
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
        .collect()
}

/// What the DEM check of the answer said, with its centre `runs`.
fn check_words(a: &Answer, b: &Candidate, p: &DesignParams, runs: &[String]) -> String {
    let mut m = String::new();
    match &a.check {
        Check::NoDem => {
            let _ = write!(m, " Not checked with the DEM (`--no-dem`).");
        }
        Check::Confirmed(loads) => {
            let _ = write!(
                m,
                " **Confirmed by the DEM** at {} mN ({}){}.",
                loads
                    .iter()
                    .map(|w| format!("{w}"))
                    .collect::<Vec<_>>()
                    .join(", "),
                runs.join("; "),
                if tolerance_box(p).is_point() {
                    String::new()
                } else {
                    format!(
                        ", and at every corner of its tolerance box at {} mN",
                        b.score.superlubric_to_mn
                    )
                }
            );
        }
        Check::Contradicted(why) => {
            let _ = write!(
                m,
                " **Not confirmed**: no DEM-checked design of the top {} is; this one's DEM run says {why} ({}).",
                p.confirm.designs,
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
    m
}

/// The DEM at the corners of the answer's tolerance box, per load (empty without corner runs).
fn corner_words(dem: &[DemRow], name: &str, a: &Answer) -> String {
    let mut m = String::new();
    let corners: Vec<&DemRow> = dem
        .iter()
        .filter(|d| {
            d.pattern == name
                && Some(d.rank) == a.index.map(|i| i + 1)
                && (d.theta_offset_deg != 0.0 || d.direction_offset_deg != 0.0)
        })
        .collect();
    if !corners.is_empty() {
        let at = |w: f64| {
            let c: Vec<&&DemRow> = corners
                .iter()
                .filter(|d| LoadKey::of_mn(d.load_mN) == LoadKey::of_mn(w))
                .collect();
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
    m
}
