//! The answer of `superlube design` on a hand-made ranking (no solver, no DEM run): which DEM
//! runs are made and in which order, how the tolerance corners enter the DEM's check, and the
//! headline of a borderline answer.

use super::test_args::{design_args, SMALL_SCENE};
use super::*;
use crate::present::design_report::{dem_rows, words::answer_line};
use crate::study::design::answer::{answer, check, Check};
use crate::study::design::confirm::{confirm_jobs, to_entries};
use crate::study::design::rank::{Candidate, CornerEstimate, Score};
use crate::study::design::{DemEntry, DesignParams, DesignScene, PatternResult};
use crate::study::rows::{label, FrictionRow};
use crate::study::verdict::Verdict;
use surrogate::units::n_to_mn;

/// The scenes and parameters of a small square-tri design with the DEM (`extra` appended).
fn params(extra: &[&str]) -> (Vec<DesignScene>, DesignParams) {
    let dir = std::env::temp_dir().join(format!("superlube-answer-{}", std::process::id()));
    let flags = [
        "--load-mn",
        "0.01,0.03,0.06,0.09",
        "--confirm-loads-mn",
        "0.01,0.09",
        "--confirm",
        "3",
        "--theta-tol-deg",
        "0.1",
        "--direction-tol-deg",
        "0.5",
    ];
    prepare(&design_args(&[&SMALL_SCENE, &flags, extra], &dir)).unwrap()
}

/// A friction row at `w_mn` with μ_est `mu` and path P_max 3 GPa.
fn row(w_mn: f64, mu: f64) -> FrictionRow {
    let mut r = FrictionRow::new(
        "square-tri",
        0.0,
        0.0,
        0.0,
        w_mn * 1e-3,
        &Err(surrogate::SceneError::invalid("x", 0.0, "y")),
    );
    r.error.clear();
    r.mu_est = Some(mu);
    r.p_max_GPa = Some(3.0);
    r
}

/// A ranking of `n` designs θ = 1°, 2°, … (α 90°), each superlubric to 0.06 mN.
fn pattern(ds: &DesignScene, n: usize) -> PatternResult {
    let sc = &ds.scene;
    let ranking = (0..n)
        .map(|k| Candidate {
            pattern: ds.name.clone(),
            theta_deg: (k + 1) as f64,
            alpha_deg: 90.0,
            line_deg: 0.0,
            direction_deg: 90.0,
            corrugation_nm: 0.1,
            scan_load_mn: 0.09,
            screen_intact_to_mn: 0.09,
            reason: crate::study::design::rank::Pick::Top,
            friction: vec![row(0.01, 0.01), row(0.03, 0.01), row(0.06, 0.01)],
            corners: vec![CornerEstimate {
                theta_offset_deg: 0.1,
                direction_offset_deg: -0.5,
                row: row(0.06, 0.012),
            }],
            score: Score {
                superlubric_to_mn: 0.06,
                nominal_to_mn: 0.06,
                theta_window_deg: Some(0.1),
                direction_window_deg: Some(0.5),
                verdict: Verdict::Superlubric,
                exact: true,
                intact_to_mn: 0.06,
                mu_worst: 0.01,
                contacts: 10.0,
                seed_limits_mn: None,
                yield_to_mn: None,
                below_ladder_mn: None,
            },
        })
        .collect();
    PatternResult::of_ranking(
        ds.clone(),
        crate::study::design::symmetry_words::PairSymmetry::of_scene(sc),
        ranking,
    )
}

/// The DEM entries of every confirmation run of `pr`, each with μ_DEM `mu(entry)` (P_max 3 GPa).
fn runs(pr: &PatternResult, p: &DesignParams, mu: &dyn Fn(&DemEntry) -> f64) -> Vec<DemEntry> {
    let (_, entries) = confirm_jobs(std::slice::from_ref(pr), &p.confirm, &p.limit_knobs());
    let outcomes: Vec<_> = entries
        .iter()
        .map(|e| crate::study::batch::SlideOutcome {
            name: format!("run{}", e.rank),
            dir: std::path::PathBuf::new(),
            result: None,
            error: None,
            reused: false,
        })
        .collect();
    let mut dem = to_entries(&entries, &outcomes);
    for e in &mut dem {
        e.outcome.result = Some(crate::study::batch::SlideResult {
            friction_mN: 0.0,
            friction_std_mN: 0.0,
            mu: mu(e),
            mean_contacts: 10.0,
            max_p_max_GPa: 3.0,
            mean_failed_contacts: 0.0,
            locked_in: false,
            advance_ratio: None,
            steps: 1,
            wall_s: 0.0,
        });
    }
    dem
}

