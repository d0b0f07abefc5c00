//! Unit tests of the shortlist's level walk.

use super::walk::{LevelWalk, Next};
use crate::study::design::model::fixtures::pattern;
use crate::study::design::model::Stop;

/// The level walk stops at the first level below the best exact limit once the ranking holds
/// the designs it needs, never before; a floor skips a level that cannot exceed it.
#[test]
fn the_level_walk_stops_below_the_best_limit_and_skips_under_the_floor() {
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
