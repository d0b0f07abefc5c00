//! `superlube design`'s yield stage (on by default; `--yield-samples N` sets its devices) on a
//! small scene without the DEM: each answer's `yield_<p>.csv` (one row per device, its seed
//! never the scene's nor a searched one), `yield_<p>.json` and `yield_<p>.png` with sidecars,
//! the report's "load at 95 % yield" column giving the summary's load and bound, and the
//! answer's fabrication sentence; with `--no-yield` no yield file is written, the report has
//! no such column and every other output is the same bytes; bad yield flags are refused
//! naming the flag.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir, SMALL_SCENE};
use std::path::Path;

/// With [`SMALL_SCENE`] (square-tri on a 15 µm slider, ≈ 80 spheres): a rough substrate
/// searched on seeds 1 and 2, θ every 1°, a ladder of loads scaled to its sphere count, the
/// default tolerance box.
const SMALL: [&str; 8] = [
    "--sigma-h-um",
    "0.002",
    "--seeds",
    "1,2",
    "--theta",
    "0:30:1",
    "--load-mn",
    "0.01,0.03,0.06,0.09,0.12,0.15",
];

fn design(extra: &[&str], out: &Path) -> std::process::Output {
    bin()
        .arg("design")
        .args(SMALL_SCENE)
        .args(SMALL)
        .args(["--no-dem"])
        .args(extra)
        .arg("--out-dir")
        .arg(out)
        .output()
        .unwrap()
}

