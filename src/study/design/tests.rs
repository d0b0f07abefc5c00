//! Unit tests of the design pipeline's outcome and answer.

use super::answer::{Answer, Check};
use super::rank::{Candidate, Score};
use super::symmetry_words::PairSymmetry;
use super::*;

fn pattern(name: &str, n: usize) -> PatternResult {
    let scene = surrogate::Scene::preset(name).unwrap();
    let sym = PairSymmetry::of(&scene.slider.lattice, &scene.substrate.lattice);
    let ranking = (0..n)
        .map(|k| Candidate {
            pattern: name.into(),
            theta_deg: k as f64,
            alpha_deg: 90.0,
            line_deg: 0.0,
            direction_deg: 90.0,
            corrugation_nm: 0.1,
            scan_load_mn: 3.86,
            screen_intact_to_mn: 3.86,
            reason: super::rank::Pick::Top,
            friction: vec![],
            corners: vec![],
            score: Score {
                superlubric_to_mn: 3.86,
                nominal_to_mn: 3.86,
                theta_window_deg: None,
                direction_window_deg: None,
                verdict: crate::study::verdict::Verdict::Superlubric,
                exact: true,
                intact_to_mn: 3.86,
                mu_worst: 0.01,
                contacts: 100.0,
                seed_limits_mn: None,
                yield_to_mn: None,
                below_ladder_mn: None,
            },
        })
        .collect();
    PatternResult::of_ranking(
        DesignScene {
            name: name.into(),
            scene,
            flags: vec![],
            warnings: vec![],
            facts: None,
            recipe: None,
        },
        sym,
        ranking,
    )
}

/// A design is confirmed at the confirmation loads and at its own superlubric load (once,
/// in order); a design superlubric nowhere only at the confirmation loads.
#[test]
fn each_design_is_also_confirmed_at_its_own_limit() {
    let loads = [0.35e-3, 1.75e-3, 2.1e-3, 2.45e-3, 3.86e-3];
    let confirm = [0.35e-3, 2.1e-3, 3.86e-3];
    let mut c = pattern("tri-tri", 1).ranking.remove(0);
    c.score.superlubric_to_mn = 2.45;
    assert_eq!(
        loads_to_confirm(&c, &confirm, &loads),
        vec![0.35e-3, 2.1e-3, 2.45e-3, 3.86e-3]
    );
    c.score.superlubric_to_mn = 2.1;
    assert_eq!(loads_to_confirm(&c, &confirm, &loads), confirm.to_vec());
    c.score.superlubric_to_mn = 0.0;
    assert_eq!(loads_to_confirm(&c, &confirm, &loads), confirm.to_vec());
}

/// The study-protocol check runs on the recommended design: the first *confirmed* answer
/// (not the estimate's rank 1, which the DEM may contradict), at the middle of its confirmed
/// loads; without a confirmed answer, the first pattern's answer at the middle load.
#[test]
fn protocol_check_runs_on_the_recommended_design() {
    let pats = vec![pattern("square-tri", 3), pattern("tri-tri", 3)];
    let loads = [0.35e-3, 2.1e-3, 3.86e-3];
    let contradicted = Answer {
        index: Some(0),
        check: Check::Contradicted(super::answer::Contradiction {
            why: "P_max above P_crit".into(),
            corner: None,
        }),
        others: vec![],
    };
    // square-tri: rank 1 contradicted, rank 3 confirmed at 0.35 and 2.1 mN
    let answers = vec![
        Answer {
            index: Some(2),
            check: Check::Confirmed(vec![0.35, 2.1]),
            others: vec![(
                1,
                Check::Contradicted(super::answer::Contradiction {
                    why: "x".into(),
                    corner: None,
                }),
            )],
        },
        contradicted.clone(),
    ];
    let ProtocolCheck {
        pattern: pr,
        index: i,
        load: w,
    } = protocol_check_design(&pats, &answers, &loads).unwrap();
    assert_eq!((pr.scene.name.as_str(), i, w), ("square-tri", 2, 2.1e-3));
    // the first pattern unconfirmed, the second confirmed at one load: the second
    let answers = vec![
        contradicted.clone(),
        Answer {
            index: Some(1),
            check: Check::Confirmed(vec![0.35]),
            others: vec![],
        },
    ];
    let ProtocolCheck {
        pattern: pr,
        index: i,
        load: w,
    } = protocol_check_design(&pats, &answers, &loads).unwrap();
    assert_eq!((pr.scene.name.as_str(), i, w), ("tri-tri", 1, 0.35e-3));
    // none confirmed: the first pattern's answer at the middle confirmation load
    let answers = vec![contradicted.clone(), contradicted];
    let ProtocolCheck {
        pattern: pr,
        index: i,
        load: w,
    } = protocol_check_design(&pats, &answers, &loads).unwrap();
    assert_eq!((pr.scene.name.as_str(), i, w), ("square-tri", 0, 2.1e-3));
    // no ranked design at all
    let none = Answer {
        index: None,
        check: Check::Unchecked,
        others: vec![],
    };
    assert!(protocol_check_design(&pats, &[none.clone(), none], &loads).is_none());
}

