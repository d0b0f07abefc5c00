//! `superlube tolerance` and `design --theta-tol-deg/--direction-tol-deg` on small scenes: the map's
//! files and sidecars, its nominal point against `superlube friction`, the screen's bound,
//! zero tolerance reproducing the nominal ranking, the robust ranking's order, and bad input
//! refused naming the flag before anything is written.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};
use std::path::Path;

/// A 15 µm slider (≈ 80 spheres) and four loads scaled to its sphere count.
const SMALL: [&str; 6] = [
    "--slider-radius-um",
    "15",
    "--substrate-um",
    "60x60",
    "--load-mn",
    "0.01,0.03,0.06,0.09",
];

fn rows(path: &Path) -> Vec<std::collections::HashMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let h = r.headers().unwrap().clone();
    r.records()
        .map(|x| {
            let x = x.unwrap();
            h.iter()
                .zip(x.iter())
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect()
        })
        .collect()
}

fn num(r: &std::collections::HashMap<String, String>, k: &str) -> f64 {
    r[k].parse().unwrap_or_else(|_| panic!("{k} = {:?}", r[k]))
}

/// `superlube tolerance` of tri-tri at (θ, α) on the small scene into `out`: θ and direction
/// axes as (range, points, tolerance), in degrees.
fn tolerance_map(at: (&str, &str), theta: (&str, &str, &str), dir: (&str, &str, &str), out: &Path) {
    let o = bin()
        .args([
            "tolerance",
            "--pattern",
            "tri-tri",
            "--theta",
            at.0,
            "--alpha",
            at.1,
        ])
        .args(SMALL)
        .args(["--theta-range-deg", theta.0, "--theta-points", theta.1])
        .args(["--direction-range-deg", dir.0, "--direction-points", dir.1])
        .args([
            "--theta-tol-deg",
            theta.2,
            "--direction-tol-deg",
            dir.2,
            "--out",
        ])
        .arg(out)
        .output()
        .unwrap();
    assert_ok(&o);
}

