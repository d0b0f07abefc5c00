//! `superlube friction` (issue 8, point 1): the leading columns and units, one row per
//! (θ, α, W) in the order θ, α, W for lists and ranges, a row of a range equal to a run at that
//! single value, shards merging byte for byte into the unsharded output, a resumed run equal
//! to an uninterrupted one, and bad input refused naming the flag. Small scenes (a 15 µm slider).

mod common;
use common::{assert_ok, bin, fails_naming, run_small, tmpdir, SMALL_SCENE};
use std::path::Path;

fn friction(extra: &[&str], out: &Path) -> std::process::Output {
    run_small("friction", &[extra], out)
}

/// The cell of row `i` (0 = first data row) in column `name` of the CSV at `path`.
fn cells(path: &Path) -> impl Fn(usize, &str) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let header: Vec<String> = text
        .lines()
        .next()
        .unwrap()
        .split(',')
        .map(String::from)
        .collect();
    let r = rows(path);
    move |i: usize, name: &str| {
        let c = header.iter().position(|c| c == name).unwrap();
        r[i][c].clone()
    }
}

fn rows(path: &Path) -> Vec<Vec<String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    r.records()
        .map(|x| x.unwrap().iter().map(String::from).collect())
        .collect()
}

#[test]
fn columns_order_and_ranges() {
    let d = tmpdir("friction-cols");
    let out = d.join("f.csv");
    let o = friction(
        &[
            "--theta",
            "0:10:5",
            "--alpha",
            "0,90",
            "--load-mn",
            "0.02:0.06:0.02",
        ],
        &out,
    );
    assert_ok(&o);
    let text = std::fs::read_to_string(&out).unwrap();
    let header = text.lines().next().unwrap();
    assert!(
        header.starts_with("pattern,theta_deg,alpha_deg,load_mN,mu_est,p_max_GPa,failed_fraction,"),
        "{header}"
    );
    for col in [
        "mu_coating",
        "mu_corrugation",
        "mu_quasi_static",
        "mu_est_spread",
        "eta",
        "barrier_pJ",
        "max_lateral_force_mN",
        "contacts_mean",
        "line_deg",
        "direction_deg",
        "path_length_um",
        "path_step_um",
        "transverse_offset_um",
        "tilt_pair_ratio",
        "mount_resonance",
        "error",
    ] {
        assert!(
            header.split(',').any(|c| c == col),
            "{col} missing: {header}"
        );
    }
    let col = |name: &str| header.split(',').position(|c| c == name).unwrap();
    let (i_mu_est, i_mu_qs) = (col("mu_est"), col("mu_quasi_static"));
    let (i_line, i_alpha, i_direction) = (col("line_deg"), col("alpha_deg"), col("direction_deg"));
    let r = rows(&out);
    assert_eq!(r.len(), 3 * 2 * 3);
    // θ outer, α, then W
    let key: Vec<(String, String, String)> = r
        .iter()
        .map(|x| (x[1].clone(), x[2].clone(), x[3].clone()))
        .collect();
    assert_eq!(key[0], ("0.0".into(), "0.0".into(), "0.02".into()));
    assert_eq!(key[2], ("0.0".into(), "0.0".into(), "0.06".into()));
    assert_eq!(key[3], ("0.0".into(), "90.0".into(), "0.02".into()));
    assert_eq!(key[6], ("5.0".into(), "0.0".into(), "0.02".into()));
    assert_eq!(key[17], ("10.0".into(), "90.0".into(), "0.06".into()));
    for x in &r {
        let mu: f64 = x[i_mu_est].parse().unwrap();
        assert!(mu.is_finite() && mu > 0.0, "{x:?}");
        // the quasi-static estimate is at least the coating's μ1
        let mu_qs: f64 = x[i_mu_qs].parse().unwrap();
        assert!(mu_qs >= 0.01 - 1e-12, "{x:?}");
        assert!(x.last().unwrap().is_empty(), "{x:?}");
        // direction = line + α
        let (line, alpha, dir): (f64, f64, f64) = (
            x[i_line].parse().unwrap(),
            x[i_alpha].parse().unwrap(),
            x[i_direction].parse().unwrap(),
        );
        assert!((line + alpha - dir).abs() < 1e-6, "{x:?}");
    }
    // the 5° / 90° / 0.04 mN row of the range equals a single-value run, byte for byte
    let one = d.join("one.csv");
    assert_ok(&friction(
        &["--theta", "5", "--alpha", "90", "--load-mn", "0.04"],
        &one,
    ));
    let single = std::fs::read_to_string(&one).unwrap();
    let line = text.lines().nth(1 + 3 + 3 + 3 + 1).unwrap();
    assert_eq!(single.lines().nth(1).unwrap(), line);
    // sidecar
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("f.csv.meta.json")).unwrap()).unwrap();
    assert_eq!(meta["workflow"], "friction");
    assert_eq!(meta["rows"], 18);
    assert_eq!(meta["params"]["alpha_deg"], serde_json::json!([0.0, 90.0]));
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn shards_merge_byte_identically_and_resume_equals_whole() {
    let d = tmpdir("friction-shards");
    let args = [
        "--theta",
        "0,3,6",
        "--alpha",
        "0,45,90",
        "--load-mn",
        "0.02,0.05",
    ];
    let whole = d.join("whole.csv");
    assert_ok(&friction(&args, &whole));
    let expect = std::fs::read(&whole).unwrap();
    let mut files = Vec::new();
    for i in [2usize, 0, 1] {
        let f = d.join(format!("s{i}.csv"));
        let mut a: Vec<&str> = args.to_vec();
        let sh = format!("{i}/3");
        a.extend(["--shard", &sh]);
        assert_ok(&friction(&a, &f));
        files.push(f);
    }
    let merged = d.join("merged.csv");
    let o = bin()
        .arg("merge")
        .args(&files)
        .arg("--out")
        .arg(&merged)
        .output()
        .unwrap();
    assert_ok(&o);
    assert_eq!(std::fs::read(&merged).unwrap(), expect);
    // killed after 5 rows (mid-item: the item's second load is dropped), then resumed
    let resumed = d.join("resumed.csv");
    let o = bin()
        .arg("friction")
        .args(SMALL_SCENE)
        .args(args)
        .arg("--out")
        .arg(&resumed)
        .env("SUPERLUBE_TEST_KILL_AFTER_ROWS", "5")
        .output()
        .unwrap();
    assert!(!o.status.success());
    let mut a: Vec<&str> = args.to_vec();
    a.push("--resume");
    let o = friction(&a, &resumed);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(log.contains("resum"), "{log}");
    assert_eq!(std::fs::read(&resumed).unwrap(), expect);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn bad_input_names_the_flag() {
    let d = tmpdir("friction-bad");
    let out = d.join("x.csv");
    let out = out.to_str().unwrap();
    let base = |extra: &[&'static str]| -> Vec<String> {
        let mut v: Vec<String> = vec!["friction".into()];
        v.extend(SMALL_SCENE.iter().map(|s| s.to_string()));
        v.extend(extra.iter().map(|s| s.to_string()));
        v.extend(["--out".to_string(), out.to_string()]);
        v
    };
    let check = |extra: &[&'static str], flag: &str| {
        let args = base(extra);
        let a: Vec<&str> = args.iter().map(String::as_str).collect();
        fails_naming(&a, flag);
    };
    check(&["--alpha", "200"], "--alpha");
    check(&["--load-mn", "0"], "--load-mn");
    check(&["--theta", "a"], "--theta");
    check(&["--step-um", "0"], "--step-um");
    check(&["--transient-um", "20"], "--transient-um");
    check(&["--alpha", "7", "--length-um", "40"], "friction.length_um");
    check(&["--transverse-um", "-1"], "--transverse-um");
    check(&["--transverse-um", "20"], "friction.transverse_um");
    check(&["--shard", "3/3"], "--shard");
    assert!(!Path::new(out).exists());
    std::fs::remove_dir_all(&d).ok();
}

/// The study's tri-tri scene at 30° (its full 100 µm slider): on the study's spring mount the
/// tilt mode is at ω_t/ω_p = 0.89 of the stuck pairs' lateral mode, so the 2.45 mN row, whose
/// coating fails, is flagged `mount_resonance` (its μ_est an upper bound of the DEM's, measured
/// 2.8× there) and the intact 0.35 mN row is not; with K1 = 10⁷ N/m (ratio 2.8) nothing is, and
/// nothing is on a substrate rough enough to detune the resonance (σ_h = 10 nm).
#[test]
fn mount_resonance_flags_failed_rows_on_the_study_mount() {
    let d = tmpdir("friction_resonance");
    let run = |extra: &[&str], out: &Path| {
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
            .args(["--load-mn", "0.35,2.45"])
            .args(extra)
            .arg("--out")
            .arg(out)
            .output()
            .unwrap();
        assert_ok(&o);
        (o, cells(out))
    };
    let study = d.join("study.csv");
    let (o, get) = run(&[], &study);
    let ratio: f64 = get(0, "tilt_pair_ratio").parse().unwrap();
    assert!((ratio - 0.89).abs() < 0.01, "{ratio}");
    assert_eq!(get(0, "failed_fraction").parse::<f64>().unwrap(), 0.0);
    assert_eq!(get(0, "mount_resonance"), "false");
    assert!(get(1, "failed_fraction").parse::<f64>().unwrap() > 0.0);
    assert_eq!(get(1, "mount_resonance"), "true");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("note: the springs mount's tilt mode is at 0.89"),
        "{err}"
    );

    assert!(err.contains("it applies to 1 of 2 rows"), "{err}");
    // quiet when no row is flagged: the intact 0.35 mN row alone on the same mount
    let o = bin()
        .args(["friction", "--pattern", "tri-tri", "--theta-deg", "30"])
        .args(["--alpha-deg", "0", "--load-mn", "0.35", "--out"])
        .arg(d.join("intact.csv"))
        .output()
        .unwrap();
    assert_ok(&o);
    assert_eq!(cells(&d.join("intact.csv"))(0, "mount_resonance"), "false");
    assert!(!String::from_utf8_lossy(&o.stderr).contains("tilt mode"));

    let (o, get) = run(&["--tilt-k1-n-m", "1e7"], &d.join("stiff.csv"));
    let stiff: f64 = get(1, "tilt_pair_ratio").parse().unwrap();
    assert!((stiff - 0.89 * 10f64.sqrt()).abs() < 0.03, "{stiff}");
    assert_eq!(get(1, "mount_resonance"), "false");
    assert!(!String::from_utf8_lossy(&o.stderr).contains("tilt mode"));

    // A rough substrate (σ_h = 10 nm ≥ 5 nm) detunes the resonance: the coating fails at
    // 2.45 mN, the ratio is the study's, and the row is not flagged.
    let (o, get) = run(
        &["--sigma-h-um", "0.01", "--seed", "1"],
        &d.join("rough.csv"),
    );
    assert!(get(1, "failed_fraction").parse::<f64>().unwrap() > 0.0);
    let rough: f64 = get(1, "tilt_pair_ratio").parse().unwrap();
    assert_eq!(rough, ratio);
    assert_eq!(get(1, "mount_resonance"), "false");
    assert!(!String::from_utf8_lossy(&o.stderr).contains("tilt mode"));
}

