//! Unit tests of the design pipeline: the plan's cross-stage rules, and the stages run in the
//! listed order on a small design with an oracle in place of the DEM.

use super::*;
use crate::study::design::confirm::{confirm_jobs, loads_to_confirm};
use crate::study::design::model::fixtures::pattern;
use crate::study::design::model::Check;
use crate::study::design::test_design::{out_dir, small_params, small_scene, Oracle, Record};
use crate::study::load::Load;
use std::sync::Mutex;

/// The plan keeps at least three designs per pattern (more with a larger `--confirm`), keeps
/// only each pattern's best across many patterns without the DEM, and its floor is the third
/// best exact robust limit so far, only across many patterns.
#[test]
fn the_plan_keeps_three_designs_and_floors_at_the_third_best_pattern() {
    let mut p = small_params(0.0, true);
    assert_eq!(Plan::new(&p).keep, MIN_KEPT);
    p.confirm.designs = 5;
    let plan = Plan::new(&p);
    assert_eq!((plan.keep, plan.confirmed, plan.rank.keep), (5, 5, 5));
    assert_eq!(plan.robust(1.4, true).keep, 1);
    assert_eq!(plan.robust(1.4, false).keep, 5);
    assert_eq!(plan.robust(1.4, false).floor_mn, 1.4);
    p.confirm.no_dem = false;
    assert_eq!(Plan::new(&p).robust(1.4, true).keep, 5);
    // the floor: 0 until three patterns have an exact limit, then the third best
    let mut floor = Floor::new(true);
    let mut alone = Floor::new(false);
    // each record, then the floor after it
    let steps = [
        ((2.1, true), 0.0),
        ((3.86, true), 0.0),
        ((9.0, false), 0.0),
        ((1.4, true), 1.4),
        ((2.45, true), 2.1),
    ];
    for ((limit, exact), after) in steps {
        let mut pr = pattern("tri-tri", 1);
        pr.ranking[0].score.superlubric_to_mn = limit;
        pr.ranking[0].score.exact = exact;
        floor.record(&pr);
        alone.record(&pr);
        assert_eq!(floor.mn(), after, "after {limit}");
    }
    assert_eq!(floor.mn(), 2.1);
    assert_eq!(alone.mn(), 0.0);
}

/// The stages run in the pipeline's order: the screen, the levels, the ranking, the estimates
/// the DEM is compared with (in the pattern's files, before its trim), the DEM (one batch, the
/// runs the confirmation asks for, through the runner), then the answers from its outcomes;
/// without the DEM no run is asked and the answer says so.
#[test]
fn the_pipeline_runs_its_stages_in_order_and_confirms_through_the_runner() {
    let p = small_params(0.0, false);
    let scenes = [small_scene("tri-tri")];
    let dir = out_dir("pipeline-oracle");
    let store = Store::new(&dir);
    let rec = Record::default();
    let oracle = Oracle::new(0.005);
    let hooked: Mutex<Vec<bool>> = Mutex::new(Vec::new());
    let hook = |pr: &PatternResult| -> Result<()> {
        // the DEM's estimates are in the pattern's files: a row at every load it confirms
        let c = &pr.ranking[0];
        let every = loads_to_confirm(c, &p.confirm.loads, &p.loads)
            .iter()
            .all(|&w| c.friction.iter().any(|r| Load::from_n(w).is(r.load_mN)));
        hooked.lock().unwrap().push(every && !pr.trimmed);
        Ok(())
    };
    let o = Pipeline::new(&p, &store, &rec)
        .with_runner(&oracle)
        .run(&scenes, &hook)
        .unwrap();
    assert_eq!(hooked.into_inner().unwrap(), vec![true]);
    assert!(o.patterns[0].trimmed && o.dem_ran);
    let seen = rec.names();
    let at = |n: &str| seen.iter().position(|s| *s == n).unwrap_or(usize::MAX);
    assert!(
        at("symmetry") < at("screen")
            && at("screen") < at("level")
            && at("level") < at("best")
            && at("best") < at("dem"),
        "{seen:?}"
    );
    // one batch: the confirmation's runs, in its order, on its threads
    let (jobs, _) = confirm_jobs(&o.patterns, &p.confirm, &p.limit_knobs());
    let names: Vec<String> = jobs.iter().map(|j| j.name.clone()).collect();
    assert!(!names.is_empty());
    assert_eq!(*oracle.batches.lock().unwrap(), vec![(names, 1)]);
    assert_eq!(o.dem.len(), jobs.len());
    // every run superlubric in the oracle: the answer is confirmed at its loads up to its limit
    let c = &o.patterns[0].ranking[0];
    assert!(c.score.superlubric_to_mn > 0.0, "{c:?}");
    match &o.answers[0].check {
        Check::Confirmed(loads) => {
            assert!(!loads.is_empty() && loads.iter().all(|&w| w <= c.score.superlubric_to_mn))
        }
        other => panic!("{other:?}"),
    }
    // without the DEM (the surrogate's stages reused): no run, the answer says so
    let mut p = p;
    p.confirm.no_dem = true;
    let none = Oracle::new(0.005);
    let o = Pipeline::new(&p, &store, &Record::default())
        .with_runner(&none)
        .run(&scenes, &|_| Ok(()))
        .unwrap();
    assert!(none.batches.lock().unwrap().is_empty());
    assert!(!o.dem_ran && o.dem.is_empty());
    assert_eq!(o.answers[0].check, Check::NoDem);
    std::fs::remove_dir_all(&dir).ok();
}
