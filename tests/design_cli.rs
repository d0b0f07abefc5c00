//! `superlube design` (issue 8, points 3 and "Checks") on small scenes: `--no-dem` writes the
//! report, the ranking and the CSVs/PNGs behind them with sidecars; a second run with the same
//! `--out` recomputes nothing (the log says every stage was reused and no file — stage or final
//! output — changes its modification time); a changed input with the same `--out` is refused
//! naming what differs, before any work; bad input is refused naming the flag; the DEM stage
//! runs its runs side by side, writes dem.csv with μ_est next to μ_DEM, reuses finished runs,
//! and reports failed runs while the design still completes.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// Both default patterns on a 15 µm slider (≈ 80 spheres), θ every 1°, four loads scaled to the
/// sphere count of the study's 0.35–3.86 mN.
const SMALL: [&str; 8] = [
    "--slider-radius-um",
    "15",
    "--substrate-um",
    "60x60",
    "--theta",
    "0:30:1",
    "--load-mn",
    "0.01,0.03,0.06,0.09",
];

/// `superlube design` on [`SMALL`] with `extra`; the nominal design (no fabrication tolerance)
/// unless `extra` sets one (tolerance: tests/tolerance_cli.rs).
fn design(extra: &[&str], out: &Path) -> std::process::Output {
    let nominal: &[&str] = if extra.contains(&"--theta-tol-deg") {
        &[]
    } else {
        &["--theta-tol-deg", "0", "--direction-tol-deg", "0"]
    };
    bin()
        .arg("design")
        .args(SMALL)
        .args(nominal)
        .args(extra)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

/// Every file under `dir` with its modification time.
fn mtimes(dir: &Path) -> BTreeMap<PathBuf, SystemTime> {
    let mut m = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let e = e.unwrap();
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else {
                m.insert(p, e.metadata().unwrap().modified().unwrap());
            }
        }
    }
    m
}