#[test]
fn map_files_nominal_point_and_the_screen_bound() {
    let d = tmpdir("tolerance-map");
    let out = d.join("map");
    tolerance_map(("30", "0"), ("0.4", "5", "0.2"), ("1", "3", "0.5"), &out);
    for f in [
        "map.csv",
        "map.png",
        "map.csv.meta.json",
        "map.png.meta.json",
    ] {
        assert!(out.join(f).exists(), "{f} missing");
    }
    let m = rows(&out.join("map.csv"));
    assert_eq!(m.len(), 15);
    // direction outer, θ inner
    assert_eq!(num(&m[0], "theta_offset_deg"), -0.4);
    assert_eq!(num(&m[1], "theta_offset_deg"), -0.2);
    assert_eq!(num(&m[0], "direction_offset_deg"), -1.0);
    assert_eq!(num(&m[5], "direction_offset_deg"), 0.0);
    for r in &m {
        // the screen's placement bound is never exceeded; confident ≤ superlubric
        assert!(num(r, "superlubric_to_mN") <= num(r, "placement_intact_to_mN"));
        assert!(num(r, "confident_to_mN") <= num(r, "superlubric_to_mN"));
        // the pull direction is fixed in the substrate frame: α follows the contact line
        assert!(
            (num(r, "direction_deg")
                - num(r, "direction_offset_deg")
                - m[7]["direction_deg"].parse::<f64>().unwrap())
            .abs()
                < 1e-9
        );
    }
    // the nominal point against `superlube friction` at the same θ, α and loads
    let nominal = &m[7];
    assert_eq!(num(nominal, "theta_offset_deg"), 0.0);
    let fr = d.join("fr.csv");
    let o = bin()
        .args([
            "friction",
            "--pattern",
            "tri-tri",
            "--theta",
            "30",
            "--alpha",
            "0",
        ])
        .args(SMALL)
        .arg("--out")
        .arg(&fr)
        .output()
        .unwrap();
    assert_ok(&o);
    let mut expect = 0.0;
    for r in rows(&fr) {
        let ok = r["error"].is_empty() && num(&r, "p_max_GPa") <= 4.0 && num(&r, "mu_est") < 0.02;
        if !ok {
            break;
        }
        expect = num(&r, "load_mN");
    }
    assert_eq!(num(nominal, "superlubric_to_mN"), expect);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn tolerance_bad_input_names_the_flag() {
    let d = tmpdir("tolerance-bad");
    let out = d.join("x");
    let o = out.to_str().unwrap();
    let run = |extra: &[&str], flag: &str| {
        let mut a: Vec<&str> = vec!["tolerance", "--pattern", "tri-tri", "--alpha", "0"];
        a.extend(SMALL);
        a.extend(extra);
        a.extend(["--out", o]);
        fails_naming(&a, flag);
    };
    run(&["--theta-range-deg", "-0.1"], "--theta-range-deg");
    run(&["--direction-range-deg", "NaN"], "--direction-range-deg");
    run(&["--theta-points", "0"], "--theta-points");
    run(&["--theta-tol-deg", "0.5"], "--theta-tol-deg");
    run(&["--theta-tol-deg", "-1"], "--theta-tol-deg");
    fails_naming(
        &["tolerance", "--pattern", "tri-tri", "--out", o],
        "--direction-deg",
    );
    assert!(!out.exists(), "nothing may be written");
    std::fs::remove_dir_all(&d).ok();
}

fn design(extra: &[&str], out: &Path) {
    let o = bin()
        .args(["design", "--theta", "0:30:1", "--no-dem"])
        .args(SMALL)
        .args(extra)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap();
    assert_ok(&o);
}

#[test]
fn zero_tolerance_is_the_nominal_ranking_and_the_robust_one_is_ordered() {
    let d = tmpdir("tolerance-design");
    let nominal = d.join("nominal");
    design(
        &["--theta-tol-deg", "0", "--direction-tol-deg", "0"],
        &nominal,
    );
    let n = rows(&nominal.join("ranking.csv"));
    assert!(!n.is_empty());
    for r in &n {
        assert_eq!(r["superlubric_to_mN"], r["superlubric_to_nominal_mN"]);
        assert_eq!(num(r, "theta_window_deg"), 0.0);
        assert_eq!(r["robust_exact"], "true");
    }
    // ranked by the nominal limit, then μ: non-increasing limits within a pattern
    for w in n.windows(2) {
        if w[0]["pattern"] == w[1]["pattern"] {
            assert!(num(&w[0], "superlubric_to_mN") >= num(&w[1], "superlubric_to_mN"));
        }
    }
    let robust = d.join("robust");
    design(
        &[
            "--theta-tol-deg",
            "1",
            "--theta-tol-step-deg",
            "0.5",
            "--direction-tol-deg",
            "0.5",
        ],
        &robust,
    );
    let r = rows(&robust.join("ranking.csv"));
    for x in &r {
        // the robust limit never exceeds the nominal one, windows stay inside the box
        assert!(num(x, "superlubric_to_mN") <= num(x, "superlubric_to_nominal_mN"));
        // (computed for every exact design; empty only where the limit is an upper bound)
        if x["theta_window_deg"].is_empty() || x["direction_window_deg"].is_empty() {
            assert!(
                x["robust_exact"] == "false" || num(x, "superlubric_to_mN") == 0.0,
                "{x:?}"
            );
        } else {
            assert!(num(x, "theta_window_deg") <= 1.0);
            assert!(num(x, "direction_window_deg") <= 0.5);
        }
        assert!(["superlubric", "borderline", "not"].contains(&x["verdict"].as_str()));
    }
    // a design that fails somewhere in its box is never ranked above one superlubric over its
    // whole box at a higher robust load (exact limits come first, in order)
    for w in r.windows(2) {
        if w[0]["pattern"] == w[1]["pattern"]
            && w[0]["robust_exact"] == "true"
            && w[1]["robust_exact"] == "true"
        {
            assert!(num(&w[0], "superlubric_to_mN") >= num(&w[1], "superlubric_to_mN"));
        }
    }
    let report = std::fs::read_to_string(robust.join("report.md")).unwrap();
    assert!(report.contains("fabrication tolerance θ ±1°"), "{report}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn design_tolerance_bad_input_names_the_flag() {
    let d = tmpdir("tolerance-design-bad");
    let out = d.join("x");
    let o = out.to_str().unwrap();
    let run = |extra: &[&str], flag: &str| {
        let mut a: Vec<&str> = vec!["design", "--no-dem"];
        a.extend(SMALL);
        a.extend(extra);
        a.extend(["--out", o]);
        fails_naming(&a, flag);
    };
    run(&["--theta-tol-deg", "-0.1"], "--theta-tol-deg");
    run(&["--theta-tol-deg", "NaN"], "--theta-tol-deg");
    run(&["--direction-tol-deg", "-1"], "--direction-tol-deg");
    // square-tri's θ domain is 0–15°: ±8° spans it
    run(
        &["--pattern", "square-tri", "--theta-tol-deg", "8"],
        "--theta-tol-deg",
    );
    run(&["--seeds", "1,2"], "--seeds");
    run(&["--sigma-h-um", "0.01", "--seeds", "x"], "--seeds");
    assert!(!out.exists(), "nothing may be written");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn the_dem_runs_the_corners_of_the_answers_box() {
    let d = tmpdir("tolerance-dem");
    let out = d.join("run");
    let o = bin()
        .args(["design", "--pattern", "square-tri", "--theta", "0:30:1"])
        .args(SMALL)
        .args([
            "--theta-tol-deg",
            "1",
            "--theta-tol-step-deg",
            "0.5",
            "--direction-tol-deg",
            "0.5",
        ])
        .args(["--confirm", "1", "--confirm-loads-mn", "0.01,0.09"])
        .args(["--dem-equilibrate-us", "0.1", "--dem-relax-us", "0.05"])
        .args([
            "--dem-slide-us",
            "0.3",
            "--no-protocol-check",
            "--jobs",
            "2",
            "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert_ok(&o);
    let ranking = rows(&out.join("ranking.csv"));
    let best = &ranking[0];
    let limit = num(best, "superlubric_to_mN");
    assert!(
        limit > 0.0,
        "the small scene's best design is superlubric somewhere"
    );
    let dem = rows(&out.join("dem.csv"));
    let corners: Vec<_> = dem
        .iter()
        .filter(|r| num(r, "theta_offset_deg") != 0.0 || num(r, "direction_offset_deg") != 0.0)
        .collect();
    // four corners at the robust limit load (and four at the next load above, if any)
    let at_limit = corners
        .iter()
        .filter(|r| num(r, "load_mN") == limit)
        .count();
    assert_eq!(at_limit, 4, "{dem:?}");
    assert!(corners.len() == 4 || corners.len() == 8);
    for r in &corners {
        assert_eq!(num(r, "theta_offset_deg").abs(), 1.0);
        assert_eq!(num(r, "direction_offset_deg").abs(), 0.5);
        let t = num(best, "theta_deg") + num(r, "theta_offset_deg");
        assert!((num(r, "theta_deg") - t).abs() < 1e-9);
    }
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("| DEM at the box corners |"), "{report}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn a_rerun_replays_the_robust_searches_without_new_estimates() {
    let d = tmpdir("tolerance-rerun");
    let out = d.join("r");
    let args = [
        "--theta-tol-deg",
        "1",
        "--theta-tol-step-deg",
        "0.5",
        "--direction-tol-deg",
        "0.5",
    ];
    design(&args, &out);
    let first = std::fs::read(out.join("ranking.csv")).unwrap();
    std::fs::remove_file(out.join("ranking.csv")).unwrap();
    let o = bin()
        .args(["design", "--theta", "0:30:1", "--no-dem"])
        .args(SMALL)
        .args(args)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_ok(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    // every level replays its stored searches: no friction path is estimated again
    let notes: Vec<&str> = err
        .lines()
        .filter(|l| l.contains("robust limits:"))
        .collect();
    assert!(!notes.is_empty(), "{err}");
    for n in notes {
        assert!(n.ends_with("(0 friction paths)"), "{n}");
    }
    assert_eq!(std::fs::read(out.join("ranking.csv")).unwrap(), first);
    std::fs::remove_dir_all(&d).ok();
}

/// The robust limit and the windows of `design` against the independent tolerance map of the
/// same design sampled on the same grid: the robust limit is the map's lowest limit over the
/// box, and each window is the largest sampled offset up to which every axis point of the map
/// reaches the nominal limit.
#[test]
fn design_limit_and_windows_match_the_tolerance_map() {
    let d = tmpdir("tolerance-window");
    let out = d.join("r");
    design(
        &[
            "--pattern",
            "tri-tri",
            "--theta-tol-deg",
            "1",
            "--theta-tol-step-deg",
            "0.5",
            "--direction-tol-deg",
            "0.5",
            "--direction-tol-step-deg",
            "0.25",
        ],
        &out,
    );
    let r = rows(&out.join("ranking.csv"));
    // the first exact design that its box lowers (on this scene: θ = 13°, window 0 in θ)
    let best = r
        .iter()
        .find(|x| {
            x["robust_exact"] == "true"
                && num(x, "superlubric_to_mN") < num(x, "superlubric_to_nominal_mN")
        })
        .expect("a design whose tolerance box lowers its limit");
    let map = d.join("map");
    tolerance_map(
        (&best["theta_deg"], &best["alpha_deg"]),
        ("1", "5", "1"),
        ("0.5", "5", "0.5"),
        &map,
    );
    let m = rows(&map.join("map.csv"));
    assert_eq!(m.len(), 25);
    let at = |dt: f64, dd: f64| {
        let p = m
            .iter()
            .find(|x| num(x, "theta_offset_deg") == dt && num(x, "direction_offset_deg") == dd)
            .unwrap_or_else(|| panic!("no map point at {dt}, {dd}"));
        num(p, "superlubric_to_mN")
    };
    let nominal = at(0.0, 0.0);
    assert_eq!(nominal, num(best, "superlubric_to_nominal_mN"));
    let lowest = m
        .iter()
        .map(|x| num(x, "superlubric_to_mN"))
        .fold(f64::INFINITY, f64::min);
    assert_eq!(lowest, num(best, "superlubric_to_mN"));
    let window = |offsets: &[f64], point: &dyn Fn(f64) -> f64| {
        let mut w = 0.0;
        for &h in offsets {
            if point(h) >= nominal && point(-h) >= nominal {
                w = h;
            } else {
                break;
            }
        }
        w
    };
    let wt = window(&[0.5, 1.0], &|h| at(h, 0.0));
    let wd = window(&[0.25, 0.5], &|h| at(0.0, h));
    assert_eq!(num(best, "theta_window_deg"), wt, "{best:?}");
    assert_eq!(num(best, "direction_window_deg"), wd, "{best:?}");
    std::fs::remove_dir_all(&d).ok();
}

/// `--seeds`: the exact designs list each seed's own limit at the nominal orientation, none
/// below the robust limit (the worst over the box and every seed).
#[test]
fn seeds_give_each_realisations_limit_behind_the_worst_case() {
    let d = tmpdir("tolerance-seeds");
    let out = d.join("s");
    design(
        &[
            "--pattern",
            "tri-tri",
            "--theta-tol-deg",
            "1",
            "--theta-tol-step-deg",
            "0.5",
            "--direction-tol-deg",
            "0.5",
            "--sigma-h-um",
            "0.02",
            "--seeds",
            "1,2,3",
        ],
        &out,
    );
    let r = rows(&out.join("ranking.csv"));
    let mut listed = 0;
    for x in &r {
        let v = &x["superlubric_to_seeds_mN"];
        if x["robust_exact"] == "true" && num(x, "superlubric_to_mN") > 0.0 {
            let seeds: Vec<f64> = v.split(';').map(|s| s.parse().unwrap()).collect();
            assert_eq!(seeds.len(), 3, "{x:?}");
            for s in seeds {
                assert!(s >= num(x, "superlubric_to_mN"), "{x:?}");
            }
            listed += 1;
        } else {
            assert!(v.is_empty(), "{x:?}");
        }
    }
    assert!(listed >= 3, "{r:?}");
    std::fs::remove_dir_all(&d).ok();
}

/// A window known in advance. tri-tri at θ = 0 is commensurate: every sphere sits on top of
/// one, and rotating the slider lifts the rim spheres off, so the screen's P_max at the
/// placement rises with |δθ|. With P_crit set between two of its values on a fine θ list (at
/// its largest relative step between 0.3° and 0.9°), μ_sl out of reach (10), a friction path of
/// 2 nm through the placement (P_max on it is the placement's), the coating fails exactly
/// beyond a θ offset h* read off the screen alone. The design's θ window, sampled every 0.1°,
/// must be h* to that step (the largest sample ≤ h*), its direction window the whole direction
/// tolerance, and its robust limit below the nominal (the box is wider than the window).
#[test]
fn the_theta_window_of_a_coating_failure_is_found_to_the_sampling_step() {
    let d = tmpdir("tolerance-known");
    let scene = [
        "--pattern",
        "tri-tri",
        "--slider-radius-um",
        "15",
        "--substrate-um",
        "60x60",
        "--load-mn",
        "0.09",
    ];
    // 1. the screen's placement P_max over a fine θ list around 0
    let screen = d.join("screen.csv");
    let o = bin()
        .arg("screen")
        .args(scene)
        .arg("--theta=-1:1:0.02")
        .arg("--out")
        .arg(&screen)
        .output()
        .unwrap();
    assert_ok(&o);
    let pts: Vec<(f64, f64)> = rows(&screen)
        .iter()
        .map(|r| (num(r, "theta_deg").abs(), num(r, "p_max_GPa")))
        .collect();
    assert!(pts.len() > 90, "{}", pts.len());
    let mut hs: Vec<f64> = pts.iter().map(|p| p.0).collect();
    hs.sort_by(f64::total_cmp);
    hs.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    // M(h): the largest P_max over |δθ| ≤ h (non-decreasing)
    let m = |h: f64| {
        pts.iter()
            .filter(|p| p.0 <= h + 1e-9)
            .map(|p| p.1)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (j, jump) = (1..hs.len())
        .filter(|&j| hs[j] >= 0.3 && hs[j] <= 0.9)
        .map(|j| (j, m(hs[j]) / m(hs[j - 1])))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    assert!(jump > 1.0, "P_max must rise off the commensurate angle");
    let p_crit: f64 = format!("{:.6}", 0.5 * (m(hs[j - 1]) + m(hs[j])))
        .parse()
        .unwrap();
    let known = hs
        .iter()
        .copied()
        .filter(|&h| m(h) <= p_crit)
        .fold(0.0f64, f64::max);
    assert!((0.28..0.9).contains(&known), "h* = {known}");
    // 2. the design with a tolerance box wider than that window
    let out = d.join("design");
    let o = bin()
        .args(["design", "--theta", "0", "--no-dem"])
        .args(scene)
        .args([
            "--p-crit-gpa",
            &p_crit.to_string(),
            "--mu-superlubric",
            "10",
        ])
        .args(["--length-um", "0.002", "--step-um", "0.001"])
        .args(["--transient-um", "0", "--max-period-um", "0.002"])
        .args(["--transverse-um", "0"])
        .args(["--scan-distance-um", "0.5", "--alpha-refine-deg", "none"])
        .args(["--theta-tol-deg", "1", "--theta-tol-step-deg", "0.1"])
        .args([
            "--direction-tol-deg",
            "0.5",
            "--direction-tol-step-deg",
            "0.5",
        ])
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_ok(&o);
    let r = rows(&out.join("ranking.csv"));
    let best = &r[0];
    assert_eq!(num(best, "theta_deg"), 0.0);
    assert_eq!(num(best, "superlubric_to_nominal_mN"), 0.09, "{best:?}");
    let w = num(best, "theta_window_deg");
    assert!(
        w <= known + 1e-9 && w > known - 0.1 - 1e-9,
        "θ window {w}° against h* = {known}° (step 0.1°)"
    );
    assert_eq!(num(best, "direction_window_deg"), 0.5, "{best:?}");
    assert_eq!(num(best, "superlubric_to_mN"), 0.0, "{best:?}");
    std::fs::remove_dir_all(&d).ok();
}
