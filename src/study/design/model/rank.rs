//! The design score and the ranking of (θ, α) candidates.
//!
//! A candidate (θ, α) is **superlubric at load W** when its friction estimate along α exists,
//! its coating is intact on the whole sliding path (the largest P_max along the path, which
//! starts at the screened placement, ≤ P_crit) and μ_est < `mu_superlubric` (0.02): the rule
//! [`crate::study::verdict::superlubric`].
//!
//! **Score**, compared in this order (with `--rank-by yield`, the top designs' load at yield q,
//! [`Score::yield_to_mn`], comes first: [`super::super::ranking::by_yield`]):
//! 1. `superlubric_to` — the highest load W_k of the list such that the candidate is
//!    superlubric at every load W_1 … W_k (0: not even at the lowest load) — with a fabrication
//!    tolerance, the **robust** limit: the lowest such load over every sample of the tolerance
//!    box ([`crate::study::tolerance::RobustSearch`]): higher is better;
//!    where it is 0, the load it holds to below the ladder's first load, when located
//!    ([`super::super::ranking::below_ladder`]): higher is better;
//! 2. `nominal_to` — the same limit at the exact (θ, α) alone: higher is better (the margin a
//!    well-made device has; it also orders designs whose robust limits are all 0);
//! 3. the window — the θ half-width, then the direction half-width, inside which the candidate
//!    stays superlubric at its nominal limit load: wider is better (0 without tolerance);
//! 4. `mu_worst` — the largest μ_est over those loads (over the lowest load alone when
//!    `superlubric_to` is 0): lower is better;
//! 5. `contacts` — the path-averaged contact number at `superlubric_to` (at the lowest load
//!    when 0): more is better (the load is spread over more asperities);
//! 6. then θ and α ascending (a fixed order for ties).
//!
//! This one order ranks the designs of a pattern, the patterns (by their rank-1 designs) and
//! picks the recommended design, so the recommended design is rank 1 wherever it is listed.
//!
//! A candidate not superlubric at the lowest load has only that load estimated
//! ([`super::super::evaluate::estimate`]); its `intact_to` then counts that load only.

use super::theta_eval::ThetaEval;
use crate::study::load::LoadKey;
use crate::study::rows::FrictionRow;
use crate::study::verdict::{intact, superlubric, Verdict};
use serde::{Deserialize, Serialize};
use std::cmp::Ordering;

/// One (θ, α) candidate of a pattern with its friction rows (one per load, ascending).
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    /// Pattern (design scene name).
    pub pattern: String,
    /// θ (degrees).
    pub theta_deg: f64,
    /// α (degrees from the contact line).
    pub alpha_deg: f64,
    /// Contact line (degrees from x).
    pub line_deg: f64,
    /// Pulling direction (degrees from x).
    pub direction_deg: f64,
    /// Corrugation along α in the scan (nm).
    pub corrugation_nm: f64,
    /// Load of the scan (mN).
    pub scan_load_mn: f64,
    /// The screen's coating-intact load W_c (mN).
    pub screen_intact_to_mn: f64,
    /// Why it was shortlisted.
    pub reason: Pick,
    /// Friction estimate per load.
    pub friction: Vec<FrictionRow>,
    /// The estimates its robust search made at the corners of its tolerance box (the design's
    /// own substrate), every load estimated there: the estimate beside a corner's DEM run.
    /// Empty without a tolerance or a search.
    pub corners: Vec<CornerEstimate>,
    /// The score.
    pub score: Score,
}

/// One friction estimate at a corner of a candidate's tolerance box.
#[derive(Debug, Clone, PartialEq)]
pub struct CornerEstimate {
    /// θ offset from the candidate (degrees).
    pub theta_offset_deg: f64,
    /// Pull-direction offset from the candidate, substrate frame (degrees).
    pub direction_offset_deg: f64,
    /// The estimate (its `load_mN` is the load).
    pub row: FrictionRow,
}

impl Candidate {
    /// The estimate at the box corner (`dt`, `dd`) (degrees) at load `w_mn` (mN), where its
    /// robust search estimated that corner at that load.
    pub fn corner_row(&self, dt: f64, dd: f64, w_mn: f64) -> Option<&FrictionRow> {
        self.corners
            .iter()
            .find(|c| {
                (c.theta_offset_deg - dt).abs() < 1e-9
                    && (c.direction_offset_deg - dd).abs() < 1e-9
                    && LoadKey::of_mn(c.row.load_mN) == LoadKey::of_mn(w_mn)
            })
            .map(|c| &c.row)
    }
}

