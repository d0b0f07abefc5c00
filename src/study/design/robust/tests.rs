//! Unit tests of the robust search: its best-first order, and the stage on a small scene.

use crate::study::design::model::fixtures::pattern;
use crate::study::design::model::rank::{compare, Candidate, Key};

/// The robust search's best-first order is the ranking's: a reachable key with the scored
/// limit and windows orders as the scored candidates do, and a higher bound goes first.
#[test]
fn the_robust_order_is_the_ranking_order() {
    let mut r = pattern("tri-tri", 4).ranking;
    r[1].score.superlubric_to_mn = 2.1;
    r[2].score.mu_worst = 0.005;
    r[3].score.superlubric_to_mn = 0.0;
    for c in &mut r {
        c.score.theta_window_deg = Some(0.1);
        c.score.direction_window_deg = Some(0.5);
    }
    let key = |c: &Candidate| Key::reachable(c, c.score.superlubric_to_mn, 0.1, 0.5);
    for a in &r {
        for b in &r {
            assert_eq!(key(a).order(&key(b)), compare(a, b), "{a:?} vs {b:?}");
        }
    }
    let mut by_key: Vec<&Candidate> = r.iter().collect();
    by_key.sort_by(|a, b| key(a).order(&key(b)));
    let thetas: Vec<f64> = by_key.iter().map(|c| c.theta_deg).collect();
    assert_eq!(thetas, vec![2.0, 0.0, 1.0, 3.0]);
}

/// On a small design with a tolerance the stage makes the best designs exact, each robust
/// limit at most its nominal one; above a floor no candidate can reach, nothing is searched
/// and every candidate keeps its nominal limit as an upper bound.
#[test]
fn the_stage_makes_the_best_exact_and_leaves_the_floored_unsearched() {
    use crate::study::design::pipeline::{Pipeline, Search};
    use crate::study::design::robust::RobustParams;
    use crate::study::design::store::Store;
    use crate::study::design::test_design::{out_dir, small_params, small_scene, Record};
    let p = small_params(0.1, true);
    let ds = small_scene("tri-tri");
    let dir = out_dir("robust-stage");
    let store = Store::new(&dir);
    let rec = Record::default();
    let search = |floor_mn| Search::Robust(RobustParams { floor_mn, keep: 3 });
    let pr = Pipeline::new(&p, &store, &rec)
        .pattern(&ds, search(0.0))
        .unwrap();
    let r = &pr.ranking;
    assert!(r[0].score.nominal_to_mn > 0.0, "{:?}", r[0]);
    assert!(r[0].score.exact && r[0].score.theta_window_deg.is_some());
    assert!(r
        .iter()
        .all(|c| c.score.superlubric_to_mn <= c.score.nominal_to_mn));
    assert!(rec.names().contains(&"robust-done"), "{:?}", rec.names());
    // a floor above every nominal limit: no search, upper bounds only
    let rec = Record::default();
    let pr = Pipeline::new(&p, &store, &rec)
        .pattern(&ds, search(1e6))
        .unwrap();
    assert!(!rec.names().contains(&"robust"), "{:?}", rec.names());
    for c in pr.ranking.iter().filter(|c| c.score.nominal_to_mn > 0.0) {
        assert!(
            !c.score.exact && c.score.theta_window_deg.is_none(),
            "{c:?}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
