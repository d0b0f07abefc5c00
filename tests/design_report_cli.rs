//! The top of `design`'s report (issue 34) on a small scene with a tolerance box and the DEM:
//! the answer table's values against `ranking.csv` and `dem.csv` of the same run (values, not
//! wording); the answer's scene file `answer_<p>.toml` (θ set) and its `slide`, `tolerance` and
//! `export-lammps` command lines run from the report's folder and reproduce the design's DEM run
//! and map point; `friction`'s `verdict` at a (θ, α, W) equals the one `design` records for that
//! row in `friction_<p>.csv`, and its sidecar names the band.

mod common;
use common::{assert_ok, bin, tmpdir};
use std::collections::HashMap;
use std::path::Path;

type Row = HashMap<String, String>;

fn rows(path: &Path) -> Vec<Row> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let h = r.headers().unwrap().clone();
    r.records()
        .map(|x| {
            let x = x.unwrap();
            h.iter()
                .zip(x.iter())
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect()
        })
        .collect()
}

fn num(r: &Row, k: &str) -> f64 {
    r[k].parse()
        .unwrap_or_else(|_| panic!("{k} = `{}` is not a number", r[k]))
}

/// The numbers in `s` (`4 of 4 held at 0.09 mN` → 4, 4, 0.09).
fn numbers(s: &str) -> Vec<f64> {
    s.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter_map(|w| w.trim_matches('.').parse().ok())
        .collect()
}

/// The loads (mN) after `what` up to the next `mN` in `cell` (`held at 0.01, 0.09 mN`).
fn loads_after(cell: &str, what: &str) -> Vec<f64> {
    match cell.find(what) {
        Some(k) => {
            let rest = &cell[k + what.len()..];
            numbers(&rest[..rest.find("mN").unwrap()])
        }
        None => vec![],
    }
}

/// The cells of the report's answer table, by header.
fn answer_table(report: &str) -> Vec<HashMap<String, String>> {
    let mut lines = report
        .lines()
        .skip_while(|l| !l.starts_with("| pattern | θ (°) | pull from x"));
    let cells = |l: &str| -> Vec<String> {
        l.trim_matches('|')
            .split(" | ")
            .map(|c| c.trim().to_string())
            .collect()
    };
    let head = cells(lines.next().expect("no answer table"));
    lines
        .skip(1)
        .take_while(|l| l.starts_with('|'))
        .map(|l| head.iter().cloned().zip(cells(l)).collect())
        .collect()
}

/// The words of the report's command line starting with `start`, paths as given.
fn command<'r>(report: &'r str, start: &str) -> Vec<&'r str> {
    report
        .lines()
        .find(|l| l.starts_with(start))
        .unwrap_or_else(|| panic!("no `{start}` line"))
        .split_whitespace()
        .skip(1)
        .collect()
}

/// `words` with the value after `flag` replaced by `value`.
fn set(words: &[&str], flag: &str, value: &str) -> Vec<String> {
    let k = words.iter().position(|w| *w == flag).unwrap();
    let mut v: Vec<String> = words.iter().map(|w| w.to_string()).collect();
    v[k + 1] = value.to_string();
    v
}

