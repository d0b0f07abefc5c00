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

/// The one observer of a design is told each stage's typed events in the order the pipeline
/// runs them: the screen (its symmetry, then the screen), then per shortlist level the level's
/// α scans and estimates and (with a tolerance) the robust search, then the best design and
/// the report data's tolerance map.
#[test]
fn the_observer_is_told_every_stage_in_order() {
    use crate::study::design::{Event, Observer};
    use std::sync::Mutex;
    #[derive(Debug, Clone, Copy, PartialEq)]
    enum Seen {
        Symmetry,
        Screen,
        Level,
        Robust,
        RobustDone,
        Best,
        ToleranceMap,
    }
    struct Record(Mutex<Vec<(Seen, String)>>);
    impl Observer for Record {
        fn event(&self, e: &Event<'_>) {
            let seen = match e {
                Event::Symmetry { pattern, .. } => (Seen::Symmetry, pattern),
                Event::Screened { pattern, .. } | Event::ScreenReused { pattern, .. } => {
                    (Seen::Screen, pattern)
                }
                Event::Level { pattern, .. } => (Seen::Level, pattern),
                Event::Robust { pattern, .. } => (Seen::Robust, pattern),
                Event::RobustDone { pattern, .. } => (Seen::RobustDone, pattern),
                Event::Best { pattern, .. } => (Seen::Best, pattern),
                Event::ToleranceMap { pattern, .. } => (Seen::ToleranceMap, pattern),
                _ => return,
            };
            self.0.lock().unwrap().push((seen.0, seen.1.to_string()));
        }
        fn progress(&self) -> &dyn crate::runs::progress::Progress {
            &Silent
        }
    }
    let dir = std::env::temp_dir().join(format!("superlube-design-obs-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut a = args(&dir, &["--per-level", "1"]);
    a.pattern = Some("tri-tri".into());
    a.theta.text = Some("0:30:15".into());
    a.load.text = "0.01,0.03".into();
    let (scenes, params) = prepare(&a).unwrap();
    let rec = Record(Mutex::new(Vec::new()));
    design(&scenes, &params, &Store::new(&a.out), &rec, &|_| Ok(())).unwrap();
    let seen = rec.0.into_inner().unwrap();
    let order: Vec<Seen> = seen.iter().map(|(s, _)| *s).collect();
    assert_eq!(order[..2], [Seen::Symmetry, Seen::Screen], "{order:?}");
    assert_eq!(
        order[order.len() - 2..],
        [Seen::Best, Seen::ToleranceMap],
        "{order:?}"
    );
    assert!(order.contains(&Seen::Robust), "{order:?}");
    // the level loop: each level's α scans and estimates, then the robust search (begun and
    // done) or the next level
    let levels = &order[2..order.len() - 2];
    assert!(!levels.is_empty() && levels[0] == Seen::Level, "{order:?}");
    for w in levels.windows(2) {
        let ok = matches!(
            w,
            [Seen::Level, Seen::Level]
                | [Seen::Level, Seen::Robust]
                | [Seen::Robust, Seen::RobustDone]
                | [Seen::RobustDone, Seen::Level]
        );
        assert!(ok, "{w:?} out of order in {order:?}");
    }
    assert_eq!(levels.last(), Some(&Seen::RobustDone), "{order:?}");
    assert!(seen.iter().all(|(_, p)| p == "tri-tri"));
    std::fs::remove_dir_all(&dir).ok();
}
