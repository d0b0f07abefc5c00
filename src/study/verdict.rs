//! The verdict of one friction estimate (θ, α, W): superlubric, borderline or not.
//!
//! The estimate's own rule ([`superlubric`], here: the one rule of the screen's scan, the
//! ranking, the tolerance search, the answer and the report) is a yes/no on two thresholds:
//! μ_est < μ_sl (0.02) and the path's largest P_max ≤ P_crit ([`intact`]). The verdict widens each
//! threshold by the estimate's measured error against the DEM, so that a row the DEM could place
//! on the other side of a threshold is called **borderline**, never a plain yes:
//!
//! - μ: μ_est/μ_DEM measured 0.83–1.10 over the 14 configurations of the 17-run DEM comparison
//!   that are off the springs mount's resonance ([`MU_RATIO`]);
//! - P_max: the DEM's largest P_max (every step) over the estimate's path P_max measured
//!   0.962–1.048 over the 10 runs of that table that slide smoothly ([`P_RATIO`]).
//!
//! superlubric ⇔ μ_est/0.83 < μ_sl and 1.048·P_max ≤ P_crit;
//! not ⇔ no estimate, or μ_est/1.10 ≥ μ_sl, or 0.962·P_max > P_crit; borderline otherwise.
//! With the study's thresholds: superlubric needs μ_est < 0.0166 and P_max ≤ 3.82 GPa; not is
//! μ_est ≥ 0.022 or P_max > 4.16 GPa. The measurement: docs/validation/verdict-band.md.
//! Cost: a few comparisons.

use super::batch::SlideResult;
pub use super::rows::verdict::{band_words, Verdict, MU_RATIO, P_RATIO};
use super::rows::FrictionRow;
use surrogate::units::pa_to_gpa;

/// Whether a friction row's coating is intact on its whole path: no error and the path's
/// largest P_max ≤ `p_crit` (Pa). Cost: a comparison.
pub fn intact(r: &FrictionRow, p_crit: f64) -> bool {
    r.error.is_empty() && r.p_max_GPa.is_some_and(|p| p <= pa_to_gpa(p_crit))
}

/// The estimate's yes/no rule: a friction row is **superlubric** when its coating is intact on
/// the whole path ([`intact`]) and μ_est < `mu_sl`. No band (the [`Verdict`] adds it). Cost: a
/// few comparisons.
pub fn superlubric(r: &FrictionRow, p_crit: f64, mu_sl: f64) -> bool {
    intact(r, p_crit) && r.mu_est.is_some_and(|m| m < mu_sl)
}

