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
    let at = s.dem_check_load_mN.unwrap_or(0.0);
    // the check ran at the estimate's quote, before the rounds; the rounds over the pool then
    // set the quote elsewhere
    let pooled_to = s
        .load_at_quantile_mN
        .filter(|&q| !s.dem_check_load_given && load(q) != load(at));
    let agreement = match (s.dem_check_consistent, s.quote_lowered_by_check, pooled_to) {
        (Some(true), true, _) => "; the quote was lowered until its check agreed".to_string(),
        (Some(true), false, Some(q)) => format!(
            " (the estimate's quote); with them pooled, the DEM's rounds set the quote at {} mN, which the check agrees with",
            load(q)
        ),
        (Some(true), false, None) => "; agrees with the quote".to_string(),
        (Some(false), _, _) => {
            "; CONTRADICTS the quote: fewer fresh devices hold it than the yield claims".to_string()
        }
        (None, _, _) => String::new(),
    };
    Some(format!(
        "DEM check: {}/{} fresh devices held at {} mN{agreement}",
        s.dem_check_passed,
        s.dem_check_total,
        load(at)
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
            "the design's own band from {} DEM/estimate pairs on {} devices, {} of them the check's random draws (P_max ratio {:.3}–{:.3}, coverage {:.1} %)",
            s.band.pairs,
            s.band.devices,
            s.band.random_devices,
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Recipe B's summary (2026-11-29, lists emptied): 10 of 10 check devices held at the
    /// estimate's quote, 1.90 mN; with them pooled, the rounds set the quote at 1.85 mN.
    const B: &str = r#"{"pattern": "tri-tri", "theta_deg": 10.6, "direction_deg": -18.2, "quantile": 0.95, "confidence": 0.95, "samples": 59, "pooled": 69, "resolution": 0.01, "load_at_quantile_mN": 1.8526838116, "load_at_quantile_bound_mN": 1.84097802123, "ceiling_mN": [1.89926574155, 1.89676016557], "bound_rank": 1, "min_samples_for_bound": 59, "yield_at_quantile_load": 0.9565217391304348, "yield_at_quantile_load_interval": [0.8781528506347058, 0.9909423926415002], "setting_ranks": 4, "threshold_mN": 1.91556425328, "located": [18, 60, 65, 66, 68], "dem_decided": 24, "undecided": 13, "dem_runs": 40, "dem_runs_allowed": 40, "dem_rounds": 5, "band": {"source": "design", "pairs": 35, "held_pairs": 35, "p_ratio": [0.9918770751632262, 1.0061264705769544], "mu_ratio": [0.9763444953760859, 0.9988959235520367], "centre": [0.9987158959043536, 0.991804804559621], "devices": 24, "random_devices": 10, "coverage": 0.8181818181818182}, "pairs": [], "dem_check_load_mN": 1.903125, "dem_check_load_given": false, "dem_check_passed": 10, "dem_check_total": 10, "dem_check_interval": [0.6915028921816884, 1.0], "dem_check_consistent": true, "quote_lowered_by_check": false, "dem_check_runs": [], "lowest_dem_failure": {"sample": 18, "check": false, "load_mN": 1.9164266549, "theta_offset_deg": 0.09353698, "direction_offset_deg": 0.220021119, "seed": 17224887033131677236}, "dem": true, "censored": 0, "fabrication": {"theta_offset": {"law": "uniform", "half_width_deg": 0.1}, "direction_offset": {"law": "uniform", "half_width_deg": 0.5}, "sigma_h_um": 0.0, "sphere_diameter_cv": 0.0, "p_crit_sigma_GPa": 0.0, "sample_seed": 1, "excluded_seeds": [1], "truncate_sigma": 3.0}, "curve": []}"#;

    /// A check run at the estimate's quote, away from the final quote, says where the rounds
    /// set the quote (not only "agrees"); one at the quote itself, or at a load asked for,
    /// just agrees; the band line counts its devices.
    #[test]
    fn the_check_says_where_the_rounds_set_the_quote() {
        let mut s: YieldSummary = serde_json::from_str(B).unwrap();
        assert_eq!(
            check(&s).unwrap(),
            "DEM check: 10/10 fresh devices held at 1.90 mN (the estimate's quote); with them pooled, the DEM's rounds set the quote at 1.85 mN, which the check agrees with"
        );
        s.dem_check_load_given = true;
        assert!(check(&s)
            .unwrap()
            .ends_with("held at 1.90 mN; agrees with the quote"));
        s.dem_check_load_given = false;
        s.dem_check_load_mN = s.load_at_quantile_mN;
        assert!(check(&s)
            .unwrap()
            .ends_with("held at 1.85 mN; agrees with the quote"));
        assert!(dem_work(&s).contains(
            "from 35 DEM/estimate pairs on 24 devices, 10 of them the check's random draws"
        ));
        assert!(dem_work(&s).contains("coverage 81.8 %"));
    }
}