#[test]
fn the_answer_table_matches_the_csvs_and_its_commands_run_the_answer() {
    let d = tmpdir("design-report");
    let out = d.join("run");
    let o = bin()
        .args(["design", "--pattern", "square-tri", "--theta", "0:30:1"])
        .args(["--slider-radius-um", "15", "--substrate-um", "60x60"])
        .args(["--load-mn", "0.01,0.03,0.06,0.09"])
        .args(["--theta-tol-deg", "1", "--theta-tol-step-deg", "0.5"])
        .args(["--direction-tol-deg", "0.5"])
        .args(["--confirm", "1", "--confirm-loads-mn", "0.01,0.09"])
        .args(["--dem-equilibrate-us", "0.1", "--dem-relax-us", "0.05"])
        .args([
            "--dem-slide-us",
            "0.3",
            "--no-protocol-check",
            "--jobs",
            "2",
        ])
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_ok(&o);
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    // the report says what made it and defines its angles, and names the DEM protocol and
    // model beside its DEM columns
    let stamp = report.lines().nth(2).unwrap();
    assert!(stamp.starts_with("Made by superlube "), "{report}");
    assert!(
        stamp.contains("UTC with `superlube design --pattern square-tri --theta 0:30:1"),
        "{stamp}"
    );
    for needle in [
        "At **θ = 0** the slider's lattice vector a₁",
        "x runs along the substrate's first side",
        "θ > 0 turns the slider counter-clockwise seen from above",
        "0° moves the slider towards +x, 90° towards +y",
        "The DEM columns are Tier 3 DEM runs of equilibrate 0.1 + relax 0.05 + slide 0.3 µs at 0.1 m/s",
        "DEM model: reduced model",
    ] {
        assert!(report.contains(needle), "{needle}: {report}");
    }
    let table = answer_table(&report);
    assert_eq!(table.len(), 1, "{report}");
    let t = &table[0];
    assert_eq!(t["pattern"], "square-tri");

    // against ranking.csv: the answer is the rank-1 design (--confirm 1)
    let ranking = rows(&out.join("ranking.csv"));
    let best = &ranking[0];
    let (theta, theta_tol) = (numbers(&t["θ (°)"])[0], numbers(&t["θ (°)"])[1]);
    assert_eq!(theta, num(best, "theta_deg"));
    assert_eq!(theta_tol, num(best, "theta_tol_deg"));
    let pull = numbers(&t["pull from x (°)"]);
    assert!(
        (pull[0] - num(best, "direction_deg")).abs() <= 0.005,
        "{t:?}"
    );
    assert_eq!(pull[1], num(best, "direction_tol_deg"));
    let alpha = numbers(&t["pull from contact line α (°)"])[0];
    assert!((alpha - num(best, "alpha_deg")).abs() <= 0.005, "{t:?}");
    let limit = num(best, "superlubric_to_mN");
    assert_eq!(numbers(&t["robust limit (mN)"]), vec![limit]);
    assert_eq!(
        t["robust limit (mN)"].starts_with('≤'),
        best["robust_exact"] == "false"
    );
    assert_eq!(t["verdict"], best["verdict"]);
    // the nominal optimum: the highest nominal limit of the pattern, where above the robust one
    let top_nominal = ranking
        .iter()
        .map(|r| num(r, "superlubric_to_nominal_mN"))
        .fold(0.0, f64::max);
    if top_nominal > limit {
        assert!(
            numbers(&t["nominal optimum"]).contains(&top_nominal),
            "{t:?}"
        );
    } else {
        assert_eq!(t["nominal optimum"], "the same design");
    }

    // against dem.csv: the design's own runs, then its corners per load
    let dem = rows(&out.join("dem.csv"));
    let mine = |corner: bool| -> Vec<&Row> {
        dem.iter()
            .filter(|r| {
                r["rank"] == "1"
                    && r["protocol"] == "design"
                    && (num(r, "theta_offset_deg") != 0.0 || num(r, "direction_offset_deg") != 0.0)
                        == corner
            })
            .collect()
    };
    let held = |r: &Row| r["superlubric_dem"] == "true";
    let centre = mine(false);
    assert!(!centre.is_empty());
    let loads = |v: Vec<&Row>| -> Vec<f64> {
        let mut w: Vec<f64> = v.iter().map(|r| num(r, "load_mN")).collect();
        w.sort_by(f64::total_cmp);
        w
    };
    let cell = &t["DEM at the design"];
    assert_eq!(
        loads_after(cell, "held at "),
        loads(centre.iter().copied().filter(|r| held(r)).collect())
    );
    assert_eq!(
        loads_after(cell, "failed at "),
        loads(centre.iter().copied().filter(|r| !held(r)).collect())
    );
    let corners = mine(true);
    assert!(!corners.is_empty(), "{dem:?}");
    let cell = &t["DEM at the box corners"];
    let parts: Vec<&str> = cell.split("; ").collect();
    let mut corner_loads = loads(corners.clone());
    corner_loads.dedup();
    assert_eq!(parts.len(), corner_loads.len(), "{cell}");
    for (part, w) in parts.iter().zip(&corner_loads) {
        let at: Vec<&Row> = corners
            .iter()
            .copied()
            .filter(|r| num(r, "load_mN") == *w)
            .collect();
        let ok = at.iter().filter(|r| held(r)).count();
        assert_eq!(
            numbers(part),
            vec![ok as f64, at.len() as f64, *w],
            "{cell}"
        );
    }
    // the DEM table's angles carry what the tolerance resolves, not nine decimals
    let dem_sec = &report[report
        .find("| pattern | rank | θ (°) | α (°) | tolerance corner")
        .unwrap()..];
    for line in dem_sec.lines().skip(2).take_while(|l| l.starts_with('|')) {
        let alpha = line.split(" | ").nth(3).unwrap();
        assert!(
            alpha.split('.').nth(1).is_none_or(|f| f.len() <= 2),
            "{line}"
        );
    }

    // the answer's scene file: θ set, and its commands run from the report's folder
    let scene: toml::Value =
        toml::from_str(&std::fs::read_to_string(out.join("answer_square-tri.toml")).unwrap())
            .unwrap();
    assert_eq!(scene["slider"]["theta_deg"].as_float(), Some(theta));
    assert!(out.join("answer_square-tri.toml.meta.json").exists());
    // slide at the answer's limit: the design's own DEM run at that load, reproduced
    let slide = command(&report, "superlube slide --scene answer_square-tri.toml");
    let o = bin().current_dir(&out).args(&slide).output().unwrap();
    assert_ok(&o);
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("answer_square-tri/slide.json")).unwrap(),
    )
    .unwrap();
    let w = numbers(slide[slide.iter().position(|w| *w == "--load-mn").unwrap() + 1])[0];
    let run = centre
        .iter()
        .find(|r| num(r, "load_mN") == w)
        .expect("the design's DEM ran its own limit load");
    let mu = json["mu"]
        .as_f64()
        .unwrap_or_else(|| panic!("no μ in {json}"));
    let mu_dem = num(run, "mu_dem");
    assert!(
        (mu - mu_dem).abs() <= 1e-9 * mu_dem.abs(),
        "{mu} vs {mu_dem}"
    );
    // the tolerance map's nominal point, on a 3 × 3 grid to stay cheap
    let tol = command(
        &report,
        "superlube tolerance --scene answer_square-tri.toml",
    );
    let tol = set(&tol, "--theta-points", "3");
    let refs: Vec<&str> = tol.iter().map(String::as_str).collect();
    let tol = set(&refs, "--direction-points", "3");
    let o = bin().current_dir(&out).args(&tol).output().unwrap();
    assert_ok(&o);
    let nominal = |rs: Vec<Row>| -> Row {
        rs.into_iter()
            .find(|r| num(r, "theta_offset_deg") == 0.0 && num(r, "direction_offset_deg") == 0.0)
            .unwrap()
    };
    let here = nominal(rows(&out.join("answer_square-tri/tolerance/map.csv")));
    let design_map = nominal(rows(&out.join("tolerance_square-tri.csv")));
    for k in [
        "superlubric_to_mN",
        "mu_est_at_limit",
        "p_max_at_limit_GPa",
        "limited_by",
    ] {
        assert_eq!(here[k], design_map[k], "{k}");
    }
    // the LAMMPS export
    let export = command(
        &report,
        "superlube export-lammps --scene answer_square-tri.toml",
    );
    let o = bin().current_dir(&out).args(&export).output().unwrap();
    assert_ok(&o);
    assert!(out
        .join("answer_square-tri/lammps/in.superlube.lmp")
        .exists());

    // `friction`'s verdict at the answer's (θ, α, W) equals the one design recorded
    let needle = format!(" --theta-deg {theta} ");
    let fr: Vec<&str> = report
        .lines()
        .find(|l| l.starts_with("superlube friction ") && l.contains(&needle))
        .expect("the answer's θ has a friction command")
        .split_whitespace()
        .skip(1)
        .collect();
    let o = bin()
        .args(&fr)
        .arg("--out")
        .arg(d.join("f.csv"))
        .output()
        .unwrap();
    assert_ok(&o);
    let design_rows = rows(&out.join("friction_square-tri.csv"));
    let key = |r: &Row| {
        (
            r["theta_deg"].clone(),
            r["alpha_deg"].clone(),
            r["load_mN"].clone(),
        )
    };
    let mut n = 0;
    for r in rows(&d.join("f.csv")) {
        assert!(["superlubric", "borderline", "not"].contains(&r["verdict"].as_str()));
        if let Some(x) = design_rows.iter().find(|x| key(x) == key(&r)) {
            assert_eq!(r["verdict"], x["verdict"], "{:?}", key(&r));
            assert_eq!(r["mu_est"], x["mu_est"]);
            n += 1;
        }
    }
    assert!(n >= 1, "no row of the design reproduced");
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("f.csv.meta.json")).unwrap()).unwrap();
    let band = meta["params"]["verdict"]["band"].as_str().unwrap();
    assert!(
        band.starts_with("borderline = μ_est in [0.0166, 0.0220)"),
        "{band}"
    );
    std::fs::remove_dir_all(&d).ok();
}