/// The score of a candidate (see the module docs; loads in mN).
#[derive(Debug, Clone, PartialEq)]
pub struct Score {
    /// Highest load up to which the candidate is superlubric (mN; 0: none): over the whole
    /// tolerance box once [`Score::nominal_to_mn`] is set apart from it.
    pub superlubric_to_mn: f64,
    /// The same at the nominal (θ, α) alone (mN).
    pub nominal_to_mn: f64,
    /// θ half-width (degrees) inside which it stays superlubric at the nominal limit load
    /// (`None`: no tolerance, or not computed for a design outside the top of the ranking).
    pub theta_window_deg: Option<f64>,
    /// Direction half-width (degrees) inside which it stays superlubric at that load.
    pub direction_window_deg: Option<f64>,
    /// The worst verdict over every load up to `superlubric_to_mn` (and over the box's samples
    /// estimated there, with a tolerance); `Not` when that is 0.
    pub verdict: Verdict,
    /// Whether `superlubric_to_mn` is exact (else an upper bound: the robust evaluation stopped
    /// once the design could not reach the top of the ranking).
    pub exact: bool,
    /// Highest load up to which its coating is intact on the whole path (mN; 0: none).
    pub intact_to_mn: f64,
    /// Largest μ_est up to `superlubric_to` (at the lowest load when that is 0).
    pub mu_worst: f64,
    /// Path-averaged contacts at `superlubric_to` (at the lowest load when 0).
    pub contacts: f64,
    /// With several substrate seeds, each seed's own limit at the nominal (θ, α) (mN, seed
    /// order): the spread behind the worst case. `None`: one substrate, or not computed.
    pub seed_limits_mn: Option<Vec<f64>>,
    /// With `--rank-by yield`, for the top designs: the load (mN) at least a fraction q of
    /// fabricated devices hold with confidence γ by the estimate (the quoted load itself
    /// where the devices are too few for a bound; [`super::super::ranking::by_yield`]). It orders before
    /// everything else; `None`: not computed.
    pub yield_to_mn: Option<f64>,
    /// Where the robust limit is 0 (not even the ladder's first load holds over the box): the
    /// load (mN) it holds to below the first load, located by bisection down to a floor
    /// ([`super::super::ranking::below_ladder`]; `Some(0.0)`: below the floor). Orders right after the robust
    /// limit; `None`: not searched.
    pub below_ladder_mn: Option<f64>,
}

/// The score of the rows of one (θ, α), loads ascending.
pub fn score(rows: &[FrictionRow], p_crit: f64, mu_sl: f64) -> Score {
    let prefix = |ok: &dyn Fn(&FrictionRow) -> bool| rows.iter().take_while(|r| ok(r)).count();
    let n_sl = prefix(&|r| superlubric(r, p_crit, mu_sl));
    let n_in = prefix(&|r| intact(r, p_crit));
    let load = |n: usize| if n == 0 { 0.0 } else { rows[n - 1].load_mN };
    let upto = &rows[..n_sl.max(1).min(rows.len())];
    Score {
        superlubric_to_mn: load(n_sl),
        nominal_to_mn: load(n_sl),
        // the nominal point alone (no tolerance): its window is 0 by definition; the robust
        // stage replaces these where the box is wider
        theta_window_deg: Some(0.0),
        direction_window_deg: Some(0.0),
        verdict: Verdict::worst(&rows[..n_sl], mu_sl, p_crit),
        exact: true,
        intact_to_mn: load(n_in),
        mu_worst: upto
            .iter()
            .map(|r| r.mu_est.unwrap_or(f64::INFINITY))
            .fold(f64::NEG_INFINITY, f64::max),
        contacts: upto.last().and_then(|r| r.contacts_mean).unwrap_or(0.0),
        seed_limits_mn: None,
        yield_to_mn: None,
        below_ladder_mn: None,
    }
}

/// Why an orientation was shortlisted (`crate::present` words it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pick {
    /// It survives the highest load (the top level).
    Top,
    /// One of the best of a lower level, of load `W_c` (N).
    Level(f64),
}

