//! The sentences of the report that depend on the outcome in more ways than a template should
//! hold: the answer per pattern (also the final log line), its tolerance words, the protocol in
//! words, which design a study-protocol run is on; and the number formats ([`fmt_g`]).

use super::rows::{row_at, DemProtocol, DemRow};
use crate::study::design::answer::{Answer, Check, Contradiction};
use crate::study::design::best::BEST_PATTERNS;
use crate::study::design::rank::{Candidate, Pick};
use crate::study::design::symmetry_words::PairSymmetry;
use crate::study::design::symmetry_words::{self, Domain, SymmetryWords};
use crate::study::design::{tolerance_box, DesignOutcome, DesignParams, PatternResult};
use crate::study::design::{
    OutsideDomain, ThetaNote, THETA_STEP_DEG, WIDE_DOMAIN_DEG, WIDE_THETA_STEP_DEG,
};
use crate::study::input::Input;
use crate::study::load::LoadKey;
use crate::study::rows::label;
use crate::study::verdict::{band_words, Verdict};
use std::fmt::Write as _;
use surrogate::units::{pa_to_gpa, s_to_us};

/// `v` with `digits` significant digits (plain notation from 1e-3 to 1e4).
pub fn fmt_g(v: f64, digits: usize) -> String {
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

pub fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or("–".into(), |x| fmt_g(x, digits))
}