#[test]
fn the_yield_stage_writes_its_files_and_the_report_column_and_leaves_the_rest_unchanged() {
    let d = tmpdir("design-yield");
    let (on, off) = (d.join("on"), d.join("off"));
    let o = design(&["--yield-samples", "12"], &on);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(
        log.contains(
            "square-tri: yield of the answer over fabrication: 95 % of devices made within the tolerance hold"
        ),
        "{log}"
    );
    assert_ok(&design(&["--no-yield"], &off));
    for f in [
        "yield_square-tri.csv",
        "yield_square-tri.json",
        "yield_square-tri.png",
    ] {
        assert!(on.join(f).exists(), "{f} missing");
        assert!(on.join(format!("{f}.meta.json")).exists(), "{f} sidecar");
        assert!(!off.join(f).exists(), "{f} written with --no-yield");
    }
    // one row per device; every drawn substrate seed differs from the scene's (0) and the
    // searched ones (1, 2)
    let mut r = csv::Reader::from_path(on.join("yield_square-tri.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let seed = h.iter().position(|c| c == "seed").unwrap();
    let rows: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 12);
    for row in &rows {
        let s: u64 = row[seed].parse().unwrap();
        assert!(![0, 1, 2].contains(&s), "drawn seed {s} was searched");
    }
    // the summary is for the answer, and the report's cell gives its load and bound
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(on.join("yield_square-tri.json")).unwrap())
            .unwrap();
    assert_eq!(s["samples"], 12);
    let load = s["load_at_quantile_mN"].as_f64().expect("a quoted load");
    let report = std::fs::read_to_string(on.join("report.md")).unwrap();
    assert!(
        report.contains("| load at 95 % yield (mN; ≥ its 95 % bound) |"),
        "{report}"
    );
    let row = report
        .lines()
        .find(|l| l.starts_with("| square-tri |"))
        .unwrap();
    // the cell: the quoted load to 3 significant digits, no bound from 12 devices
    let cell = row.split(" | ").nth(5).unwrap();
    let (shown, rest) = cell.split_once(' ').unwrap();
    let shown: f64 = shown.parse().unwrap();
    assert!((shown - load).abs() <= 0.005 * load, "{row}");
    assert_eq!(rest, "(no bound: 12 devices, needs ≥ 59)", "{row}");
    assert!(report.contains("](yield_square-tri.png)"), "{report}");
    assert!(
        report.contains("**Fabrication**: 95 % of devices made within the tolerance hold"),
        "{report}"
    );
    let sidecar = std::fs::read_to_string(on.join("yield_square-tri.csv.meta.json")).unwrap();
    assert!(sidecar.contains("\"sample_seed\""), "{sidecar}");
    // without the stage: no yield column, and every shared output the same bytes (the
    // sidecars record the command line, the report its stamp and the yield)
    let plain = std::fs::read_to_string(off.join("report.md")).unwrap();
    assert!(
        !plain.contains("% yield") && !plain.contains("yield_"),
        "{plain}"
    );
    for f in [
        "ranking.csv",
        "patterns.csv",
        "shortlist_square-tri.csv",
        "friction_square-tri.csv",
        "tolerance_square-tri.csv",
        "answer_square-tri.toml",
    ] {
        assert_eq!(
            std::fs::read(on.join(f)).unwrap(),
            std::fs::read(off.join(f)).unwrap(),
            "{f} differs with the yield stage"
        );
    }
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn bad_yield_flags_name_the_flag() {
    let d = tmpdir("design-yield-bad");
    let out = d.join("x");
    let o = out.to_str().unwrap();
    let run = |extra: &[&str], flag: &str| {
        let mut a: Vec<&str> = vec!["design", "--pattern", "square-tri", "--no-dem"];
        a.extend(extra);
        a.extend(["--out-dir", o]);
        fails_naming(&a, flag);
    };
    run(&["--yield-samples", "0"], "--yield-samples");
    run(
        &["--yield-samples", "5", "--yield-quantile", "1.5"],
        "--yield-quantile",
    );
    run(
        &["--yield-samples", "5", "--yield-confidence", "0"],
        "--yield-confidence",
    );
    run(&["--no-yield", "--yield-samples", "5"], "--no-yield");
    run(&["--yield-dem-max-runs", "4"], "--yield-dem-max-runs");
    assert!(!out.join("report.md").exists());
    std::fs::remove_dir_all(&d).ok();
}

/// `--rank-by yield`: the top designs are ordered by their load at 95 % yield (best first,
/// `yield_rank.csv`), the ranking's rank 1 is the first of them, the answer's own yield (the
/// same devices, no DEM) gives the load it was ranked by, and the report says how it ranked.
#[test]
fn rank_by_yield_orders_the_top_designs_by_their_load_at_yield() {
    let d = tmpdir("design-rank-yield");
    let out = d.join("y");
    let o = design(&["--rank-by", "yield", "--yield-samples", "12"], &out);
    assert_ok(&o);
    let mut r = csv::Reader::from_path(out.join("yield_rank.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let (rank, theta, alpha, load) = (
        col("rank"),
        col("theta_deg"),
        col("alpha_deg"),
        col("load_at_yield_mN"),
    );
    let rows: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    assert!(!rows.is_empty() && rows.len() <= 3, "{rows:?}");
    let loads: Vec<f64> = rows.iter().map(|x| x[load].parse().unwrap()).collect();
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[rank].parse::<usize>().unwrap(), k + 1, "{rows:?}");
    }
    assert!(loads.windows(2).all(|w| w[0] >= w[1]), "{loads:?}");
    // rank 1 of ranking.csv is the first ranked by yield
    let mut rk = csv::Reader::from_path(out.join("ranking.csv")).unwrap();
    let hk = rk.headers().unwrap().clone();
    let first = rk.records().next().unwrap().unwrap();
    let at = |n: &str| first[hk.iter().position(|c| c == n).unwrap()].to_string();
    assert_eq!(at("theta_deg"), rows[0][theta].to_string());
    assert_eq!(at("alpha_deg"), rows[0][alpha].to_string());
    // the answer's yield: the same 12 devices, so the same load (no bound from 12 devices)
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("yield_square-tri.json")).unwrap())
            .unwrap();
    assert_eq!(s["load_at_quantile_mN"].as_f64().unwrap(), loads[0]);
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(
        report.contains("**Ranked by yield** (`--rank-by yield`)"),
        "{report}"
    );
    // each ranked design's devices are stored: the answer's yield reused them, and a re-run
    // recomputes none and writes the same ranking
    let log = String::from_utf8_lossy(&o.stderr);
    let estimated = log.matches("yield: critical loads: 100%").count();
    assert_eq!(estimated, rows.len(), "{log}");
    let before = std::fs::read(out.join("yield_rank.csv")).unwrap();
    let again = design(&["--rank-by", "yield", "--yield-samples", "12"], &out);
    assert_ok(&again);
    let log = String::from_utf8_lossy(&again.stderr);
    assert!(!log.contains("yield: critical loads"), "{log}");
    assert_eq!(std::fs::read(out.join("yield_rank.csv")).unwrap(), before);
    // its answers differ from the worst case's: the two never share a folder
    let o = design(&["--yield-samples", "12"], &out);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("rank_by_yield"), "{err}");
    std::fs::remove_dir_all(&d).ok();
}