/// The level walk stops at the first level below the best exact limit once the ranking holds
/// the designs it needs, never before; a floor skips a level that cannot exceed it.
#[test]
fn the_level_walk_stops_below_the_best_limit_and_skips_under_the_floor() {
    use super::walk::{LevelWalk, Next};
    let level = surrogate::units::mn_to_n;
    let mut ranking = pattern("tri-tri", 3).ranking;
    for c in &mut ranking {
        c.score.superlubric_to_mn = 2.1;
    }
    let no_reach = || -> anyhow::Result<f64> { panic!("reach asked without a floor") };
    // no floor: 3.86 and 2.1 are taken, 1.4 < 2.1 stops the walk
    let mut w = LevelWalk::new(3, 0.0, true);
    assert_eq!(
        w.next(0, level(3.86), &[], no_reach).unwrap(),
        Next::Evaluate
    );
    w.evaluated(&ranking);
    assert_eq!(
        w.next(1, level(2.1), &ranking, no_reach).unwrap(),
        Next::Evaluate
    );
    assert_eq!(
        w.next(2, level(1.4), &ranking, no_reach).unwrap(),
        Next::Stop
    );
    let end = w.end();
    assert_eq!((end.taken, end.skipped.len()), (2, 0));
    assert!(
        matches!(end.stop, Stop::Before { reach_mn, best_mn, .. } if reach_mn == 1.4 && best_mn == 2.1)
    );
    // too few designs: the walk goes on below the best limit
    let mut w = LevelWalk::new(4, 0.0, true);
    w.evaluated(&ranking);
    assert_eq!(
        w.next(0, level(1.4), &ranking, no_reach).unwrap(),
        Next::Evaluate
    );
    // a floor of 2.45 mN: a 3.86 mN level whose reach is 2.1 mN is skipped (the nominal best,
    // 3.86 mN, is above it)
    let mut w = LevelWalk::new(3, 2.45, true);
    let mut top = ranking.clone();
    top[0].score.nominal_to_mn = 4.0;
    assert_eq!(
        w.next(0, level(3.86), &top, || Ok(2.1)).unwrap(),
        Next::Skip
    );
    assert_eq!(
        w.next(1, level(3.86), &top, || Ok(3.0)).unwrap(),
        Next::Evaluate
    );
    let end = w.end();
    assert_eq!((end.taken, end.skipped), (2, vec![0]));
    // without a robust search the floor is not applied
    let mut w = LevelWalk::new(3, 2.45, false);
    assert_eq!(
        w.next(0, level(3.86), &top, no_reach).unwrap(),
        Next::Evaluate
    );
}

/// The robust search's best-first order is the ranking's: a reachable key with the scored
/// limit and windows orders as the scored candidates do, and a higher bound goes first.
#[test]
fn the_robust_order_is_the_ranking_order() {
    use super::rank::{compare, Key};
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
