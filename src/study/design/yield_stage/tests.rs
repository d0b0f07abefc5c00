//! Unit tests of the yield stage on a small scene (the estimate's part, no DEM).

use super::*;
use crate::study::design::limit::LimitKnobs;
use crate::study::design::model::fixtures::pattern;
use crate::study::design::model::{Answer, Check, DesignOutcome};
use crate::study::design::stage_env::StageEnv;
use crate::study::design::store::Store;
use crate::study::design::test_design::{out_dir, small_params, small_scene, Record};

/// The stage gives each answer that is superlubric somewhere its yield over `samples` devices
/// (one row each, no DEM), none to a pattern without an answer, stores the devices' critical
/// loads and reuses them on a re-run with the same summary.
#[test]
fn each_answer_gets_its_yield_and_a_rerun_reuses_the_devices() {
    let p = small_params(0.1, true);
    let limit: LimitKnobs = p.limit_knobs();
    let dir = out_dir("yield-stage");
    let store = Store::new(&dir);
    let rec = Record::default();
    let env = StageEnv {
        limit: &limit,
        store: &store,
        obs: &rec,
    };
    let mut with = pattern("tri-tri", 1);
    with.scene = small_scene("tri-tri");
    let without = pattern("square-tri", 0);
    let answer = |index| Answer {
        index,
        check: Check::NoDem,
        others: vec![],
    };
    let o = DesignOutcome {
        answers: vec![answer(Some(0)), answer(None)],
        ..DesignOutcome::without_report(vec![with, without])
    };
    let params = YieldRunParams {
        knobs: YieldStageParams {
            samples: 4,
            quantile: 0.5,
            confidence: 0.9,
            resolution: 0.5,
            seed: 7,
            dem_check: 0,
            dem_max_runs: 40,
            rank_by: RankBy::WorstCase,
        },
        dem: None,
    };
    let stage = YieldStage::new(env, &params);
    let y = stage.run(&o).unwrap();
    assert_eq!(y.len(), 2);
    assert!(y[1].is_none());
    let a = y[0].as_ref().unwrap();
    assert_eq!((a.theta_deg, a.direction_deg), (0.0, 90.0));
    assert_eq!(a.outcome.rows.len(), 4);
    assert_eq!(a.outcome.summary.samples, 4);
    assert!(dir.join("stages/tri-tri/yield_0_90.json").is_file());
    assert_eq!(rec.names(), ["yield"]);
    // a re-run reads the stored devices: the same summary
    let again = stage.run(&o).unwrap();
    assert_eq!(
        format!("{:?}", again[0].as_ref().unwrap().outcome.summary),
        format!("{:?}", a.outcome.summary)
    );
    std::fs::remove_dir_all(&dir).ok();
}