/// The candidates of one orientation's evaluation.
pub fn candidates(
    pattern: &str,
    ev: &ThetaEval,
    screen_intact_to_mn: f64,
    reason: Pick,
    p_crit: f64,
    mu_sl: f64,
) -> Vec<Candidate> {
    ev.alphas_deg
        .iter()
        .map(|&a| {
            let rows: Vec<FrictionRow> = ev
                .friction
                .iter()
                .filter(|r| r.alpha_deg == a)
                .cloned()
                .collect();
            (a, rows)
        })
        .map(|(a, rows)| Candidate {
            pattern: pattern.to_string(),
            theta_deg: ev.theta_deg,
            alpha_deg: a,
            line_deg: ev.line_deg,
            direction_deg: rows.first().map_or(ev.line_deg + a, |r| r.direction_deg),
            corrugation_nm: ev
                .scan
                .iter()
                .find(|r| (r.alpha_deg - a).abs() < 1e-9)
                .map_or(f64::NAN, |r| r.corrugation_nm),
            scan_load_mn: ev.scan_load_mN,
            screen_intact_to_mn,
            reason,
            score: score(&rows, p_crit, mu_sl),
            friction: rows,
            corners: Vec::new(),
        })
        .collect()
}

/// A window for the ordering (not computed: 0).
fn window(w: Option<f64>) -> f64 {
    w.unwrap_or(0.0)
}

/// Ranking group: exact robust limits above zero first, then upper bounds (designs whose
/// evaluation stopped below the top), then those superlubric nowhere.
fn group(exact: bool, superlubric_to_mn: f64) -> u8 {
    match (exact, superlubric_to_mn > 0.0) {
        (true, true) => 0,
        (false, _) => 1,
        (true, false) => 2,
    }
}

/// What the ranking order compares of a candidate (the module docs' score, in order): its
/// load at yield q where computed, its group, limit, nominal limit, windows, μ, contacts,
/// then θ and α: the one tie rule of every table that lists designs or patterns. [`compare`] orders candidates by it; the
/// robust search orders by it the best score each candidate could still reach
/// ([`Key::reachable`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Key {
    /// [`Score::yield_to_mn`] (−∞: not computed).
    yield_to_mn: f64,
    group: u8,
    superlubric_to_mn: f64,
    below_ladder_mn: f64,
    nominal_to_mn: f64,
    theta_window_deg: f64,
    direction_window_deg: f64,
    mu_worst: f64,
    contacts: f64,
    theta_deg: f64,
    alpha_deg: f64,
}

impl Key {
    /// The key of `c` as scored.
    pub fn of(c: &Candidate) -> Key {
        let s = &c.score;
        Key {
            yield_to_mn: s.yield_to_mn.unwrap_or(f64::NEG_INFINITY),
            group: group(s.exact, s.superlubric_to_mn),
            superlubric_to_mn: s.superlubric_to_mn,
            below_ladder_mn: s.below_ladder_mn.unwrap_or(0.0),
            nominal_to_mn: s.nominal_to_mn,
            theta_window_deg: window(s.theta_window_deg),
            direction_window_deg: window(s.direction_window_deg),
            mu_worst: s.mu_worst,
            contacts: s.contacts,
            theta_deg: c.theta_deg,
            alpha_deg: c.alpha_deg,
        }
    }

    /// The key `c` would have with the limit `superlubric_to_mn` (mN, taken as exact) and the
    /// windows given (degrees), its μ and contacts unchanged: the best score a robust search
    /// still allows it.
    pub fn reachable(
        c: &Candidate,
        superlubric_to_mn: f64,
        theta_window_deg: f64,
        direction_window_deg: f64,
    ) -> Key {
        Key {
            group: group(true, superlubric_to_mn),
            superlubric_to_mn,
            theta_window_deg,
            direction_window_deg,
            ..Key::of(c)
        }
    }

