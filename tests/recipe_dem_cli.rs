//! `superlube design --vary` (issue 36, item 4): a recipe outside the validated range (here a
//! slider of E = 50 GPa; the band was measured at 100 GPa) gets the DEM at its centre and at
//! the corners of its tolerance box before it is named, with the model `auto` where `reduced`
//! was asked; a recipe inside the range keeps the design's model. Without the DEM the report
//! calls the flagged recipe unconfirmed. The report gives the best recipe's robust limit at
//! P_crit = 3.6, 4 and 4.4 GPa, monotone in P_crit. A small scene and a very short DEM protocol (fast).

mod common;
use common::{assert_ok, run_small, tmpdir};
use std::path::Path;

/// On the small scene (a 15 µm slider on a 60 µm substrate): a few θ and loads, a 3 × 3
/// tolerance box.
const SMALL: [&str; 14] = [
    "--theta",
    "0:15:3",
    "--load-mn",
    "0.01,0.03,0.06,0.09",
    "--theta-tol-deg",
    "0.5",
    "--direction-tol-deg",
    "1",
    "--theta-tol-step-deg",
    "0.5",
    "--direction-tol-step-deg",
    "1",
    "--vary",
    "slider.material.youngs_GPa=50,100",
];

/// The short DEM protocol of the confirmation.
const DEM: [&str; 14] = [
    "--confirm",
    "1",
    "--confirm-loads-mn",
    "0.01",
    "--dem-equilibrate-us",
    "0.1",
    "--dem-relax-us",
    "0.05",
    "--dem-slide-us",
    "0.3",
    "--no-protocol-check",
    "--jobs",
    "2",
    "--dem-model=reduced",
];

fn design(extra: &[&str], out: &Path) -> std::process::Output {
    run_small("design", &[&SMALL, extra], out)
}

const SOFT: &str = "square-tri+slider.material.youngs_GPa=50";
const STUDY: &str = "square-tri+slider.material.youngs_GPa=100";

/// `ranking.csv`'s rank-1 row of `pattern`: (θ, α, robust limit mN).
fn best(out: &Path, pattern: &str) -> (f64, f64, f64) {
    let mut r = csv::Reader::from_path(out.join("ranking.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let x = r
        .records()
        .map(Result::unwrap)
        .find(|x| &x[col("pattern")] == pattern && &x[col("rank")] == "1")
        .unwrap_or_else(|| panic!("no rank-1 design of {pattern}"));
    let f = |n: &str| x[col(n)].parse::<f64>().unwrap();
    (f("theta_deg"), f("alpha_deg"), f("superlubric_to_mN"))
}

#[test]
fn a_recipe_outside_the_validated_range_gets_its_dem_runs_before_it_is_named() {
    let d = tmpdir("recipe-dem");
    // without the DEM: the flagged recipe is unconfirmed
    let out = d.join("run");
    assert_ok(&design(&["--no-dem"], &out));
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    let (_, _, soft_limit) = best(&out, SOFT);
    assert!(soft_limit > 0.0, "the test needs a superlubric soft recipe");
    let pats = std::fs::read_to_string(out.join("patterns.csv")).unwrap();
    let soft_first = pats.find(SOFT) < pats.find(STUDY);
    if soft_first {
        assert!(
            report.contains("best recipe slider.material.youngs_GPa = 50 ")
                && report
                    .contains("**unconfirmed**: outside the validated range (slider E = 50 GPa)"),
            "{report}"
        );
    }
    assert!(
        report.contains("is **unconfirmed** without the DEM"),
        "{report}"
    );
    // with the DEM (the surrogate stages reused)
    let o = design(&DEM, &out);
    assert_ok(&o);
    let mut r = csv::Reader::from_path(out.join("dem.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let recs: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    let runs = |pattern: &str| -> Vec<&csv::StringRecord> {
        recs.iter()
            .filter(|x| &x[col("pattern")] == pattern && &x[col("rank")] == "1")
            .collect()
    };
    let (theta, alpha, limit) = best(&out, SOFT);
    let soft = runs(SOFT);
    let at = |x: &csv::StringRecord, n: &str| x[col(n)].parse::<f64>().unwrap();
    // its centre at its own limit load
    assert!(
        soft.iter().any(|x| at(x, "theta_deg") == theta
            && at(x, "alpha_deg") == alpha
            && at(x, "theta_offset_deg") == 0.0
            && at(x, "direction_offset_deg") == 0.0
            && at(x, "load_mN") == limit),
        "no centre run of {SOFT} at {limit} mN: {soft:?}"
    );
    // its four corners at its limit load
    let mut corners: Vec<(f64, f64)> = soft
        .iter()
        .filter(|x| at(x, "load_mN") == limit && at(x, "theta_offset_deg") != 0.0)
        .map(|x| (at(x, "theta_offset_deg"), at(x, "direction_offset_deg")))
        .collect();
    corners.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(
        corners,
        vec![(-0.5, -1.0), (-0.5, 1.0), (0.5, -1.0), (0.5, 1.0)],
        "{soft:?}"
    );
    // the flagged recipe's runs ask for `auto`, the study-range recipe's keep `reduced`
    let requested = |x: &csv::StringRecord| {
        let j: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(out.join(&x[col("run_dir")]).join("slide.json")).unwrap(),
        )
        .unwrap();
        j["model_requested"].as_str().unwrap().to_string()
    };
    for x in &soft {
        assert_eq!(requested(x), "auto", "{x:?}");
    }
    let inside = runs(STUDY);
    assert!(!inside.is_empty());
    for x in &inside {
        assert_eq!(requested(x), "reduced", "{x:?}");
    }
    // the report's DEM table of the best recipes, with the decision
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("The DEM at the best recipes"), "{report}");
    assert!(
        report.contains("| square-tri: slider.material.youngs_GPa = 50 |"),
        "{report}"
    );
    assert!(report.contains("slider E = 50 GPa"), "{report}");
    // named only when every run at its limit (centre and corners) held in the DEM
    let held = soft
        .iter()
        .filter(|x| at(x, "load_mN") == limit)
        .all(|x| &x[col("superlubric_dem")] == "true");
    if held {
        assert!(report.contains("**confirmed by the DEM**"), "{report}");
    } else {
        assert!(
            report.contains("not named: slider.material.youngs_GPa = 50"),
            "{report}"
        );
    }
    std::fs::remove_dir_all(&d).ok();
}