/// Every design the answer can name (the top K) has its box's corners run at its robust limit
/// load and the next load above; the runs of a borderline design go first, its corners too.
#[test]
fn borderline_designs_run_first_and_every_top_design_has_its_corners() {
    let (scenes, p) = params(&[]);
    let mut pr = pattern(&scenes[0], 4);
    pr.ranking[1].score.verdict = Verdict::Borderline;
    let (jobs, entries) = confirm_jobs(std::slice::from_ref(&pr), &p.confirm, &p.limit_knobs());
    assert_eq!(jobs.len(), entries.len());
    let ranks: Vec<usize> = entries.iter().map(|e| e.rank).collect();
    let first_other = ranks.iter().position(|&r| r != 2).unwrap();
    assert!(first_other > 0, "{ranks:?}");
    assert!(ranks[first_other..].iter().all(|&r| r != 2), "{ranks:?}");
    // rank 4 is outside --confirm 3
    assert!(!ranks.contains(&4));
    for rank in 1..=3 {
        let corners: Vec<_> = entries
            .iter()
            .filter(|e| {
                e.rank == rank && (e.theta_offset_deg != 0.0 || e.direction_offset_deg != 0.0)
            })
            .collect();
        // four corners at 0.06 mN (the limit) and four at 0.09 mN (the next load)
        assert_eq!(corners.len(), 8, "rank {rank}: {entries:?}");
        for w in [0.06, 0.09] {
            let at: Vec<_> = corners
                .iter()
                .filter(|e| label(n_to_mn(e.load)) == w)
                .collect();
            assert_eq!(at.len(), 4, "rank {rank} at {w} mN");
        }
        for e in &corners {
            assert_eq!(
                (e.theta_offset_deg.abs(), e.direction_offset_deg.abs()),
                (0.1, 0.5)
            );
            assert_eq!(e.theta_deg, label(rank as f64 + e.theta_offset_deg));
        }
    }
    // the borderline design's corners are among its first runs, before rank 1's
    let first_corner_2 = entries
        .iter()
        .position(|e| e.rank == 2 && e.theta_offset_deg != 0.0)
        .unwrap();
    let first_1 = entries.iter().position(|e| e.rank == 1).unwrap();
    assert!(first_corner_2 < first_1);
    // run names are distinct (one directory each)
    let mut names: Vec<&str> = jobs.iter().map(|j| j.name.as_str()).collect();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), jobs.len());
}

