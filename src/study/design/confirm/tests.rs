//! Unit tests of the DEM confirmation: which loads and design the runs take, and the stage
//! itself on a tiny design with an oracle in place of the DEM.

use super::*;
use crate::study::design::model::fixtures::pattern;
use crate::study::design::model::{Answer, Check, Contradiction};

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
        check: Check::Contradicted(Contradiction {
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
                Check::Contradicted(Contradiction {
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

/// The stage runs the confirmation's jobs as one batch on its threads through the runner,
/// then — the protocol shorter than the study's — the recommended design once with the
/// study's protocol, alone, at the middle of its confirmed loads; without the DEM it asks for
/// nothing and adds no estimate.
#[test]
fn the_stage_runs_one_batch_then_the_protocol_check_through_the_runner() {
    use crate::study::design::limit::{LimitKnobs, ToleranceParams};
    use crate::study::design::stage_env::StageEnv;
    use crate::study::design::store::Store;
    use crate::study::design::test_design::{out_dir, Oracle, Record};
    let loads = [0.35e-3, 2.1e-3, 3.86e-3];
    let limit = LimitKnobs {
        loads: crate::study::load::Loads::new(loads.to_vec()),
        mu_superlubric: 0.02,
        line: None,
        friction: surrogate::friction::FrictionParams::default(),
        tolerance: ToleranceParams {
            theta_tol_deg: 0.0,
            direction_tol_deg: 0.0,
            theta_tol_step_deg: 0.05,
            direction_tol_step_deg: 0.25,
            seeds: vec![],
        },
    };
    let mut cp = ConfirmParams {
        designs: 2,
        loads: loads.to_vec(),
        no_dem: false,
        jobs: 2,
        dem_shard: crate::runs::shard::Shard::ALL,
        dem: crate::study::design::test_design::dem_params(),
        dem_is_study_protocol: false,
        protocol_check: true,
    };
    let dir = out_dir("confirm-stage");
    let store = Store::new(&dir);
    let rec = Record::default();
    let env = StageEnv {
        limit: &limit,
        store: &store,
        obs: &rec,
    };
    let pats = vec![pattern("tri-tri", 3)];
    let oracle = Oracle::new(0.005);
    let dem = ConfirmStage::new(env, &cp, &oracle).run(&pats).unwrap();
    let batches = oracle.batches.lock().unwrap().clone();
    // 2 designs × 3 loads side by side, then the check alone
    assert_eq!(batches.len(), 2, "{batches:?}");
    assert_eq!((batches[0].0.len(), batches[0].1), (6, 2));
    assert_eq!(batches[1].0.len(), 1);
    assert_eq!(batches[1].1, 1);
    assert!(batches[1].0[0].ends_with("_study-protocol"), "{batches:?}");
    assert_eq!(dem.len(), 7);
    let check = &dem[6].run;
    assert_eq!(check.protocol, DemProtocol::Study);
    assert_eq!((check.rank, check.load), (1, 2.1e-3));
    assert!(dem[..6]
        .iter()
        .all(|e| e.run.protocol == DemProtocol::Design));
    assert_eq!(rec.names(), ["dem", "protocol-check"]);
    // the study's own protocol: no check
    cp.dem_is_study_protocol = true;
    let oracle = Oracle::new(0.005);
    assert_eq!(
        ConfirmStage::new(env, &cp, &oracle)
            .run(&pats)
            .unwrap()
            .len(),
        6
    );
    assert_eq!(oracle.batches.lock().unwrap().len(), 1);
    // without the DEM: nothing run, no estimate added
    cp.no_dem = true;
    let oracle = Oracle::new(0.005);
    let stage = ConfirmStage::new(env, &cp, &oracle);
    assert!(stage.run(&pats).unwrap().is_empty());
    let mut pr = pats[0].clone();
    stage.estimates(&mut pr).unwrap();
    assert!(pr.ranking.iter().all(|c| c.friction.is_empty()));
    assert!(oracle.batches.lock().unwrap().is_empty());
    std::fs::remove_dir_all(&dir).ok();
}