/// The DEM's verdict on one slide run at `load_mn` (mN; for the words): `Ok` when it completed
/// (`result`), did not lock in, kept every contact at or below P_crit (`p_crit`, Pa) at every
/// step and measured μ_DEM < `mu_sl`; else why not (`error`: why the run failed). No band: the
/// DEM is the reference. The one rule behind the design's answer and `dem.csv`'s
/// `superlubric_dem`. Cost: a few comparisons.
pub fn dem_superlubric(
    result: Option<&SlideResult>,
    error: Option<&str>,
    load_mn: f64,
    p_crit: f64,
    mu_sl: f64,
) -> Result<(), String> {
    let w = load_mn;
    match (result, error) {
        (Some(r), _) if r.locked_in => Err(format!("locked in at {w} mN")),
        (Some(r), _) if r.max_p_max_GPa.is_nan() || r.max_p_max_GPa > pa_to_gpa(p_crit) => {
            Err(format!(
                "P_max {:.3} GPa > P_crit at {w} mN (coating failed)",
                r.max_p_max_GPa
            ))
        }
        (Some(r), _) if r.mu.is_nan() || r.mu >= mu_sl => {
            Err(format!("μ_DEM = {:.4} at {w} mN", r.mu))
        }
        (Some(_), _) => Ok(()),
        (None, Some(err)) => Err(format!("the DEM run at {w} mN failed: {err}")),
        (None, None) => Err(format!("no DEM result at {w} mN")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_split_the_thresholds() {
        let v = |mu: f64, p_gpa: f64| Verdict::of(Some(mu), Some(p_gpa * 1e9), 0.02, 4e9);
        assert_eq!(v(0.010, 3.0), Verdict::Superlubric);
        assert_eq!(v(0.0165, 3.8), Verdict::Superlubric);
        // μ within the band on either side of 0.02
        assert_eq!(v(0.0170, 3.0), Verdict::Borderline);
        assert_eq!(v(0.0211, 3.0), Verdict::Borderline);
        assert_eq!(v(0.0221, 3.0), Verdict::Not);
        // P_max within the band on either side of 4 GPa
        assert_eq!(v(0.010, 3.9), Verdict::Borderline);
        assert_eq!(v(0.010, 4.1), Verdict::Borderline);
        assert_eq!(v(0.010, 4.2), Verdict::Not);
        assert_eq!(Verdict::of(None, Some(1e9), 0.02, 4e9), Verdict::Not);
        assert_eq!(Verdict::Borderline.to_string(), "borderline");
    }

    /// A judged row's CSV is the unjudged row's, byte for byte, with one `verdict` column
    /// before `error`; its verdict is [`Verdict::of_row`]'s; JSON without a verdict has no key.
    #[test]
    fn a_judged_row_adds_only_its_verdict_column() {
        let row = |mu: f64, p: f64| {
            let mut r = FrictionRow::new(
                "square-tri",
                0.1,
                0.2,
                0.3,
                1e-3,
                &Err(surrogate::SceneError::invalid("x", 0.0, "y")),
            );
            r.error.clear();
            r.mu_est = Some(mu);
            r.p_max_GPa = Some(p);
            r
        };
        let plain = vec![row(0.010, 3.0), row(0.018, 3.0), row(0.03, 3.0)];
        let judged: Vec<FrictionRow> = plain.iter().map(|r| r.clone().judged(0.02, 4e9)).collect();
        let words: Vec<Verdict> = judged.iter().map(|r| r.verdict.unwrap()).collect();
        assert_eq!(
            words,
            vec![Verdict::Superlubric, Verdict::Borderline, Verdict::Not]
        );
        for (a, b) in plain.iter().zip(&judged) {
            assert_eq!(Some(Verdict::of_row(a, 0.02, 4e9)), b.verdict);
        }
        let text = |rows: &[FrictionRow]| {
            String::from_utf8(crate::runs::sink::csv_bytes(rows).unwrap()).unwrap()
        };
        let (before, after) = (text(&plain), text(&judged));
        let header: Vec<&str> = after.lines().next().unwrap().split(',').collect();
        let k = header.iter().position(|c| *c == "verdict").unwrap();
        assert_eq!(header[k + 1], "error");
        assert_eq!(header.len(), k + 2);
        let dropped: String = after
            .lines()
            .map(|l| {
                let mut v: Vec<&str> = l.split(',').collect();
                v.remove(k);
                v.join(",") + "\n"
            })
            .collect();
        assert_eq!(dropped, before);
        assert!(after.contains(",superlubric,\n") && after.contains(",borderline,\n"));
        assert!(!serde_json::to_string(&plain[0])
            .unwrap()
            .contains("verdict"));
    }

    #[test]
    fn a_dem_run_is_superlubric_only_below_every_threshold() {
        let run = |mu: f64, p_gpa: f64, locked_in: bool| SlideResult {
            friction_mN: 0.0,
            friction_std_mN: 0.0,
            mu,
            mean_contacts: 3.0,
            max_p_max_GPa: p_gpa,
            mean_failed_contacts: 0.0,
            locked_in,
            advance_ratio: None,
            steps: 1,
            wall_s: 0.0,
        };
        let v = |r: &SlideResult| dem_superlubric(Some(r), None, 0.09, 4e9, 0.02);
        assert_eq!(v(&run(0.0199, 4.0, false)), Ok(()));
        assert!(v(&run(0.0200, 3.0, false)).unwrap_err().contains("μ_DEM"));
        assert!(v(&run(0.01, 4.01, false)).unwrap_err().contains("P_crit"));
        assert!(v(&run(0.01, 3.0, true)).unwrap_err().contains("locked in"));
        assert!(v(&run(f64::NAN, 3.0, false)).is_err());
        let failed = dem_superlubric(None, Some("blew up"), 0.09, 4e9, 0.02);
        assert!(failed.unwrap_err().contains("failed: blew up"));
    }
}
