//! `superlube equilibrate` and `superlube slide` end to end on tiny scenes: files, columns, JSON
//! keys, agreement with the surrogate, resume, bad input.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};

use std::path::PathBuf;

const TINY: [&str; 8] = [
    "--pattern",
    "square-tri",
    "--slider-radius-um",
    "9",
    "--substrate-um",
    "60x40",
    "--load-mn",
    "0.02",
];

fn json(path: &PathBuf) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn equilibrate_writes_series_and_summary_matching_the_surrogate() {
    let d = tmpdir("eq");
    let (csv, js) = (d.join("eq.csv"), d.join("eq.json"));
    let out = bin()
        .arg("equilibrate")
        .args(TINY)
        .args(["--equilibrate-us", "0.3", "--start", "gap", "--gap-nm", "1"])
        .arg("--out")
        .arg(&csv)
        .arg("--json")
        .arg(&js)
        .output()
        .unwrap();
    assert_ok(&out);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("stable step estimate"), "{err}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(
        text.lines().next().unwrap(),
        "t_us,support_x_um,spring_force_mN,z_um,contacts,p_max_GPa,failed_contacts,p_max_peak_GPa"
    );
    let j = json(&js);
    for k in [
        "contacts",
        "p_max_GPa",
        "z_um",
        "steps",
        "wall_s",
        "surrogate_contacts",
        "surrogate_p_max_GPa",
        "surrogate_z_um",
        "contacts_diff",
        "p_max_rel_diff",
        "z_diff_nm",
        "dt_us",
        "dt_crit_us",
    ] {
        assert!(j.get(k).is_some(), "missing {k}");
    }
    assert!(j["steps"].as_u64().unwrap() > 1000);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn slide_summary_and_resume() {
    let d = tmpdir("slide");
    let args = |csv: &PathBuf, js: &PathBuf| {
        let mut c = bin();
        c.arg("slide")
            .args(TINY)
            .args([
                "--equilibrate-us",
                "0.1",
                "--relax-us",
                "0.1",
                "--slide-us",
                "0.3",
                "--speed-m-s",
                "1",
                "--rigid-z",
                "--prune",
            ])
            .arg("--out")
            .arg(csv)
            .arg("--json")
            .arg(js);
        c
    };
    let (csv, js) = (d.join("a.csv"), d.join("a.json"));
    let out = args(&csv, &js).output().unwrap();
    assert_ok(&out);
    let j = json(&js);
    for k in [
        "friction_mN",
        "mu",
        "mean_contacts",
        "max_p_max_GPa",
        "locked_in",
        "steps",
        "wall_s",
        "alpha_deg",
        "line_deg",
        "direction_deg",
    ] {
        assert!(j.get(k).is_some(), "missing {k}");
    }
    // square-tri at θ = 0: the contact line is the substrate row (x), so α = 0 pulls along x.
    assert!(j["line_deg"].as_f64().unwrap().abs() < 1e-9);
    assert!(j["direction_deg"].as_f64().unwrap().abs() < 1e-9);
    // Interrupted run: a checkpoint every 300 steps, then resumed: the same time series.
    let ck = d.join("run.ckpt");
    let (csv2, js2) = (d.join("b.csv"), d.join("b.json"));
    let mut first = args(&d.join("part.csv"), &d.join("part.json"));
    first
        .arg("--checkpoint")
        .arg(&ck)
        .args(["--checkpoint-every", "300"]);
    assert!(first.output().unwrap().status.success());
    assert!(ck.exists());
    let mut resumed = args(&csv2, &js2);
    resumed.arg("--checkpoint").arg(&ck).arg("--resume");
    let out = resumed.output().unwrap();
    assert_ok(&out);
    assert!(String::from_utf8_lossy(&out.stderr).contains("resumed at step"));
    assert_eq!(
        std::fs::read_to_string(&csv).unwrap(),
        std::fs::read_to_string(&csv2).unwrap()
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn xyz_snapshots_are_extended_xyz_frames() {
    let d = tmpdir("xyz");
    let xyz = d.join("snap.xyz");
    let out = bin()
        .arg("equilibrate")
        .args(TINY)
        .args(["--equilibrate-us", "0.05", "--xyz-every", "100"])
        .arg("--xyz")
        .arg(&xyz)
        .arg("--out")
        .arg(d.join("eq.csv"))
        .arg("--json")
        .arg(d.join("eq.json"))
        .output()
        .unwrap();
    assert_ok(&out);
    let steps = json(&d.join("eq.json"))["steps"].as_u64().unwrap();
    let text = std::fs::read_to_string(&xyz).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let n: usize = lines[0].trim().parse().unwrap();
    assert!(
        lines[1].contains("Properties=species:S:1:pos:R:3"),
        "{}",
        lines[1]
    );
    assert!(lines[1].contains("Time="), "{}", lines[1]);
    // every frame: count line, comment line, n particle lines of 6 fields
    assert_eq!(lines.len() % (n + 2), 0);
    assert_eq!((lines.len() / (n + 2)) as u64, steps / 100);
    for l in &lines[2..n + 2] {
        assert_eq!(l.split_whitespace().count(), 6, "{l}");
    }
    std::fs::remove_dir_all(&d).ok();
}

/// α is measured from the contact line, as in `superlube corrugation`: the moiré estimate by
/// default, `--line-deg` when given.
#[test]
fn alpha_is_measured_from_the_contact_line() {
    let d = tmpdir("alpha");
    let direction = |extra: &[&str]| {
        let js = d.join("eq.json");
        let out = bin()
            .arg("equilibrate")
            .args(TINY)
            .args(["--equilibrate-us", "0.01", "--rigid-z", "--alpha", "90"])
            .args(extra)
            .arg("--out")
            .arg(d.join("eq.csv"))
            .arg("--json")
            .arg(&js)
            .output()
            .unwrap();
        assert_ok(&out);
        let j = json(&js);
        assert_eq!(j["alpha_deg"].as_f64().unwrap(), 90.0);
        (
            j["line_deg"].as_f64().unwrap(),
            j["direction_deg"].as_f64().unwrap(),
        )
    };
    let (line, dir) = direction(&["--line-deg", "10"]);
    assert!((line - 10.0).abs() < 1e-9 && (dir - 100.0).abs() < 1e-9);
    // square-tri at θ = 10.2°: the moiré lines run at −46.1° (see the corrugation figure).
    let (line, dir) = direction(&["--theta", "10.2"]);
    assert!((line + 46.1).abs() < 0.1, "line {line}");
    assert!((dir - (line + 90.0)).abs() < 1e-9);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn bad_input_names_the_field() {
    fails_naming(&["equilibrate", "--load-mn", "0"], "--load-mn");
    fails_naming(&["slide", "--alpha", "270"], "--alpha");
    fails_naming(&["slide", "--line-deg", "nan"], "--line-deg");
    fails_naming(&["slide", "--dt-us", "-1"], "--dt-us");
    fails_naming(
        &["equilibrate", "--slider-radius-um", "-3"],
        "slider.radius_um",
    );
    fails_naming(&["slide", "--slide-us", "0"], "--slide-us");
    fails_naming(&["slide", "--speed-m-s", "0"], "--speed-m-s");
    fails_naming(&["slide", "--relax-us", "-1"], "--relax-us");
    // A time step far beyond the stable one is caught and reported with the stable step
    // (the full model: beyond its contact limit, refused at the start; `auto` would pick
    // rigid-z here).
    let mut a = vec!["equilibrate"];
    a.extend(TINY);
    a.extend([
        "--equilibrate-us",
        "0.5",
        "--dt-us",
        "0.01",
        "--start",
        "gap",
        "--model",
        "full",
    ]);
    fails_naming(&a, "stable");
}

/// A commensurate slider resting in the hollows of the substrate (tri-tri, θ = 0, slider sites
/// over the triangle centroids) is held by the interlocking: the slowly loading spring cannot drag
/// it within the window, so the run is reported `locked_in`, the spring force rising at K0·v.
#[test]
fn commensurate_slider_in_the_hollows_locks_in() {
    let d = tmpdir("lockin");
    let js = d.join("lock.json");
    let out = bin()
        .args([
            "slide",
            "--pattern",
            "tri-tri",
            "--theta",
            "0",
            "--slider-radius-um",
            "6",
            "--substrate-um",
            "40x30",
            "--offset-um",
            "1.5,0.8660254",
            "--load-mn",
            "0.05",
            "--rigid-z",
            "--prune",
            "--speed-m-s",
            "0.01",
            "--equilibrate-us",
            "1",
            "--relax-us",
            "1",
            "--slide-us",
            "10",
        ])
        .arg("--out")
        .arg(d.join("lock.csv"))
        .arg("--json")
        .arg(&js)
        .output()
        .unwrap();
    assert_ok(&out);
    let j = json(&js);
    let ratio = j["advance_ratio"].as_f64().unwrap();
    let slope = j["force_slope_ratio"].as_f64().unwrap();
    assert_eq!(j["locked_in"], serde_json::Value::Bool(true), "{j}");
    assert!(ratio.abs() < 0.1, "advance ratio {ratio}");
    assert!((slope - 1.0).abs() < 0.1, "force slope / K0·v = {slope}");
    assert!(String::from_utf8_lossy(&out.stderr).contains("LOCKED IN"));
    std::fs::remove_dir_all(&d).ok();
}

/// A DEM run on a `springs` mount in the measured tilt resonance (ω_t/ω_p in 0.6–1.15; here a
/// tiny slider with K1 = 5000 N/m, r = 0.66) whose coating may fail (P_crit lowered to 1 GPa,
/// below the surrogate's P_max 1.44 GPa) says so on stderr and records the ratio in its JSON;
/// the study's K1 on the tiny slider (r = 9.3), a constant-μ run (no coating switch, no
/// resonance measured) and an intact coating (the study's P_crit) do not warn.
#[test]
fn a_run_on_a_resonant_mount_says_so() {
    let d = tmpdir("resonant_mount");
    let run = |extra: &[&str], name: &str| {
        let js = d.join(format!("{name}.json"));
        let out = bin()
            .arg("equilibrate")
            .args(TINY)
            .args(["--equilibrate-us", "0.01"])
            .args(extra)
            .arg("--out")
            .arg(d.join(format!("{name}.csv")))
            .arg("--json")
            .arg(&js)
            .output()
            .unwrap();
        assert_ok(&out);
        let warned = String::from_utf8_lossy(&out.stderr).contains("tilt mode is at");
        let r = json(&js)["tilt_pair_ratio"].as_f64().unwrap();
        (warned, r)
    };
    let soft = ["--tilt-k1-n-m", "5000", "--p-crit-gpa", "1"];
    let (warned, r) = run(&soft, "soft");
    assert!(warned);
    assert!((0.6..=1.15).contains(&r), "{r}");
    let (warned, r_study) = run(&["--p-crit-gpa", "1"], "study");
    assert!(!warned);
    assert!(
        (r_study / r - (1e6f64 / 5000.0).sqrt()).abs() < 1e-9,
        "{r_study}"
    );
    let (warned, _) = run(&[&soft[..], &["--mu", "0.01"]].concat(), "constant");
    assert!(!warned);
    let (warned, r_intact) = run(&soft[..2], "intact");
    assert!(!warned);
    assert_eq!(r_intact, r);
}

/// Per-site sphere sizes (a slider site file with 4 µm, 2 µm and 3 µm spheres) in the DEM
/// tiers: slide (one run and a batch) runs; equilibrate, from a gap, settles on the screen's
/// contacts and P_max (2 %), its snapshots giving each sphere its own radius; and design's DEM
/// stage confirms with the active set on (each slider sphere integrated, docs/physics.md).
#[test]
fn per_site_sizes_run_in_the_dem_tiers() {
    let d = tmpdir("per_site_sizes");
    std::fs::write(
        d.join("sites.csv"),
        "x_um,y_um,diameter_um\n0,0,4\n9,0,2\n0,9,2\n-9,0,\n",
    )
    .unwrap();
    let scene = d.join("varied.toml");
    std::fs::write(
        &scene,
        "pattern = 'square-tri'\n[substrate]\nsize_um = [60, 60]\n[slider]\nsites = 'sites.csv'\n",
    )
    .unwrap();
    let s = scene.to_str().unwrap();
    let out = bin()
        .args(["screen", "--scene", s, "--theta", "0", "--load-mn", "0.05"])
        .output()
        .unwrap();
    assert_ok(&out);
    let mut r = csv::Reader::from_reader(&out.stdout[..]);
    let h = r.headers().unwrap().clone();
    let row = r.records().next().unwrap().unwrap();
    let col = |k: &str| -> f64 { row[h.iter().position(|x| x == k).unwrap()].parse().unwrap() };
    let (contacts, p_max) = (col("contacts"), col("p_max_GPa"));
    let csv_out = d.join("run.csv");
    let o = csv_out.to_str().unwrap();
    let batch = d.join("batch");
    let b = batch.to_str().unwrap();
    let short = [
        "--equilibrate-us",
        "0.3",
        "--relax-us",
        "0.1",
        "--slide-us",
        "0.3",
    ];
    let slide = [
        &["slide", "--scene", s, "--line-deg", "0", "--out", o][..],
        &["--load-mn", "0.05"],
        &short,
    ]
    .concat();
    let slide_batch = [
        &["slide", "--scene", s, "--line-deg", "0", "--out-dir", b][..],
        &["--load-mn", "0.05,0.1"],
        &short,
    ]
    .concat();
    let equilibrate = ["equilibrate", "--scene", s, "--load-mn", "0.05", "--out", o];
    for args in [&slide[..], &slide_batch] {
        let out = bin().args(args).output().unwrap();
        assert_ok(&out);
    }
    assert!(csv_out.exists() && batch.exists());
    let (js, xyz) = (d.join("eq.json"), d.join("eq.xyz"));
    let out = bin()
        .args(equilibrate)
        .args(["--equilibrate-us", "3", "--xyz-every", "1000"])
        .args(["--start", "gap", "--gap-nm", "1"])
        .arg("--json")
        .arg(&js)
        .arg("--xyz")
        .arg(&xyz)
        .output()
        .unwrap();
    assert_ok(&out);
    let j = json(&js);
    assert_eq!(j["contacts"].as_f64(), Some(contacts), "{j}");
    let p = j["p_max_GPa"].as_f64().unwrap();
    assert!(
        (p / p_max - 1.0).abs() < 0.02,
        "DEM P_max {p} vs screen {p_max} GPa"
    );
    let text = std::fs::read_to_string(&xyz).unwrap();
    let frame: Vec<f64> = text
        .lines()
        .filter(|l| l.starts_with("S "))
        .take(4)
        .map(|l| l.split_whitespace().nth(4).unwrap().parse().unwrap())
        .collect();
    assert_eq!(frame, [2.0, 1.0, 1.0, 1.5]);
    let design = d.join("design");
    let out = bin()
        .args([
            "design",
            "--scene",
            s,
            "--line-deg",
            "0",
            "--theta",
            "0:10:10",
        ])
        .args(["--load-mn", "0.05", "--p-crit-gpa", "20", "--confirm", "1"])
        .args(["--dem-equilibrate-us", "0.3", "--dem-relax-us", "0.1"])
        .args([
            "--dem-slide-us",
            "0.3",
            "--dem-speed-m-s",
            "1",
            "--no-protocol-check",
        ])
        .arg("--out-dir")
        .arg(&design)
        .output()
        .unwrap();
    assert_ok(&out);
    let dem = std::fs::read_to_string(design.join("dem.csv")).unwrap();
    assert!(dem.lines().count() > 1 && dem.contains(",ok,"), "{dem}");
    let run = json(&design.join("dem/varied_theta0_alpha0_W0.05/slide.json"));
    assert_eq!(run["active_set"].as_bool(), Some(true), "{run}");
    std::fs::remove_dir_all(&d).ok();
}

/// Two sphere sizes (2 µm slider spheres on the 3 µm substrate, a 15 µm slider): the DEM, in
/// both models and started from a gap, settles on the screen's equilibrium of the same scene
/// (contacts equal, P_max within 2 %, as the one-size equilibrium tests), and its snapshots
/// give each body its own radius. A wrong contact distance (2 × either radius) would change the
/// contacts; R_eff of either size alone (R/2) P_max by 13–14 %.
#[test]
fn two_sphere_sizes_settle_on_the_screen() {
    let d = tmpdir("two_sizes");
    let scene = d.join("two.toml");
    std::fs::write(
        &scene,
        "pattern = 'square-tri'\n[substrate]\nsize_um = [60, 60]\n\
         [slider]\nradius_um = 15\nsphere_diameter_um = 2.0\n",
    )
    .unwrap();
    let load = ["--theta", "0", "--load-mn", "0.05"];
    let out = bin()
        .arg("screen")
        .args(load)
        .arg("--scene")
        .arg(&scene)
        .output()
        .unwrap();
    assert_ok(&out);
    let mut r = csv::Reader::from_reader(&out.stdout[..]);
    let h = r.headers().unwrap().clone();
    let row = r.records().next().unwrap().unwrap();
    let col = |k: &str| -> f64 { row[h.iter().position(|x| x == k).unwrap()].parse().unwrap() };
    let (contacts, p_max) = (col("contacts"), col("p_max_GPa"));
    assert!(contacts > 0.0);
    for model in ["reduced", "full"] {
        let (js, xyz) = (
            d.join(format!("{model}.json")),
            d.join(format!("{model}.xyz")),
        );
        let out = bin()
            .arg("equilibrate")
            .args(load)
            .args(["--model", model, "--equilibrate-us", "3"])
            .args(["--start", "gap", "--gap-nm", "1", "--xyz-every", "1000"])
            .arg("--scene")
            .arg(&scene)
            .arg("--xyz")
            .arg(&xyz)
            .arg("--out")
            .arg(d.join(format!("{model}.csv")))
            .arg("--json")
            .arg(&js)
            .output()
            .unwrap();
        assert_ok(&out);
        let j = json(&js);
        assert_eq!(j["surrogate_contacts"].as_f64(), Some(contacts), "{model}");
        assert_eq!(j["contacts"].as_f64(), Some(contacts), "{model}: {j}");
        let p = j["p_max_GPa"].as_f64().unwrap();
        assert!(
            (p / p_max - 1.0).abs() < 0.02,
            "{model}: DEM P_max {p} vs screen {p_max} GPa"
        );
        let text = std::fs::read_to_string(&xyz).unwrap();
        let radius = |species: &str| -> Vec<f64> {
            let mut r: Vec<f64> = text
                .lines()
                .filter(|l| l.starts_with(&format!("{species} ")))
                .map(|l| l.split_whitespace().nth(4).unwrap().parse().unwrap())
                .collect();
            r.dedup();
            r
        };
        assert_eq!(radius("S"), [1.0], "{model}");
        assert_eq!(radius("B"), [1.5], "{model}");
    }
    std::fs::remove_dir_all(&d).ok();
}
