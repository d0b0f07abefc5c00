//! The words of a yield, the same in `superlube yield`'s log, the design's log and report, and
//! the yield plot's legend: loads to 3 significant digits ([`load`]), the fabricator's sentence
//! ([`fabricator`]) and the DEM check's ([`check`]).

use crate::present::design_report::words::fmt_g;
use crate::study::fab_yield::YieldSummary;
use crate::study::rows::label;

/// A load (mN) to 3 significant digits, as every yield text writes it.
pub fn load(w_mn: f64) -> String {
    fmt_g(w_mn, 3)
}

/// A fraction in percent (`95`).
fn pct(v: f64) -> String {
    format!("{}", label(100.0 * v))
}

/// What the yield means for a fabricator, in one line: "95 % of devices made within the
/// tolerance hold 1.78 mN; with 95 % confidence, at least 95 % hold 1.74 mN".
pub fn fabricator(s: &YieldSummary) -> String {
    let q = pct(s.quantile);
    match (s.load_at_quantile_mN, s.load_at_quantile_bound_mN) {
        (Some(w), Some(b)) => format!(
            "{q} % of devices made within the tolerance hold {} mN; with {} % confidence, at least {q} % hold {} mN",
            load(w),
            pct(s.confidence),
            load(b)
        ),
        (Some(w), None) => format!(
            "{q} % of devices made within the tolerance hold {} mN (no confidence bound from {} devices: a bound needs ≥ {})",
            load(w),
            s.pooled,
            s.min_samples_for_bound
        ),
        _ => format!("none of {} devices is superlubric at any load", s.pooled),
    }
}

/// The DEM check in one line ("DEM check: 9/10 fresh devices held at 1.78 mN; agrees with
/// the quote"); `None` without a check.
pub fn check(s: &YieldSummary) -> Option<String> {
    if s.dem_check_total == 0 {
        return None;
    }
    let agreement = match (s.dem_check_consistent, s.quote_lowered_by_check) {
        (Some(true), true) => "; the quote was lowered until its check agreed",
        (Some(true), false) => "; agrees with the quote",
        (Some(false), _) => {
            "; CONTRADICTS the quote: fewer fresh devices hold it than the yield claims"
        }
        (None, _) => "",
    };
    Some(format!(
        "DEM check: {}/{} fresh devices held at {} mN{agreement}",
        s.dem_check_passed,
        s.dem_check_total,
        load(s.dem_check_load_mN.unwrap_or(0.0))
    ))
}

/// How far more DEM runs could lift the quote and its bound ("more DEM runs could lift the
/// quote to at most 1.92 mN and its bound to 1.88 mN"); `None` without a ceiling.
pub fn ceiling(s: &YieldSummary) -> Option<String> {
    match s.ceiling_mN {
        Some([Some(q), Some(b)]) => Some(format!(
            "more DEM runs could lift the quote to at most {} mN and its bound to {} mN",
            load(q),
            load(b)
        )),
        _ => None,
    }
}

/// What the DEM did for the yield in one line: runs, located devices and the band.
pub fn dem_work(s: &YieldSummary) -> String {
    let band = match s.band.coverage {
        Some(c) => format!(
            "the design's own band from {} DEM/estimate pairs on {} devices (P_max ratio {:.3}–{:.3}, coverage {:.1} %)",
            s.band.pairs,
            s.band.devices,
            s.band.p_ratio[0],
            s.band.p_ratio[1],
            100.0 * c
        ),
        None => "the global band (too few DEM/estimate pairs for the design's own)".into(),
    };
    let undecided = if s.undecided > 0 {
        let ceiling = ceiling(s).map_or(String::new(), |c| format!("; {c}"));
        format!(
            "; {} device(s) that could still set them kept at the lower end of what is known (the quote is conservative){ceiling}",
            s.undecided
        )
    } else {
        String::new()
    };
    format!(
        "{} of {} DEM run(s); {} device(s) located by the DEM (the lowest {} critical loads set the quote and its bound); {band}{undecided}",
        s.dem_runs,
        s.dem_runs_allowed,
        s.located.len(),
        s.setting_ranks
    )
}