    /// The ranking order of two keys (best first).
    pub fn order(&self, o: &Key) -> Ordering {
        o.yield_to_mn
            .total_cmp(&self.yield_to_mn)
            .then(self.group.cmp(&o.group))
            .then(o.superlubric_to_mn.total_cmp(&self.superlubric_to_mn))
            .then(o.below_ladder_mn.total_cmp(&self.below_ladder_mn))
            .then(o.nominal_to_mn.total_cmp(&self.nominal_to_mn))
            .then(o.theta_window_deg.total_cmp(&self.theta_window_deg))
            .then(o.direction_window_deg.total_cmp(&self.direction_window_deg))
            .then(self.mu_worst.total_cmp(&o.mu_worst))
            .then(o.contacts.total_cmp(&self.contacts))
            .then(self.theta_deg.total_cmp(&o.theta_deg))
            .then(self.alpha_deg.total_cmp(&o.alpha_deg))
    }
}

/// The ranking order (best first).
pub fn compare(a: &Candidate, b: &Candidate) -> Ordering {
    Key::of(a).order(&Key::of(b))
}

/// Candidates of `ranking` with a load whose failed contacts sit on a mount in resonance (the
/// report's resonance note). Cost: one pass over the friction rows.
pub fn resonance_flagged(ranking: &[Candidate]) -> usize {
    ranking
        .iter()
        .filter(|c| c.friction.iter().any(|r| r.mount_resonance == Some(true)))
        .count()
}

/// One row of `ranking.csv`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct RankingRow {
    /// Rank within the pattern (1 = best design).
    pub rank: usize,
    /// Pattern (design scene name).
    pub pattern: String,
    /// θ (degrees).
    pub theta_deg: f64,
    /// α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Contact line (degrees from x).
    pub line_deg: f64,
    /// Pulling direction (degrees from x).
    pub direction_deg: f64,
    /// θ tolerance of the design (degrees; `--theta-tol-deg`).
    pub theta_tol_deg: f64,
    /// Pulling-direction tolerance (degrees; `--direction-tol-deg`).
    pub direction_tol_deg: f64,
    /// Robust limit: highest load up to which superlubric (coating intact on the path and
    /// μ_est < the limit at every load up to it) at every sample of the tolerance box and every
    /// seed (mN; 0: none). Equal to the nominal with zero tolerances.
    pub superlubric_to_mN: f64,
    /// The same at the nominal (θ, α) alone (mN).
    pub superlubric_to_nominal_mN: f64,
    /// θ half-width (degrees) around the nominal inside which every sample on the θ axis (the
    /// nominal direction) is superlubric at every load up to `superlubric_to_nominal_mN`
    /// (sampled out to `theta_tol_deg`: equal to it means "at least"). 0 with a zero tolerance;
    /// empty for designs below the exact top of the ranking other than the nominal optimum (not
    /// computed).
    pub theta_window_deg: Option<f64>,
    /// The same along the pulling-direction axis (degrees; at most `direction_tol_deg`).
    pub direction_window_deg: Option<f64>,
    /// The worst verdict over every load up to `superlubric_to_mN` and every sample of the box
    /// estimated there: superlubric, borderline (within the estimate's measured uncertainty of
    /// the μ or P_crit threshold) or not (also when `superlubric_to_mN` is 0).
    pub verdict: String,
    /// Whether `superlubric_to_mN` is exact; `false`: an upper bound (the robust evaluation
    /// stops once a design cannot reach the designs ranked above it, which are exact).
    pub robust_exact: bool,
    /// With `--seeds`, each seed's own limit at the nominal (θ, α), `;`-separated in seed
    /// order (mN): the spread behind `superlubric_to_mN`, the worst case. Empty with one
    /// substrate, and where not computed (as the windows).
    pub superlubric_to_seeds_mN: String,
    /// Largest μ_est up to `superlubric_to_mN` (at the lowest load when that is 0).
    pub mu_worst: f64,
    /// Path-averaged contacts at `superlubric_to_mN`.
    pub contacts_mean: f64,
    /// Highest load up to which the coating is intact on the whole path (mN).
    pub coating_intact_to_mN: f64,
    /// The screen's coating-intact load at the screened placement (mN).
    pub screen_intact_to_mN: f64,
    /// μ_est at the lowest load.
    pub mu_est_lowest: Option<f64>,
    /// Corrugation along α in the scan (nm).
    pub corrugation_nm: f64,
    /// Load of the scan (mN).
    pub scan_load_mN: f64,
    /// Why the orientation was shortlisted.
    pub shortlist: String,
}