/// The study's square-tri scene at θ ≈ 0: the placement sits on a crest between grooves along
/// the substrate rows. Pulled along the rows' normal off the scene's mirror line (θ = 0.1°,
/// α = 90.5°) the slider drifts off the crest (the DEM: 0.85 µm sideways, 26 failed contacts,
/// locked in at 2.1 mN), so the estimate's path runs in the groove, where the coating fails at
/// 0.7 and 2.1 mN and holds at 0.35 mN, as in the DEM. On the mirror line (θ = 0, α = 90°)
/// there is no transverse force and the path stays on the crest, as the DEM's slider does; with
/// `--transverse-um 0` the path runs through the placement (the coating intact at 2.1 mN).
#[test]
fn a_slider_released_on_a_crest_drifts_into_the_groove() {
    let d = tmpdir("friction_transverse");
    let read = |out: &Path| {
        let get = cells(out);
        move |i: usize, name: &str| -> f64 { get(i, name).parse().unwrap() }
    };
    let study = |extra: &[&str], out: &Path| {
        bin()
            .args([
                "friction",
                "--pattern",
                "square-tri",
                "--load-mn",
                "0.35,0.7,2.1",
            ])
            .args(extra)
            .arg("--out")
            .arg(out)
            .output()
            .unwrap()
    };
    // the DEM (study protocol): into the groove at every one of these loads, the coating
    // intact at 0.35 mN (max P_max 3.6 GPa) and failed at 0.7 (4.4 GPa) and 2.1 mN
    let off_mirror = d.join("off_mirror.csv");
    assert_ok(&study(&["--theta", "0.1", "--alpha", "90.5"], &off_mirror));
    let get = read(&off_mirror);
    for i in 0..3 {
        let y = get(i, "transverse_offset_um");
        assert!(y.abs() > 0.5, "load {i}: {y}");
    }
    assert_eq!(get(0, "failed_fraction"), 0.0);
    assert!(get(0, "p_max_GPa") < 4.0 && get(0, "mu_est") < 0.02);
    // across a rise of U(y) at the placement (0.14 pJ): the rule before stopped there
    assert!(get(1, "p_max_GPa") > 4.0, "{}", get(1, "p_max_GPa"));
    assert!(
        get(2, "failed_fraction") > 0.1,
        "{}",
        get(2, "failed_fraction")
    );
    assert!(get(2, "p_max_GPa") > 4.0 && get(2, "mu_est") > 0.05);

    let straight = d.join("straight.csv");
    assert_ok(&study(
        &["--theta", "0.1", "--alpha", "90.5", "--transverse-um", "0"],
        &straight,
    ));
    let get = read(&straight);
    for i in 0..3 {
        assert_eq!(get(i, "transverse_offset_um"), 0.0);
    }
    assert!(get(2, "p_max_GPa") < 3.5 && get(2, "failed_fraction") == 0.0);

    let mirror = d.join("mirror.csv");
    assert_ok(&study(&["--theta", "0", "--alpha", "90"], &mirror));
    let get = read(&mirror);
    for i in 0..3 {
        assert_eq!(get(i, "transverse_offset_um"), 0.0);
        assert!(get(i, "mu_est") < 0.02 && get(i, "failed_fraction") == 0.0);
    }
    std::fs::remove_dir_all(&d).ok();
}
