//! Unit tests of the design pipeline's outcome and answer.

use super::answer::{Answer, Check};
use super::rank::{Candidate, Score};
use super::symmetry::PairSymmetry;
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
            reason: String::new(),
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
        check: Check::Contradicted("P_max above P_crit".into()),
        others: vec![],
    };
    // square-tri: rank 1 contradicted, rank 3 confirmed at 0.35 and 2.1 mN
    let answers = vec![
        Answer {
            index: Some(2),
            check: Check::Confirmed(vec![0.35, 2.1]),
            others: vec![(1, Check::Contradicted("x".into()))],
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