impl RankingRow {
    /// The row of `c` at rank `rank` (tolerances in degrees).
    pub fn new(rank: usize, c: &Candidate, tol: (f64, f64), shortlist: String) -> RankingRow {
        RankingRow {
            rank,
            pattern: c.pattern.clone(),
            theta_deg: c.theta_deg,
            alpha_deg: c.alpha_deg,
            line_deg: c.line_deg,
            direction_deg: c.direction_deg,
            theta_tol_deg: tol.0,
            direction_tol_deg: tol.1,
            superlubric_to_mN: c.score.superlubric_to_mn,
            superlubric_to_nominal_mN: c.score.nominal_to_mn,
            theta_window_deg: c.score.theta_window_deg,
            direction_window_deg: c.score.direction_window_deg,
            verdict: c.score.verdict.to_string(),
            robust_exact: c.score.exact,
            superlubric_to_seeds_mN: c.score.seed_limits_mn.as_ref().map_or(String::new(), |v| {
                v.iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join(";")
            }),
            mu_worst: c.score.mu_worst,
            contacts_mean: c.score.contacts,
            coating_intact_to_mN: c.score.intact_to_mn,
            screen_intact_to_mN: c.screen_intact_to_mn,
            mu_est_lowest: c.friction.first().and_then(|r| r.mu_est),
            corrugation_nm: c.corrugation_nm,
            scan_load_mN: c.scan_load_mn,
            shortlist,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fr(w: f64, mu: f64, p: f64) -> FrictionRow {
        let mut r = FrictionRow::new(
            "x",
            0.0,
            0.0,
            0.0,
            w * 1e-3,
            &Err(surrogate::SceneError::invalid("x", 0.0, "y")),
        );
        r.error.clear();
        r.mu_est = Some(mu);
        r.p_max_GPa = Some(p);
        r.contacts_mean = Some(100.0 * w);
        r
    }

    #[test]
    fn score_is_the_superlubric_prefix() {
        let rows = vec![
            fr(1.0, 0.011, 3.0),
            fr(2.0, 0.015, 3.5),
            fr(3.0, 0.012, 4.1),
            fr(4.0, 0.010, 3.9),
        ];
        let s = score(&rows, 4e9, 0.02);
        assert_eq!(s.superlubric_to_mn, 2.0);
        assert_eq!(s.intact_to_mn, 2.0);
        assert_eq!(s.mu_worst, 0.015);
        assert_eq!(s.contacts, 200.0);
        assert_eq!(s.verdict, Verdict::Superlubric);
        let rows = vec![fr(1.0, 0.03, 3.0), fr(2.0, 0.01, 3.0)];
        let s = score(&rows, 4e9, 0.02);
        assert_eq!((s.superlubric_to_mn, s.intact_to_mn), (0.0, 2.0));
        assert_eq!(s.mu_worst, 0.03);
        assert_eq!(s.verdict, Verdict::Not);
    }

    /// A load below the limit inside the μ band makes the limit borderline, though the limit
    /// load itself is clear of both bands.
    #[test]
    fn the_verdict_is_the_worst_over_every_load_up_to_the_limit() {
        let rows = vec![
            fr(1.0, 0.011, 3.0),
            fr(2.0, 0.018, 3.0),
            fr(3.0, 0.010, 3.0),
            fr(4.0, 0.030, 3.0),
        ];
        assert_eq!(
            Verdict::of_row(&rows[2], 0.02, 4e9),
            Verdict::Superlubric,
            "the limit load alone is clear"
        );
        let s = score(&rows, 4e9, 0.02);
        assert_eq!(s.superlubric_to_mn, 3.0);
        assert_eq!(s.verdict, Verdict::Borderline);
        // a P_max inside the band at the lowest load counts too; rows past the limit do not
        let rows = vec![fr(1.0, 0.011, 3.9), fr(2.0, 0.010, 3.0), fr(3.0, 0.05, 5.0)];
        let s = score(&rows, 4e9, 0.02);
        assert_eq!((s.superlubric_to_mn, s.verdict), (2.0, Verdict::Borderline));
        let rows = [
            fr(1.0, 0.011, 3.0),
            fr(2.0, 0.010, 3.0),
            fr(3.0, 0.019, 3.0),
        ];
        let s = score(&rows[..2], 4e9, 0.02);
        assert_eq!(s.verdict, Verdict::Superlubric);
    }
}