/// The protocol in words (`equilibrate 2 + relax 2 + slide 60 µs at 0.1 m/s`).
pub fn protocol_words(p: &DesignParams) -> String {
    let s = &p.confirm.dem.sim;
    format!(
        "equilibrate {} + relax {} + slide {} µs at {} m/s, friction over the last two thirds of the slide",
        label(s_to_us(s.protocol.equilibrate_time)),
        label(s_to_us(s.protocol.relax_time)),
        label(s_to_us(s.protocol.slide_time)),
        s.protocol.support_speed
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
    m.push_str(&tolerance_words(pr, b, p));
    let runs: Vec<String> = dem
        .iter()
        .filter(|d| {
            d.pattern == *name
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
        .collect();
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
    let corners: Vec<&DemRow> = dem
        .iter()
        .filter(|d| {
            d.pattern == *name
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

/// Where the robust limit of `b` is 0 and was located below the ladder's first load
/// ([`crate::study::design::below_ladder`]), the sentence giving it with its meaning; empty
/// otherwise.
pub fn below_ladder_words(b: &Candidate, p: &DesignParams) -> String {
    use crate::study::design::below_ladder::{FLOOR_FRACTION, RESOLUTION};
    let Some(w) = b
        .score
        .below_ladder_mn
        .filter(|_| b.score.superlubric_to_mn == 0.0)
    else {
        return String::new();
    };
    let first = p.loads.labels_mn().first().copied().unwrap_or(0.0);
    let floor = fmt_g(first * FLOOR_FRACTION, 3);
    if w > 0.0 {
        format!(
            " Below the ladder's first load ({first} mN), bisection over the same samples (to {} %, down to {floor} mN) finds it superlubric up to **{} mN**: its robust limit lies there, below every load of the ladder.",
            100.0 * RESOLUTION,
            fmt_g(w, 3)
        )
    } else {
        format!(
            " It fails even at {floor} mN ({} % of the ladder's first load, {first} mN, the floor of the search below the ladder): it carries no load superlubrically.",
            100.0 * FLOOR_FRACTION
        )
    }
}

/// The tolerance sentences of the answer `b`: the robust limit over the box and the window at
/// the nominal limit, and the nominal optimum where it differs (a borderline verdict is in the
/// headline, [`answer_line`]).
pub fn tolerance_words(pr: &PatternResult, b: &Candidate, p: &DesignParams) -> String {
    let within = |w: Option<f64>, step: f64| match w {
        Some(w) if w > 0.0 => format!("±{w}°"),
        Some(_) => format!("less than ±{step}° (the first sample)"),
        None => "(window not computed)".to_string(),
    };
    let mut m = String::new();
    let sc = &b.score;
    if !sc.exact && pr.robust_floor_mn > 0.0 && sc.superlubric_to_mn <= pr.robust_floor_mn {
        let _ = write!(
            m,
            " Its limit over the fabrication tolerance θ ±{}° × pull direction ±{}° {}, and the best {} patterns' robust limits were all at least {} mN when it was taken (the patterns are taken best nominal design first), so it cannot enter the best {}.",
            p.tolerance.theta_tol_deg,
            p.tolerance.direction_tol_deg,
            if sc.superlubric_to_mn < sc.nominal_to_mn {
                format!(
                    "was searched only until it fell to them: it is at most {} mN",
                    sc.superlubric_to_mn
                )
            } else {
                format!(
                    "was not searched: it is at most its nominal limit, {} mN",
                    sc.nominal_to_mn
                )
            },
            BEST_PATTERNS,
            pr.robust_floor_mn,
            BEST_PATTERNS
        );
        return m;
    }
    if p.tolerance.theta_tol_deg > 0.0 || p.tolerance.direction_tol_deg > 0.0 {
        let _ = write!(
            m,
            " Over the fabrication tolerance θ ±{}° × pull direction ±{}° (the pull direction stays fixed in the substrate frame when the slider is misaligned) it holds to **{} mN**{}",
            p.tolerance.theta_tol_deg,
            p.tolerance.direction_tol_deg,
            match sc.below_ladder_mn {
                Some(w) if sc.superlubric_to_mn == 0.0 && w > 0.0 => fmt_g(w, 3),
                _ => sc.superlubric_to_mn.to_string(),
            },
            match sc.below_ladder_mn {
                Some(w) if sc.superlubric_to_mn == 0.0 && w > 0.0 => " (below the ladder)",
                _ => "",
            }
        );
        if sc.nominal_to_mn > sc.superlubric_to_mn {
            let _ = write!(
                m,
                "; its nominal {} mN holds only within θ {}, direction {}.",
                sc.nominal_to_mn,
                within(
                    sc.theta_window_deg,
                    p.tolerance
                        .theta_tol_step_deg
                        .min(p.tolerance.theta_tol_deg)
                ),
                within(
                    sc.direction_window_deg,
                    p.tolerance
                        .direction_tol_step_deg
                        .min(p.tolerance.direction_tol_deg)
                )
            );
        } else {
            m.push('.');
        }
    }
    // the nominal optimum, said only where it is another design: one whose nominal limit is
    // above both the answer's robust limit and its own nominal limit
    if let Some(n) = pr
        .ranking
        .iter()
        .filter(|c| c.score.nominal_to_mn > sc.superlubric_to_mn)
        .fold(None::<&Candidate>, |best, c| match best {
            Some(b) if b.score.nominal_to_mn >= c.score.nominal_to_mn => Some(b),
            _ => Some(c),
        })
        .filter(|n| n.score.nominal_to_mn > sc.nominal_to_mn)
    {
        let _ = write!(
            m,
            " The nominal optimum differs: θ = {}°, α = {}° reaches {} mN only within θ {} (direction {}), {}{} mN over the tolerance.",
            n.theta_deg,
            n.alpha_deg,
            n.score.nominal_to_mn,
            within(n.score.theta_window_deg, p.tolerance.theta_tol_step_deg.min(p.tolerance.theta_tol_deg)),
            within(
                n.score.direction_window_deg,
                p.tolerance.direction_tol_step_deg.min(p.tolerance.direction_tol_deg)
            ),
            if n.score.exact { "" } else { "≤ " },
            n.score.superlubric_to_mn
        );
    }
    m
}

/// What the study-protocol run `s` is run on, in words: the recommended design (a pattern's
/// answer, confirmed by the DEM or not) or another design.
pub fn which_design(o: &DesignOutcome, s: &DemRow) -> String {
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

/// The refusal of a θ list with no θ in a pattern's fundamental domain, naming the θ given,
/// the domain, an equivalent θ in it and the way out.
impl std::fmt::Display for OutsideDomain {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let Domain {
            lo_deg: lo,
            hi_deg: hi,
            closed,
        } = self.sym.domain();
        let t = self.thetas_deg[0];
        write!(
            f,
            "{}: none of `{}` lies in the fundamental domain [{}°, {}°{} of {} ({}); every orientation is equivalent to one in it (e.g. {}° ≡ {}°): give θ in [{}, {}], or pass {}",
            Input::Theta,
            super::commands::theta_text(&self.thetas_deg),
            symmetry_words::fmt(lo),
            symmetry_words::fmt(hi),
            if closed { "]" } else { ")" },
            self.pattern,
            self.sym.describe(),
            symmetry_words::fmt(t),
            symmetry_words::fmt(self.sym.fold(t)),
            symmetry_words::fmt(lo),
            symmetry_words::fmt(hi),
            Input::NoSymmetryCut
        )
    }
}

/// A load in mN for messages (`1.75 mN`).
pub fn mn(w: f64) -> String {
    format!("{} mN", label(surrogate::units::n_to_mn(w)))
}

/// Why an orientation was shortlisted, in the ranking's words.
pub fn pick_words(p: Pick) -> String {
    match p {
        Pick::Top => "survives the highest load".to_string(),
        Pick::Level(w) => format!("best of level {}", mn(w)),
    }
}

/// Why the DEM contradicts a design, naming the tolerance corner of a corner's run.
impl std::fmt::Display for Contradiction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.corner {
            None => write!(f, "{}", self.why),
            Some((dt, dd)) => write!(
                f,
                "{} at its tolerance corner δθ = {dt:+}°, δdir = {dd:+}°",
                self.why
            ),
        }
    }
}

/// A pattern's [`ThetaNote`] in words: which part of `sym`'s domain the θ list leaves out, or
/// that the whole domain is screened at the default step.
pub fn theta_note(n: &ThetaNote, sym: &PairSymmetry) -> String {
    match n {
        ThetaNote::Uncovered {
            gaps,
            theta_default,
        } => {
            let Domain {
                lo_deg: lo,
                hi_deg: hi,
                closed,
            } = sym.domain();
            format!(
                "the θ list does not cover the domain [{}°, {}°{}: {} not screened (give {} over the whole domain{})",
                symmetry_words::fmt(lo),
                symmetry_words::fmt(hi),
                if closed { "]" } else { ")" },
                sym.gaps_text(gaps),
                Input::Theta,
                if *theta_default {
                    String::new()
                } else {
                    format!(", or leave {} out to screen it at the default step", Input::Theta)
                }
            )
        }
        ThetaNote::WholeDomain { step, thetas } => format!(
            "no {} given: the whole domain at {step}° ({thetas} θ{})",
            Input::Theta,
            if *step == WIDE_THETA_STEP_DEG {
                format!(
                    "; {step}° rather than {THETA_STEP_DEG}° for a domain wider than {WIDE_DOMAIN_DEG}°"
                )
            } else {
                String::new()
            }
        ),
    }
}
