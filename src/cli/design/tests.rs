//! `superlube design` streams its patterns: each pattern's own files are written from the
//! complete pattern as it finishes, the rest from the trimmed outcome; every output must be the
//! one the untrimmed outcome gives when written at once.

use super::test_args::design_args;
use super::*;
use crate::present::design_report::{self, Writer};
use crate::runs::progress::Silent;
use crate::study::design::{inputs, PatternResult};
use std::cell::RefCell;
use std::path::Path;

/// A small two-pattern design without the DEM into `out` (`extra` flags appended).
fn args(out: &Path, extra: &[&str]) -> Args {
    let flags = [
        "--pattern",
        "square-tri,tri-tri",
        "--no-dem",
        "--theta",
        "0:30:2",
        "--slider-radius-um",
        "15",
        "--substrate-um",
        "60x60",
        "--load-mn",
        "0.01,0.03,0.06",
    ];
    design_args(&[&flags, extra], out)
}

/// The files under `dir` (relative paths, sorted), sidecars and stage files left out: the
/// sidecars name their own path.
fn outputs(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| {
            let e = e.unwrap();
            let name = e.file_name().to_string_lossy().into_owned();
            (e.file_type().unwrap().is_file()
                && !name.ends_with(".meta.json")
                && !name.starts_with("screen_")
                && name != "design.json")
                .then_some(name)
        })
        .collect();
    v.sort();
    v
}

#[test]
fn a_trimmed_outcome_gives_every_output_of_the_untrimmed_one() {
    let dir = std::env::temp_dir().join(format!("superlube-design-trim-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let a = args(&dir.join("streamed"), &[]);
    let (scenes, params) = prepare(&a).unwrap();
    let store = Store::new(&a.out);
    let record = inputs(&scenes, &params, true);
    let files = Writer::new(&store, &record, &params);
    let whole: RefCell<Vec<PatternResult>> = RefCell::new(Vec::new());
    let o = design(&scenes, &params, &store, &Silent, &|pr| {
        whole.borrow_mut().push(pr.clone());
        files.pattern(pr)
    })
    .unwrap();
    // the outcome was trimmed: no screen rows, no α scans, friction rows only at the top
    for pr in &o.patterns {
        assert!(pr.trimmed && pr.screen.is_empty() && pr.orientations.is_empty());
        assert!(pr.evaluated.iter().all(|e| e.eval.scan.is_empty()));
        assert!(pr.ranking.iter().skip(5).all(|c| c.friction.len() <= 1));
    }
    let mut untrimmed = o.clone();
    untrimmed.patterns = whole.into_inner();
    assert!(untrimmed
        .patterns
        .iter()
        .any(|pr| pr.ranking.len() > 5 && pr.ranking[5..].iter().any(|c| c.friction.len() > 1)));
    assert!(untrimmed
        .patterns
        .iter()
        .any(|pr| pr.ranking.iter().any(|c| c.friction.len() > 1)));
    design_report::publish(files, &o, &Silent).unwrap();
    // the untrimmed outcome written at once, elsewhere
    let at_once = dir.join("at-once");
    std::fs::create_dir_all(&at_once).unwrap();
    design_report::write(&Store::new(&at_once), &record, &params, &untrimmed, &Silent).unwrap();
    let names = outputs(&at_once);
    assert_eq!(outputs(&a.out), names);
    assert!(
        names.contains(&"report.md".to_string()) && names.len() > 10,
        "{names:?}"
    );
    for n in &names {
        assert!(
            std::fs::read(a.out.join(n)).unwrap() == std::fs::read(at_once.join(n)).unwrap(),
            "{n} differs between the streamed design and the untrimmed outcome"
        );
    }
    assert_eq!(
        design_report::markdown(&o, &params).unwrap(),
        design_report::markdown(&untrimmed, &params).unwrap()
    );
    // a trimmed pattern's files cannot be written again (its rows are gone)
    let again = Writer::new(&store, &record, &params);
    assert!(again.pattern(&o.patterns[0]).is_err());
    std::fs::remove_dir_all(&dir).ok();
}

/// The one observer of a design is told each stage as the pipeline enters it, in the order
/// the pipeline runs them: screen, shortlist, then per shortlist level the α scan, the estimate
/// and (with a tolerance) the robust search, then the report data.
#[test]
fn the_observer_is_told_every_stage_in_order() {
    use crate::study::design::{Event, Observer, Stage};
    use std::sync::Mutex;
    struct Record(Mutex<Vec<(Stage, String)>>);
    impl Observer for Record {
        fn stage(&self, s: Stage, pattern: &str) {
            self.0.lock().unwrap().push((s, pattern.to_string()));
        }
        fn event(&self, _: &Event<'_>) {}
        fn progress(&self) -> &dyn crate::runs::progress::Progress {
            &Silent
        }
    }
    let dir = std::env::temp_dir().join(format!("superlube-design-obs-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut a = args(&dir, &["--per-level", "1"]);
    a.pattern = Some("tri-tri".into());
    a.theta = Some("0:30:15".into());
    a.load_mn = "0.01,0.03".into();
    let (scenes, params) = prepare(&a).unwrap();
    let rec = Record(Mutex::new(Vec::new()));
    design(&scenes, &params, &Store::new(&a.out), &rec, &|_| Ok(())).unwrap();
    let seen = rec.0.into_inner().unwrap();
    let stages: Vec<Stage> = seen.iter().map(|(s, _)| *s).collect();
    assert_eq!(stages[..2], [Stage::Screen, Stage::Shortlist], "{stages:?}");
    assert_eq!(stages.last(), Some(&Stage::ReportData), "{stages:?}");
    assert!(stages.contains(&Stage::RobustSearch), "{stages:?}");
    // the level loop: each α scan followed by its estimate, then the robust search or the
    // next level's α scan
    let levels = &stages[2..stages.len() - 1];
    assert!(
        !levels.is_empty() && levels[0] == Stage::AlphaScan,
        "{stages:?}"
    );
    for w in levels.windows(2) {
        let ok = matches!(
            w,
            [Stage::AlphaScan, Stage::Estimate]
                | [Stage::Estimate, Stage::RobustSearch]
                | [Stage::Estimate, Stage::AlphaScan]
                | [Stage::RobustSearch, Stage::AlphaScan]
        );
        assert!(ok, "{w:?} out of order in {stages:?}");
    }
    assert!(seen[..seen.len() - 1].iter().all(|(_, p)| p == "tri-tri"));
    std::fs::remove_dir_all(&dir).ok();
}