#[test]
fn no_dem_writes_the_report_and_a_second_run_recomputes_nothing() {
    let d = tmpdir("design-nodem");
    let out = d.join("run");
    let o = design(&["--no-dem"], &out);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(log.contains("square-tri: screened"), "{log}");
    assert!(log.contains("α scan + friction"), "{log}");
    for f in [
        "report.md",
        "ranking.csv",
        "design.json",
        "screen_square-tri.csv",
        "screen_tri-tri.csv",
        "shortlist_square-tri.csv",
        "shortlist_tri-tri.csv",
        "corrugation_square-tri.csv",
        "friction_square-tri.csv",
        "friction_tri-tri.csv",
        "pmax_square-tri.png",
        "corrugation_tri-tri.png",
        "mu_square-tri.png",
    ] {
        assert!(out.join(f).exists(), "{f} missing");
        if f != "design.json" {
            assert!(out.join(format!("{f}.meta.json")).exists(), "{f} sidecar");
        }
    }
    assert!(!out.join("dem.csv").exists());
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    let answer = report.find("## Answer").unwrap();
    let ranking = report.find("## Ranking").unwrap();
    assert!(answer < ranking, "the answer comes first");
    for s in [
        "**square-tri**",
        "**tri-tri**",
        "superlubric up to",
        "--no-dem",
        "## Wall time per tier",
        "superlube screen --pattern square-tri",
        "superlube friction --pattern tri-tri",
        "domain [0°, 15°]",
        "domain [0°, 30°]",
    ] {
        assert!(report.contains(s), "report lacks `{s}`");
    }
    // the ranking: ranks from 1 within each pattern, ordered by the score
    let mut r = csv::Reader::from_path(out.join("ranking.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    assert_eq!(&h[0], "rank");
    assert!(h.iter().any(|c| c == "superlubric_to_mN"));
    let recs: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    assert!(recs.len() >= 6);
    let sl = h.iter().position(|c| c == "superlubric_to_mN").unwrap();
    for p in ["square-tri", "tri-tri"] {
        let mine: Vec<&csv::StringRecord> = recs.iter().filter(|x| &x[1] == p).collect();
        assert_eq!(&mine[0][0], "1");
        for w in mine.windows(2) {
            let (a, b): (f64, f64) = (w[0][sl].parse().unwrap(), w[1][sl].parse().unwrap());
            assert!(a >= b, "{p}: ranking not ordered by the superlubric load");
        }
    }
    // the report's commands reproduce the rows: the screen byte for byte, the friction rows of
    // the first evaluated orientation of each pattern line for line
    let cmds: Vec<&str> = report
        .lines()
        .filter(|l| l.starts_with("superlube screen ") || l.starts_with("superlube friction "))
        .collect();
    for p in ["square-tri", "tri-tri"] {
        for kind in ["screen", "friction"] {
            let cmd = cmds
                .iter()
                .find(|l| l.starts_with(&format!("superlube {kind} --pattern {p} ")))
                .unwrap_or_else(|| panic!("no {kind} command for {p}"));
            let mut words: Vec<&str> = cmd.split_whitespace().skip(1).collect();
            if let Some(k) = words.iter().position(|w| *w == "--out") {
                words.truncate(k);
            }
            let mine = d.join(format!("{kind}-{p}.csv"));
            let o = bin().args(&words).arg("--out").arg(&mine).output().unwrap();
            assert_ok(&o);
            let got = std::fs::read_to_string(&mine).unwrap();
            let design_file = std::fs::read_to_string(out.join(format!("{kind}_{p}.csv"))).unwrap();
            if kind == "screen" {
                assert_eq!(got, design_file, "{cmd}");
            } else {
                let mut n = 0;
                for line in got.lines().skip(1) {
                    let key: Vec<&str> = line.split(',').take(4).collect();
                    if let Some(d) = design_file
                        .lines()
                        .find(|l| l.split(',').take(4).collect::<Vec<_>>() == key)
                    {
                        assert_eq!(d, line, "{cmd}");
                        n += 1;
                    }
                }
                assert!(n >= 1, "{cmd}: no row of the design reproduced");
            }
        }
    }
    // the friction estimate of a candidate stops at the first load whose coating fails on the
    // path (P_max > P_crit = 4 GPa): no row of the same (θ, α) follows a failed one (2 did on
    // tri-tri before the early stop)
    for p in ["square-tri", "tri-tri"] {
        let mut r = csv::Reader::from_path(out.join(format!("friction_{p}.csv"))).unwrap();
        let h = r.headers().unwrap().clone();
        let col = |n: &str| h.iter().position(|c| c == n).unwrap();
        let (t, a, pm, e) = (
            col("theta_deg"),
            col("alpha_deg"),
            col("p_max_GPa"),
            col("error"),
        );
        let recs: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
        for w in recs.windows(2) {
            if w[0][t] == w[1][t] && w[0][a] == w[1][a] {
                let failed = !w[0][e].is_empty() || w[0][pm].parse::<f64>().unwrap() > 4.0;
                assert!(!failed, "{p}: a row follows a failed one: {:?}", w[1]);
            }
        }
    }
    // the screen stage holds the cut θ (square-tri: 0–15°, 16 θ × 4 loads)
    let screen = std::fs::read_to_string(out.join("screen_square-tri.csv")).unwrap();
    assert_eq!(screen.lines().count(), 1 + 16 * 4);
    let before = mtimes(&out);
    std::thread::sleep(std::time::Duration::from_millis(1100));
    // second run: every stage reused, no file touched
    let o = design(&["--no-dem"], &out);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(log.contains("square-tri: screen reused"), "{log}");
    assert!(log.contains("tri-tri: screen reused"), "{log}");
    assert!(log.contains("nothing rewritten"), "{log}");
    assert!(!log.contains("screened 16"), "{log}");
    assert_eq!(mtimes(&out), before, "a file was rewritten");
    // an interruption that lost one orientation's stage file and the report: only those are
    // made again (with the same content), every other stage file is reused untouched
    let stage_dir = out.join("stages/tri-tri");
    let lost = std::fs::read_dir(&stage_dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| {
            let n = p.file_name().unwrap().to_string_lossy().into_owned();
            n.starts_with("theta_") && n.ends_with(".json") && !n.ends_with(".meta.json")
        })
        .unwrap();
    let lost_bytes = std::fs::read(&lost).unwrap();
    let lost_eval: serde_json::Value = serde_json::from_slice(&lost_bytes).unwrap();
    std::fs::remove_file(&lost).unwrap();
    std::fs::remove_file(out.join("report.md")).unwrap();
    let o = design(&["--no-dem"], &out);
    assert_ok(&o);
    let again: serde_json::Value = serde_json::from_slice(&std::fs::read(&lost).unwrap()).unwrap();
    assert_eq!(again["eval"], lost_eval["eval"], "recomputed stage differs");
    let after = mtimes(&out);
    for (f, t) in &before {
        let remade = f == &lost
            || f.ends_with("report.md")
            || f.to_string_lossy().contains(&*lost.to_string_lossy())
            || f.ends_with("report.md.meta.json");
        if !remade {
            assert_eq!(after.get(f), Some(t), "{} was rewritten", f.display());
        }
    }
    let before = after;
    // a changed input with the same --out is refused, naming the difference; nothing changes
    let o = bin()
        .arg("design")
        .args(&SMALL[..6])
        .args(["--theta-tol-deg", "0", "--direction-tol-deg", "0"])
        .args(["--load-mn", "0.01,0.03,0.06,0.08", "--no-dem", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("other inputs") && err.contains("load_mN") && err.contains("--out"),
        "{err}"
    );
    assert_eq!(mtimes(&out), before);
    // a stage file made with other inputs is never mixed in
    let stage = out.join("screen_tri-tri.csv.meta.json");
    let text = std::fs::read_to_string(&stage).unwrap();
    std::fs::write(&stage, text.replace("\"sha256:", "\"sha256:0")).unwrap();
    let o = design(&["--no-dem"], &out);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("screen_tri-tri.csv") && err.contains("other inputs"),
        "{err}"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn bad_input_names_the_flag() {
    let d = tmpdir("design-bad");
    let out = d.join("x");
    let o = out.to_str().unwrap();
    let run = |extra: &[&str], flag: &str| {
        let mut a: Vec<&str> = vec![
            "design",
            "--slider-radius-um",
            "15",
            "--substrate-um",
            "60x60",
        ];
        a.extend(extra);
        a.extend(["--out", o]);
        fails_naming(&a, flag);
    };
    run(&["--confirm", "0"], "--confirm");
    run(
        &["--pattern", "square-tri", "--theta", "20:25:1"],
        "--theta",
    );
    run(&["--pattern", "hexagon-tri"], "--pattern");
    run(&["--load-mn", "0.05,0.03"], "--load-mn");
    run(&["--load-mn", "0.05,0.05"], "--load-mn");
    run(
        &["--load-mn", "0.01,0.05", "--confirm-loads-mn", "0.02"],
        "--confirm-loads-mn",
    );
    run(&["--alpha-refine-deg", "5,10"], "--alpha-refine-deg");
    run(&["--jobs", "0"], "--jobs");
    // the symmetry cut's message gives the domain and an equivalent orientation
    let e = bin()
        .args([
            "design",
            "--pattern",
            "square-tri",
            "--theta",
            "20:25:1",
            "--out",
            o,
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&e.stderr);
    assert!(
        err.contains("[0°, 15°]") && err.contains("20° ≡ 10°"),
        "{err}"
    );
    assert!(!out.exists(), "nothing may be written");
    // a slider that fits at its placement but leaves the substrate along a 12 µm path
    let e = bin()
        .args([
            "design",
            "--slider-radius-um",
            "15",
            "--substrate-um",
            "40x40",
            "--theta",
            "0:30:1",
            "--out",
            o,
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&e.stderr);
    assert!(
        !e.status.success()
            && err.contains("friction.length_um")
            && err.contains("pattern `square-tri`"),
        "{err}"
    );
    assert!(
        !out.exists(),
        "nothing may be written before the paths are checked"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn dem_stage_runs_side_by_side_reuses_runs_and_reports_failures() {
    let d = tmpdir("design-dem");
    let out = d.join("run");
    let proto = [
        "--pattern",
        "square-tri",
        "--confirm",
        "1",
        "--confirm-loads-mn",
        "0.01,0.09",
        "--dem-equilibrate-us",
        "0.1",
        "--dem-relax-us",
        "0.05",
        "--dem-slide-us",
        "0.3",
        "--no-protocol-check",
        "--jobs",
        "2",
    ];
    // first without the DEM, then the DEM added to the same --out: the surrogate is reused
    assert_ok(&design(&["--pattern", "square-tri", "--no-dem"], &out));
    let o = design(&proto, &out);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(log.contains("screen reused"), "{log}");
    assert!(log.contains("DEM: 2 runs, 2 side by side"), "{log}");
    let dem = std::fs::read_to_string(out.join("dem.csv")).unwrap();
    let mut r = csv::Reader::from_reader(dem.as_bytes());
    let h = r.headers().unwrap().clone();
    let recs: Vec<csv::StringRecord> = r.records().map(Result::unwrap).collect();
    assert_eq!(recs.len(), 2);
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    for x in &recs {
        assert_ne!(&x[col("status")], "failed", "{x:?}");
        let mu: f64 = x[col("mu_dem")].parse().unwrap();
        let est: f64 = x[col("mu_est")].parse().unwrap();
        assert!(mu.is_finite() && est.is_finite());
        let ratio: f64 = x[col("ratio_est_dem")].parse().unwrap();
        assert!((ratio - est / mu).abs() <= 1e-9 * ratio.abs());
        let dir = out.join(&x[col("run_dir")]);
        assert!(dir.join("slide.json").exists() && dir.join("slide.json.meta.json").exists());
    }
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("shorter than the study's"), "{report}");
    assert!(report.contains("μ_est/μ_DEM"));
    assert!(report.contains("superlube slide --pattern square-tri"));
    // the runs are reused by a re-run
    let before = mtimes(&out);
    let o = design(&proto, &out);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(log.contains("DEM: 2 of 2 runs reused"), "{log}");
    assert_eq!(mtimes(&out), before);
    // a DEM protocol that blows up: the failure is reported, the design completes
    let bad = d.join("bad");
    let mut p2: Vec<&str> = proto.to_vec();
    p2.extend(["--dem-dt-us", "0.05"]);
    let o = design(&p2, &bad);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(
        log.contains("FAILED") && log.contains("DEM run(s) failed"),
        "{log}"
    );
    let dem = std::fs::read_to_string(bad.join("dem.csv")).unwrap();
    assert!(dem.contains(",failed,"), "{dem}");
    let report = std::fs::read_to_string(bad.join("report.md")).unwrap();
    assert!(report.contains("| failed:"), "{report}");
    std::fs::remove_dir_all(&d).ok();
}

/// `--shard i/n` computes a share of the DEM runs and no report; the call without it reuses
/// every shard's runs (none recomputed) and writes the same dem.csv as an unsharded design.
#[test]
fn dem_stage_in_shards_then_the_report() {
    let d = tmpdir("design-shard");
    let proto = [
        "--pattern",
        "square-tri",
        "--confirm",
        "1",
        "--confirm-loads-mn",
        "0.01,0.06,0.09",
        "--dem-equilibrate-us",
        "0.1",
        "--dem-relax-us",
        "0.05",
        "--dem-slide-us",
        "0.3",
        "--no-protocol-check",
        "--jobs",
        "1",
    ];
    let sharded = d.join("sharded");
    for s in ["0/2", "1/2"] {
        let o = design(&[&proto[..], &["--shard", s]].concat(), &sharded);
        assert_ok(&o);
        let log = String::from_utf8_lossy(&o.stderr);
        assert!(log.contains(&format!("DEM shard {s}")), "{log}");
        assert!(
            !sharded.join("report.md").exists(),
            "no report from a shard"
        );
    }
    let o = design(&proto, &sharded);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(log.contains("DEM: 3 of 3 runs reused"), "{log}");
    let whole = d.join("whole");
    assert_ok(&design(&proto, &whole));
    // dem.csv without the wall-time column
    let strip = |p: &Path| -> Vec<String> {
        let t = std::fs::read_to_string(p).unwrap();
        let mut r = csv::Reader::from_reader(t.as_bytes());
        let h = r.headers().unwrap().clone();
        let w = h.iter().position(|c| c == "wall_s").unwrap();
        r.records()
            .map(|x| {
                let x = x.unwrap();
                x.iter()
                    .enumerate()
                    .filter(|(i, _)| *i != w)
                    .map(|(_, v)| v.to_string())
                    .collect::<Vec<_>>()
                    .join(",")
            })
            .collect()
    };
    assert_eq!(
        strip(&sharded.join("dem.csv")),
        strip(&whole.join("dem.csv"))
    );
    // bad shards are named
    let e = design(&[&proto[..], &["--shard", "2/2"]].concat(), &d.join("bad"));
    assert!(!e.status.success());
    assert!(String::from_utf8_lossy(&e.stderr).contains("--shard"));
    std::fs::remove_dir_all(&d).ok();
}

/// A rough substrate (σ_h = 10 nm) on which no tri-tri design holds the ladder's first load
/// over the default tolerance box: the answer is not 0 but the load located below the first
/// rung (by bisection over the same samples, down to 1 % of it), with its meaning.
#[test]
fn a_robust_limit_below_the_ladder_is_located_not_zero() {
    let d = tmpdir("design_below_ladder");
    let out = bin()
        .args([
            "design",
            "--pattern",
            "tri-tri",
            "--sigma-h-um",
            "0.01",
            "--no-dem",
        ])
        .arg("--out-dir")
        .arg(&d)
        .output()
        .unwrap();
    assert_ok(&out);
    let report = std::fs::read_to_string(d.join("report.md")).unwrap();
    let row = report
        .lines()
        .find(|l| l.starts_with("| tri-tri |"))
        .unwrap_or_else(|| panic!("no answer row in {report}"));
    let cell = row.split('|').nth(5).unwrap().trim();
    let w: f64 = cell
        .strip_suffix("(below the ladder)")
        .unwrap_or_else(|| panic!("robust limit cell `{cell}`"))
        .trim()
        .parse()
        .unwrap();
    assert!(w > 0.35 * 0.01 && w < 0.35, "{w}");
    assert!(
        report.contains("Below the ladder's first load (0.35 mN)"),
        "{report}"
    );
}
