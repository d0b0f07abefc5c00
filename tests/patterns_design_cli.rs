//! `superlube design` over patterns through the command line: over a list of patterns and over
//! a generated family, each pattern's geometry and best design written; the whole θ domain
//! screened without `--theta`; only the patterns that can win searched.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};

/// `design --patterns`: `patterns.csv` puts each candidate's geometry and the index's facts
/// beside its best design.
#[test]
fn design_over_patterns_writes_each_patterns_geometry_and_best_design() {
    let dir = tmpdir("patterns-design");
    let small = ["--slider-radius-um", "15", "--substrate-um", "60x60"];
    let o = bin()
        .args(["patterns", "--family", "directional", "--max-pq", "2"])
        .args(small)
        .arg("--out")
        .arg(dir.join("c"))
        .output()
        .unwrap();
    assert_ok(&o);
    let o = bin()
        .args(["design", "--no-dem", "--theta", "0:30:2", "--patterns"])
        .arg(dir.join("c/index.csv"))
        .args(["--theta-tol-deg", "0", "--direction-tol-deg", "0"])
        .args(small)
        .args(["--load-mn", "0.01,0.03,0.06", "--out"])
        .arg(dir.join("d"))
        .output()
        .unwrap();
    assert_ok(&o);
    let index = std::fs::read_to_string(dir.join("c/index.csv")).unwrap();
    let mut r = csv::Reader::from_path(dir.join("d/patterns.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), index.lines().count() - 1);
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    // best first: ranks 1, 2, …, the robust limit never rising down the table
    let limits: Vec<f64> = rows
        .iter()
        .map(|r| r[col("superlubric_to_mN")].parse().unwrap())
        .collect();
    assert!(limits.windows(2).all(|w| w[0] >= w[1]), "{limits:?}");
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[col("rank")], (k + 1).to_string());
    }
    for row in &rows {
        assert_eq!(&row[col("contact_type")], "directional");
        assert!(!row[col("p_q")].is_empty());
        let spheres: f64 = row[col("spheres")].parse().unwrap();
        let w: f64 = row[col("superlubric_to_mN")].parse().unwrap();
        let per: f64 = row[col("load_per_sphere_uN")].parse().unwrap();
        assert!(
            (per - w * 1e3 / spheres).abs() <= 1e-6 * per.max(1e-9),
            "{row:?}"
        );
    }
    // The report compares the patterns in one table: a row per pattern, its spheres beside it.
    let report = std::fs::read_to_string(dir.join("d/report.md")).unwrap();
    let table = report
        .split("## Patterns compared")
        .nth(1)
        .expect("a 'Patterns compared' section")
        .split("\n## ")
        .next()
        .unwrap();
    // the fairness rule, from the index's sidecar (`--fair area`, the default)
    assert!(
        table.contains("Compared at **equal slider area**: the candidates were made with `superlube patterns --fair area`"),
        "{table}"
    );
    for row in &rows {
        let line = format!(
            "| {} | {} | {} | {} |",
            &row[col("rank")],
            &row[col("pattern")],
            &row[col("outline")],
            &row[col("spheres")]
        );
        assert!(table.contains(&line), "{line} not in\n{table}");
    }
    // The limit against the family's parameter, and the contact maps of the best (at most 3)
    // patterns: the ones with the highest robust limit in patterns.csv.
    assert!(dir.join("d/patterns.png").exists());
    assert!(table.contains("](patterns.png)"));
    let best = rows
        .iter()
        .map(|r| r[col("superlubric_to_mN")].parse::<f64>().unwrap())
        .fold(0.0, f64::max);
    let maps: Vec<&str> = table
        .split("](contacts_")
        .skip(1)
        .map(|t| t.split(".png)").next().unwrap())
        .collect();
    assert!(!maps.is_empty() && maps.len() <= 3, "{maps:?}");
    let first = rows.iter().find(|r| &r[col("pattern")] == maps[0]).unwrap();
    assert_eq!(
        first[col("superlubric_to_mN")].parse::<f64>().unwrap(),
        best
    );
    for m in &maps {
        assert!(dir.join(format!("d/contacts_{m}.png")).exists(), "{m}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `design --family SPEC` generates the candidates into OUT/patterns/ and designs them exactly
/// as `patterns` + `design --patterns` would; a bad family is refused before anything is written.
#[test]
fn design_family_generates_and_designs_the_candidates() {
    let dir = tmpdir("design-family");
    let small = ["--slider-radius-um", "15", "--substrate-um", "60x60"];
    let design = [
        "design",
        "--no-dem",
        "--theta",
        "0:30:2",
        "--load-mn",
        "0.01,0.03",
    ];
    let tol0 = ["--theta-tol-deg", "0", "--direction-tol-deg", "0"];
    let family = "rectangular:a=3:3.5:0.5,b=3";
    let o = bin()
        .args(design)
        .args(["--family", family])
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("f"))
        .output()
        .unwrap();
    assert_ok(&o);
    assert!(
        String::from_utf8_lossy(&o.stderr)
            .contains("candidates in the contact-type pre-screen's order"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    fails_naming(
        &[
            "design",
            "--no-dem",
            "--normalize",
            "spheres",
            "--out-dir",
            "/tmp/x",
        ],
        "--family",
    );
    // --normalize spheres: candidates of (about) the base slider's sphere count, and the report
    // says that this is the rule of the comparison
    let o = bin()
        .args([
            "design",
            "--no-dem",
            "--theta",
            "0:30:10",
            "--load-mn",
            "0.01",
        ])
        .args(["--family", "presets:s=3:3.5:0.5", "--normalize", "spheres"])
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("n"))
        .output()
        .unwrap();
    assert_ok(&o);
    let index = std::fs::read_to_string(dir.join("n/patterns/index.csv")).unwrap();
    let spheres: Vec<f64> = index
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(5).unwrap().parse().unwrap())
        .collect();
    assert!(spheres.len() >= 3, "{index}");
    let (lo, hi) = spheres
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    assert!(hi <= 1.1 * lo, "{spheres:?}");
    let report = std::fs::read_to_string(dir.join("n/report.md")).unwrap();
    assert!(
        report.contains("Compared at **equal sphere count**: the candidates were made with `superlube patterns --fair count`"),
        "{report}"
    );
    let o = bin()
        .args(["patterns", "--family", family])
        .args(small)
        .arg("--out-dir")
        .arg(dir.join("c"))
        .output()
        .unwrap();
    assert_ok(&o);
    let o = bin()
        .args(design)
        .arg("--patterns")
        .arg(dir.join("c/index.csv"))
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("p"))
        .output()
        .unwrap();
    assert_ok(&o);
    let read = |p: &str| std::fs::read_to_string(dir.join(p)).unwrap();
    assert_eq!(read("f/patterns/index.csv"), read("c/index.csv"));
    // another family into the same folder is refused, its candidates untouched
    let before = read("f/patterns/index.csv");
    let o = bin()
        .args(design)
        .args(["--family", "rectangular:a=3.5,b=3"])
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("f"))
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("`--family`"));
    assert_eq!(read("f/patterns/index.csv"), before);
    assert_eq!(read("f/patterns.csv"), read("p/patterns.csv"));
    assert_eq!(read("f/ranking.csv"), read("p/ranking.csv"));
    let o = bin()
        .args(design)
        .args(["--family", "bogus"])
        .arg("--out-dir")
        .arg(dir.join("bad"))
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("`--family`"));
    assert!(!dir.join("bad").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// Without `--theta`, a pattern whose symmetry cannot be derived (a substrate from a site file)
/// is screened over the whole 0–360° at the wide-domain step, and the log and the report say
/// so; a `--theta` that covers only part of the domain is named, with the part not screened.
#[test]
fn design_screens_the_whole_domain_without_theta_and_names_a_partial_one() {
    let dir = tmpdir("design-domain");
    let mut csv = String::from("x_um,y_um\n");
    for j in -9i32..=9 {
        for i in -10i32..=10 {
            let x = 3.2 * i as f64 + if j % 2 == 0 { 0.0 } else { 1.6 };
            let y = 2.8 * j as f64;
            if x.abs() <= 30.0 {
                csv += &format!("{x},{y}\n");
            }
        }
    }
    std::fs::write(dir.join("sub.csv"), csv).unwrap();
    let scene = dir.join("free.toml");
    std::fs::write(
        &scene,
        "pattern = 'tri-tri'\n[slider]\nradius_um = 6\n[substrate]\nsize_um = [60, 60]\nsites = 'sub.csv'\n",
    )
    .unwrap();
    let design = |theta: Option<&str>, out: &str| {
        let mut c = bin();
        c.args(["design", "--no-dem", "--load-mn", "0.005,0.01"])
            .args(["--theta-tol-deg", "0", "--direction-tol-deg", "0"])
            .args([
                "--max-top",
                "2",
                "--per-level",
                "1",
                "--alpha-step-deg",
                "45",
            ])
            .args(["--alpha-refine-deg", "none", "--scan-distance-um", "2"])
            .args(["--scan-step-um", "0.5", "--scene"])
            .arg(&scene)
            .arg("--out-dir")
            .arg(dir.join(out));
        if let Some(t) = theta {
            c.args(["--theta", t]);
        }
        let o = c.output().unwrap();
        assert_ok(&o);
        let log = String::from_utf8_lossy(&o.stderr).into_owned();
        let report = std::fs::read_to_string(dir.join(out).join("report.md")).unwrap();
        let mut r = csv::Reader::from_path(dir.join(out).join("screen_free.csv")).unwrap();
        let h = r.headers().unwrap().clone();
        let c = h.iter().position(|x| x == "theta_deg").unwrap();
        let mut thetas: Vec<f64> = r
            .records()
            .map(|x| x.unwrap()[c].parse().unwrap())
            .collect();
        thetas.dedup();
        (log, report, thetas)
    };
    let (log, report, thetas) = design(None, "whole");
    let step = 0.25;
    assert_eq!(thetas.len(), (360.0 / step) as usize, "{log}");
    assert_eq!(thetas[0], 0.0);
    assert_eq!(*thetas.last().unwrap(), 360.0 - step);
    for note in [&log, &report] {
        assert!(
            note.contains("no `--theta-deg` given: the whole domain at 0.25°"),
            "{note}"
        );
        assert!(!note.contains("not screened"), "{note}");
    }
    let (log, report, thetas) = design(Some("0:30:1"), "part");
    assert_eq!(thetas.len(), 31);
    let gap = "the θ list does not cover the domain [0°, 360°): 30°–360° not screened";
    assert!(log.contains(gap), "{log}");
    assert!(report.contains(&format!("**{gap}")), "{report}");
    std::fs::remove_dir_all(&dir).ok();
}

/// With more than three patterns and a tolerance, `design` takes the patterns best nominal
/// design first and does not search the tolerance boxes of candidates that cannot enter the
/// best three: the best three limits are those of each pattern designed alone, and a pattern
/// left out is marked as an upper bound (`robust_exact = false`) that its own robust limit
/// does not exceed.
#[test]
fn design_over_many_patterns_searches_only_those_that_can_win() {
    let dir = tmpdir("patterns-floor");
    let small = ["--slider-radius-um", "15", "--substrate-um", "60x60"];
    let o = bin()
        .args(["patterns", "--family", "rectangular:a=3:4:0.5,b=3:3.5:0.5"])
        .args(small)
        .arg("--out-dir")
        .arg(dir.join("c"))
        .output()
        .unwrap();
    assert_ok(&o);
    let design = [
        "design",
        "--no-dem",
        "--theta",
        "0:30:3",
        "--load-mn",
        "0.02,0.05,0.1,0.2",
    ];
    let o = bin()
        .args(design)
        .arg("--patterns")
        .arg(dir.join("c/index.csv"))
        .args(small)
        .arg("--out-dir")
        .arg(dir.join("m"))
        .output()
        .unwrap();
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(
        log.contains("each at its nominal orientation first"),
        "{log}"
    );
    // each pattern alone: its exact robust limit (rank 1 of its ranking.csv)
    let first = |path: &std::path::Path, col: &str| -> String {
        let mut r = csv::Reader::from_path(path).unwrap();
        let h = r.headers().unwrap().clone();
        let i = h.iter().position(|c| c == col).unwrap();
        let row = r.records().next().unwrap().unwrap();
        row[i].to_string()
    };
    let mut r = csv::Reader::from_path(dir.join("m/patterns.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    let rows: Vec<(String, f64, bool)> = r
        .records()
        .map(|x| {
            let x = x.unwrap();
            (
                x[col("pattern")].to_string(),
                x[col("superlubric_to_mN")].parse().unwrap(),
                x[col("robust_exact")].parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(rows.len(), 6);
    let mut alone = Vec::new();
    for (name, _, _) in &rows {
        let out = dir.join(format!("s_{name}"));
        let o = bin()
            .args(design)
            .arg("--scene")
            .arg(dir.join(format!("c/{name}.toml")))
            .args(small)
            .arg("--out-dir")
            .arg(&out)
            .output()
            .unwrap();
        assert_ok(&o);
        assert_eq!(first(&out.join("ranking.csv"), "robust_exact"), "true");
        alone.push(
            first(&out.join("ranking.csv"), "superlubric_to_mN")
                .parse::<f64>()
                .unwrap(),
        );
    }
    // the best three: exact, and the three best limits of the patterns designed alone
    let mut best: Vec<f64> = alone.clone();
    best.sort_by(|a, b| b.total_cmp(a));
    for (k, (name, w, exact)) in rows.iter().take(3).enumerate() {
        assert!(exact, "rank {} ({name}) is not exact: {rows:?}", k + 1);
        assert_eq!(*w, best[k], "rank {}: {rows:?} vs alone {alone:?}", k + 1);
    }
    let third = rows[2].1;
    let mut left_out = 0;
    for ((name, w, exact), a) in rows.iter().zip(&alone) {
        if *exact {
            assert_eq!(w, a, "{name}: {rows:?} vs alone {alone:?}");
        } else {
            // an upper bound at most the third best, and above its own robust limit
            assert!(*w <= third && a <= w, "{name}: {rows:?} vs alone {alone:?}");
            left_out += 1;
        }
    }
    assert!(left_out > 0, "no pattern was left out: {rows:?}");
    let report = std::fs::read_to_string(dir.join("m/report.md")).unwrap();
    assert!(report.contains("was not searched"), "{report}");
    std::fs::remove_dir_all(&dir).ok();
}
