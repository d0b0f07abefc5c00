//! `superlube yield` on a small scene: its files and sidecars, the summary against the rows,
//! the step of a device-independent design at the nominal critical load, identical output
//! with 1 and 2 threads, the DEM deciding and checking, and bad input refused naming the flag
//! before anything is written.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};
use std::collections::HashMap;
use std::path::Path;

/// tri-tri at θ = 30° on a 15 µm slider (≈ 80 spheres), pulled along x, with a ladder of loads
/// scaled to its sphere count.
const SMALL: [&str; 12] = [
    "--pattern",
    "tri-tri",
    "--slider-radius-um",
    "15",
    "--substrate-um",
    "60x60",
    "--load-mn",
    "0.01,0.03,0.06,0.09,0.12,0.15",
    "--theta-deg",
    "30",
    "--direction-deg",
    "0",
];

/// A rough substrate, 6 devices and a check of 2, the DEM on a short protocol.
const DEM: [&str; 12] = [
    "--sigma-h-um",
    "0.002",
    "--samples",
    "6",
    "--dem-check",
    "2",
    "--dem-equilibrate-us",
    "1",
    "--dem-relax-us",
    "1",
    "--dem-slide-us",
    "10",
];

fn rows(path: &Path) -> Vec<HashMap<String, String>> {
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

fn num(r: &HashMap<String, String>, k: &str) -> f64 {
    r[k].parse().unwrap_or_else(|_| panic!("{k} = {:?}", r[k]))
}

fn summary(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

/// `superlube yield` on the small scene with `extra` flags into `out`, with `threads` rayon
/// threads.
fn run(extra: &[&str], out: &Path, threads: &str) {
    let o = bin()
        .arg("yield")
        .args(SMALL)
        .args(extra)
        .arg("--out-dir")
        .arg(out)
        .env("RAYON_NUM_THREADS", threads)
        .output()
        .unwrap();
    assert_ok(&o);
}

/// The files and sidecars; each row's bracket holds its critical load; the summary's quoted
/// load is the ⌈q n⌉-th highest critical load, its bound absent for too few devices, and the
/// yield there is the fraction of rows at or above it.
#[test]
fn files_rows_and_summary_agree() {
    let d = tmpdir("yield-files");
    let out = d.join("y");
    run(
        &["--sigma-h-um", "0.002", "--samples", "12", "--no-dem"],
        &out,
        "2",
    );
    for f in ["yield.csv", "summary.json", "yield.png"] {
        assert!(out.join(f).exists(), "{f} missing");
        assert!(out.join(format!("{f}.meta.json")).exists(), "{f} sidecar");
    }
    let m = rows(&out.join("yield.csv"));
    assert_eq!(m.len(), 12);
    let mut seeds: Vec<&str> = m.iter().map(|r| r["seed"].as_str()).collect();
    seeds.sort();
    seeds.dedup();
    assert_eq!(seeds.len(), 12, "a fresh substrate per device");
    for r in &m {
        let (lo, c, hi) = (
            num(r, "critical_load_low_mN"),
            num(r, "critical_load_mN"),
            num(r, "critical_load_high_mN"),
        );
        assert!(lo <= c && c <= hi, "{r:?}");
        assert!(num(r, "theta_offset_deg").abs() <= 0.1);
        assert!(num(r, "direction_offset_deg").abs() <= 0.5);
        assert_eq!(r["decided_by"], "estimate");
    }
    let s = summary(&out);
    let mut w: Vec<f64> = m.iter().map(|r| num(r, "critical_load_mN")).collect();
    w.sort_by(f64::total_cmp);
    // ⌈0.95 · 12⌉ = 12: the lowest
    assert_eq!(s["load_at_quantile_mN"].as_f64(), Some(w[0]));
    assert!(s["load_at_quantile_bound_mN"].is_null());
    assert_eq!(s["min_samples_for_bound"].as_u64(), Some(59));
    assert_eq!(s["yield_at_quantile_load"].as_f64(), Some(1.0));
    assert_eq!(s["samples"].as_u64(), Some(12));
    assert_eq!(s["dem"].as_bool(), Some(false));
    assert_eq!(s["fabrication"]["sigma_h_um"].as_f64(), Some(0.002));
    let meta = std::fs::read_to_string(out.join("yield.csv.meta.json")).unwrap();
    assert!(meta.contains("\"fabrication\"") && meta.contains("\"sample_seed\""));
}

/// No randomness (flat substrate, no tolerance): every device is the nominal one, so the yield
/// is a step from 1 to 0 at one critical load, which lies between the nominal superlubric
/// limit of `superlube tolerance` and the next rung of the ladder.
#[test]
fn no_randomness_gives_a_step_at_the_nominal_critical_load() {
    let d = tmpdir("yield-step");
    let out = d.join("y");
    run(
        &[
            "--theta-tol-deg",
            "0",
            "--direction-tol-deg",
            "0",
            "--samples",
            "5",
            "--no-dem",
        ],
        &out,
        "2",
    );
    let m = rows(&out.join("yield.csv"));
    let w: Vec<f64> = m.iter().map(|r| num(r, "critical_load_mN")).collect();
    assert!(w.iter().all(|&x| x == w[0]), "{w:?}");
    let s = summary(&out);
    let curve = s["curve"].as_array().unwrap();
    assert_eq!(curve.len(), 1);
    assert_eq!(curve[0]["load_mN"].as_f64(), Some(w[0]));
    assert_eq!(curve[0]["yield"].as_f64(), Some(1.0));
    // the nominal ladder limit of `tolerance`
    let t = d.join("t");
    let o = bin()
        .args(["tolerance"])
        .args(&SMALL[..8])
        .args(["--theta", "30", "--direction-deg", "0"])
        .args(["--theta-range-deg", "0", "--theta-points", "1"])
        .args(["--direction-range-deg", "0", "--direction-points", "1"])
        .args(["--theta-tol-deg", "0", "--direction-tol-deg", "0", "--out"])
        .arg(&t)
        .output()
        .unwrap();
    assert_ok(&o);
    let nominal = num(&rows(&t.join("map.csv"))[0], "superlubric_to_mN");
    let ladder = [0.01, 0.03, 0.06, 0.09, 0.12, 0.15];
    let next = ladder
        .iter()
        .copied()
        .find(|&x| x > nominal)
        .unwrap_or(f64::INFINITY);
    assert!(
        nominal <= w[0] && w[0] < next,
        "critical load {} outside [{nominal}, {next})",
        w[0]
    );
}

/// Same inputs and seed: identical `yield.csv` with 1 and 2 threads.
#[test]
fn the_same_seed_gives_the_same_rows_whatever_the_threads() {
    let d = tmpdir("yield-threads");
    let flags = ["--sigma-h-um", "0.002", "--samples", "6", "--no-dem"];
    run(&flags, &d.join("one"), "1");
    run(&flags, &d.join("two"), "2");
    let a = std::fs::read(d.join("one/yield.csv")).unwrap();
    let b = std::fs::read(d.join("two/yield.csv")).unwrap();
    assert_eq!(a, b);
}

/// With the DEM: every device's critical load agrees with each of its DEM runs, a located
/// device was held and failed within the resolution, the check's devices are pooled into the
/// rows, the pairs and the band are recorded, and the check's word on the quote is stated.
#[test]
fn the_dem_locates_the_setting_devices_and_checks_the_quote() {
    let d = tmpdir("yield-dem");
    let out = d.join("y");
    run(&DEM, &out, "2");
    let s = summary(&out);
    let m = rows(&out.join("yield.csv"));
    assert_eq!(m.len(), 8, "6 devices and the check's 2 pooled");
    assert_eq!(m.iter().filter(|r| r["check"] == "true").count(), 2);
    for r in &m {
        let c = num(r, "critical_load_mN");
        let runs: Vec<(f64, bool)> = if r["dem_loads_mN"].is_empty() {
            Vec::new()
        } else {
            r["dem_loads_mN"]
                .split(';')
                .zip(r["dem_superlubric"].split(';'))
                .map(|(w, ok)| (w.parse().unwrap(), ok == "true"))
                .collect()
        };
        for &(w, ok) in &runs {
            assert!(if ok { c >= w } else { c <= w }, "{r:?}");
        }
        if r["decided_by"] == "located" {
            let a = runs.iter().filter(|x| x.1).map(|x| x.0).fold(0.0, f64::max);
            let b = runs
                .iter()
                .filter(|x| !x.1)
                .map(|x| x.0)
                .fold(f64::INFINITY, f64::min);
            assert!(a == c && b > a && b - a <= 0.0101 * b, "{r:?}");
        }
        if r["decided_by"] == "dem" || r["decided_by"] == "located" {
            assert!(!runs.is_empty(), "{r:?}");
        }
    }
    let located = m.iter().filter(|r| r["decided_by"] == "located").count();
    assert_eq!(s["located"].as_array().unwrap().len(), located);
    assert!(s["dem_runs"].as_u64().unwrap() >= 2);
    assert!(s["dem_runs"].as_u64() <= s["dem_runs_allowed"].as_u64());
    assert_eq!(s["pooled"].as_u64(), Some(8));
    assert_eq!(s["dem_check_total"].as_u64(), Some(2));
    assert!(s["dem_check_passed"].as_u64().unwrap() <= 2);
    assert_eq!(s["dem_check_interval"].as_array().unwrap().len(), 2);
    assert!(s["dem_check_consistent"].is_boolean(), "{s}");
    assert!(!s["pairs"].as_array().unwrap().is_empty(), "{s}");
    assert!(s["band"]["p_ratio"].is_array(), "{s}");
    assert!(out.join("dem").is_dir());
}

/// `--no-dem` with a DEM check asked for is a contradiction, refused naming both flags.
#[test]
fn a_dem_check_without_the_dem_is_refused() {
    let d = tmpdir("yield-no-dem-check");
    let out = d.join("never");
    let mut a: Vec<&str> = vec!["yield"];
    a.extend(SMALL);
    a.extend([
        "--no-dem",
        "--dem-check",
        "5",
        "--out-dir",
        out.to_str().unwrap(),
    ]);
    fails_naming(&a, "--dem-check");
    assert!(!out.exists());
}

/// Bad input is refused naming the flag, before any work (nothing written).
#[test]
fn bad_input_is_refused_naming_the_flag() {
    let d = tmpdir("yield-bad");
    let out = d.join("never");
    let o = out.to_str().unwrap();
    let base = |extra: &[&str]| -> Vec<String> {
        let mut v: Vec<String> = vec!["yield".into()];
        v.extend(SMALL.iter().map(|s| s.to_string()));
        v.extend(extra.iter().map(|s| s.to_string()));
        v.extend(["--out-dir".to_string(), o.to_string()]);
        v
    };
    for (extra, flag) in [
        (&["--quantile", "1"][..], "--quantile"),
        (&["--quantile", "0"][..], "--quantile"),
        (&["--confidence", "1.5"][..], "--confidence"),
        (&["--samples", "0"][..], "--samples"),
        (
            &["--sphere-diameter-cv", "-0.1"][..],
            "--sphere-diameter-cv",
        ),
        (
            &["--sphere-diameter-cv", "0.05"][..],
            "--sphere-diameter-cv",
        ),
        (&["--p-crit-sigma-gpa", "-1"][..], "--p-crit-sigma-gpa"),
        (&["--p-crit-sigma-gpa", "2"][..], "--p-crit-sigma-gpa"),
        (&["--theta-sigma-deg", "-0.1"][..], "--theta-sigma-deg"),
        (&["--resolution", "0"][..], "--resolution"),
        (&["--searched-seeds", "1,x"][..], "--searched-seeds"),
        (&["--dem-max-runs", "3"][..], "--dem-max-runs"),
    ] {
        let args = base(extra);
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        fails_naming(&refs, flag);
    }
    assert!(!out.exists(), "nothing is written for bad input");
}

/// A yield killed (SIGKILL) once some of its DEM runs are stored, then run again into the same
/// folder, reruns none of them (each stored `slide.json` keeps its bytes and time), and ends
/// with the same rows as an uninterrupted run on 1 thread in a fresh folder.
#[test]
fn a_killed_yield_resumes_reusing_its_dem_runs_whatever_the_threads() {
    let d = tmpdir("yield-kill");
    let flags = DEM;
    let out = d.join("y");
    let mut child = bin()
        .arg("yield")
        .args(SMALL)
        .args(flags)
        .arg("--out-dir")
        .arg(&out)
        .env("RAYON_NUM_THREADS", "2")
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let stored = |dir: &Path| -> Vec<(std::path::PathBuf, std::time::SystemTime)> {
        let mut v: Vec<_> = std::fs::read_dir(dir.join("dem"))
            .map(|r| {
                r.filter_map(|e| {
                    let p = e.ok()?.path().join("slide.json");
                    let t = std::fs::metadata(&p).ok()?.modified().ok()?;
                    Some((p, t))
                })
                .collect()
            })
            .unwrap_or_default();
        v.sort();
        v
    };
    let t0 = std::time::Instant::now();
    while stored(&out).len() < 2 && t0.elapsed().as_secs() < 300 {
        if child.try_wait().unwrap().is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    child.kill().ok();
    child.wait().unwrap();
    let before = stored(&out);
    assert!(!before.is_empty(), "no DEM run was stored before the kill");
    run(&flags, &out, "2");
    let after = stored(&out);
    for (p, t) in &before {
        let kept = after.iter().find(|(q, _)| q == p).map(|x| x.1);
        assert_eq!(kept, Some(*t), "{} was run again", p.display());
    }
    let fresh = d.join("fresh");
    run(&flags, &fresh, "1");
    assert_eq!(
        std::fs::read(out.join("yield.csv")).unwrap(),
        std::fs::read(fresh.join("yield.csv")).unwrap()
    );
    std::fs::remove_dir_all(&d).ok();
}
