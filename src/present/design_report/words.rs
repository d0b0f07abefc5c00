//! The sentences of the report that depend on the outcome in more ways than a template should
//! hold: the answer per pattern (also the final log line), its tolerance words, the protocol in
//! words, which design a study-protocol run is on; and the number formats ([`fmt_g`]).

pub use super::answer_line::answer_line;
use super::rows::DemRow;
use crate::study::design::answer::{Check, Contradiction};
use crate::study::design::best::BEST_PATTERNS;
use crate::study::design::rank::{Candidate, Pick};
use crate::study::design::symmetry_words::PairSymmetry;
use crate::study::design::symmetry_words::{self, Domain, SymmetryWords};
use crate::study::design::{DesignOutcome, DesignParams, PatternResult};
use crate::study::design::{
    OutsideDomain, ThetaNote, THETA_STEP_DEG, WIDE_DOMAIN_DEG, WIDE_THETA_STEP_DEG,
};
use crate::study::input::Input;
use crate::study::rows::label;
use std::fmt::Write as _;
use surrogate::units::s_to_us;

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