/// A design is confirmed only when its centre AND its box's corners hold at its robust limit
/// load; a failing corner is named, and the answer moves to the next design that holds.
#[test]
fn the_answer_needs_the_corners_at_the_robust_limit() {
    let (scenes, p) = params(&[]);
    let pr = pattern(&scenes[0], 3);
    // every run superlubric: rank 1 confirmed at its own loads
    let all_ok = runs(&pr, &p, &|_| 0.01);
    assert!(
        matches!(check(&pr, 1, &all_ok, &p.answer_rule()), Check::Confirmed(ref w) if w == &vec![0.01, 0.06])
    );
    // rank 1's corner (+0.1°, −0.5°) fails at its limit load: contradicted, naming the corner;
    // a corner failing only at the next load above does not count
    let corner_fails = |e: &DemEntry| {
        let at_limit = label(n_to_mn(e.run.load)) == 0.06;
        let named = e.run.theta_offset_deg == 0.1 && e.run.direction_offset_deg == -0.5;
        let fails = (named && at_limit) || (e.run.theta_offset_deg != 0.0 && !at_limit);
        if e.run.rank == 1 && fails {
            0.05
        } else {
            0.01
        }
    };
    let dem = runs(&pr, &p, &corner_fails);
    match check(&pr, 1, &dem, &p.answer_rule()) {
        Check::Contradicted(why) => {
            let why = why.to_string();
            assert!(why.contains("μ_DEM"), "{why}");
            assert!(why.contains("corner δθ = +0.1°, δdir = -0.5°"), "{why}");
        }
        c => panic!("{c:?}"),
    }
    let a = answer(&pr, &dem, true, &p.answer_rule());
    assert_eq!(a.index, Some(1), "the next design whose box holds");
    assert!(matches!(a.check, Check::Confirmed(_)));
    // only the failures above the limit: confirmed
    let above = |e: &DemEntry| {
        if e.run.rank == 1 && e.run.theta_offset_deg != 0.0 && label(n_to_mn(e.run.load)) == 0.09 {
            0.05
        } else {
            0.01
        }
    };
    assert!(matches!(
        check(&pr, 1, &runs(&pr, &p, &above), &p.answer_rule()),
        Check::Confirmed(_)
    ));
    // no corner run at all: not confirmed
    let centre_only: Vec<DemEntry> = all_ok
        .into_iter()
        .filter(|e| e.run.theta_offset_deg == 0.0 && e.run.direction_offset_deg == 0.0)
        .collect();
    assert_eq!(
        check(&pr, 1, &centre_only, &p.answer_rule()),
        Check::Unchecked
    );
    // the answer's words: the corners of the answer's own box
    let o = crate::study::design::DesignOutcome {
        patterns: vec![pr.clone()],
        dem: dem.clone(),
        dem_ran: true,
        answers: vec![a.clone()],
        maps: vec![None],
        p_crit: None,
        yields: Vec::new(),
    };
    let rows = dem_rows(&o, &p);
    let line = answer_line(&pr, &a, &rows, &p, 0.09);
    assert!(line.contains("θ = **2°**"), "{line}");
    assert!(
        line.contains("at every corner of its tolerance box at 0.06 mN"),
        "{line}"
    );
    assert!(line.contains("4 of 4 superlubric at 0.06 mN"), "{line}");
    // dem.csv's corner rows carry the search's estimate where it made one, else nothing
    for r in rows.iter().filter(|r| r.theta_offset_deg != 0.0) {
        let estimated =
            r.theta_offset_deg == 0.1 && r.direction_offset_deg == -0.5 && r.load_mN == 0.06;
        assert_eq!(r.mu_est.is_some(), estimated, "{r:?}");
        assert_eq!(r.superlubric_est.is_some(), estimated, "{r:?}");
        if estimated {
            assert_eq!(r.mu_est, Some(0.012));
            assert_eq!(r.verdicts_agree, Some(r.superlubric_dem == Some(true)));
        }
    }
}

/// A borderline answer's headline carries the qualifier: never a plain "stays superlubric".
#[test]
fn a_borderline_answer_is_never_a_plain_yes() {
    let (scenes, p) = params(&["--no-dem"]);
    let mut pr = pattern(&scenes[0], 1);
    let a = answer(&pr, &[], false, &p.answer_rule());
    let plain = answer_line(&pr, &a, &[], &p, 0.09);
    assert!(
        plain.contains("stays superlubric up to **0.06 mN**"),
        "{plain}"
    );
    assert!(!plain.contains("borderline"), "{plain}");
    pr.ranking[0].score.verdict = Verdict::Borderline;
    let line = answer_line(&pr, &a, &[], &p, 0.09);
    assert!(!line.contains("stays superlubric"), "{line}");
    let head = &line[..line.find("mN**").unwrap()];
    assert!(head.contains("**borderline** superlubric up to"), "{line}");
    assert!(line.contains("docs/validation/verdict-band.md"), "{line}");
    // superlubric at the nominal orientation only: not "superlubric nowhere"
    pr.ranking[0].score.superlubric_to_mn = 0.0;
    pr.ranking[0].score.verdict = Verdict::Not;
    let line = answer_line(&pr, &a, &[], &p, 0.09);
    assert!(!line.contains("no design is superlubric"), "{line}");
    assert!(
        line.contains("is superlubric up to 0.06 mN at its nominal orientation only"),
        "{line}"
    );
    pr.ranking[0].score.nominal_to_mn = 0.0;
    let line = answer_line(&pr, &a, &[], &p, 0.09);
    assert!(
        line.contains("no design is superlubric even at the lowest load"),
        "{line}"
    );
}
