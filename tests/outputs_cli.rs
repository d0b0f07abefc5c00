//! Outputs that are checked before the run and describe themselves (issue 7, items 6 and 10).

mod common;
use common::{assert_ok, bin, tmpdir};
use std::path::Path;

const TINY: [&str; 6] = [
    "--pattern",
    "square-tri",
    "--slider-radius-um",
    "9",
    "--substrate-um",
    "60x40",
];

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// An unwritable output path (its directory cannot take a file, or it is a directory) fails
/// before any work, naming the flag — for every command and every output flag.
#[test]
fn unwritable_outputs_fail_before_the_run() {
    let d = tmpdir("outputs-check");
    let dir = d.to_str().unwrap();
    let nowhere = "/proc/superlube-no-such-dir/x.out";
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["screen", "--theta", "0", "--out", nowhere], "--out"),
        (vec!["screen", "--theta", "0", "--out", dir], "--out"),
        (
            vec![
                "screen",
                "--theta",
                "0",
                "--load-mn",
                "1",
                "--contacts-out",
                nowhere,
            ],
            "--contacts-out",
        ),
        (
            vec!["landscape", "--grid", "3", "--plot", nowhere],
            "--plot",
        ),
        (
            vec!["landscape", "--grid", "3", "--contact-map", dir],
            "--contact-map",
        ),
        (
            vec!["corrugation", "--alpha", "0", "--out", nowhere],
            "--out",
        ),
        (
            vec![
                "figures",
                "--only",
                "contacts",
                "--out-dir",
                "/proc/superlube-x",
            ],
            "--out-dir",
        ),
        (vec!["equilibrate", "--json", nowhere], "--json"),
        (vec!["slide", "--xyz", nowhere], "--xyz"),
        (vec!["slide", "--checkpoint", dir], "--checkpoint"),
    ];
    for (mut args, flag) in cases {
        if !matches!(args[0], "figures") {
            args.extend(TINY);
        }
        let t0 = std::time::Instant::now();
        let out = bin().args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} should fail");
        assert!(err.contains(&format!("`{flag}`")), "{args:?}: {err}");
        assert!(err.contains("before starting"), "{args:?}: {err}");
        // Nothing ran: no DEM set-up line, no progress.
        assert!(
            !err.contains("stable step") && !err.contains('%'),
            "{args:?}: {err}"
        );
        assert!(t0.elapsed().as_secs_f64() < 20.0);
    }
    std::fs::remove_dir_all(&d).ok();
}

/// A write that fails at the end (here: `/dev/full`, which passes the check but has no space)
/// does not stop the other outputs: the JSON summary is still written, and the command reports
/// the failure naming the flag and exits non-zero.
#[test]
fn a_failed_write_at_the_end_keeps_the_others() {
    if !Path::new("/dev/full").exists() {
        eprintln!("no /dev/full: skipped");
        return;
    }
    let d = tmpdir("outputs-full");
    let js = d.join("eq.json");
    let out = bin()
        .arg("equilibrate")
        .args(TINY)
        .args(["--load-mn", "0.02", "--equilibrate-us", "0.02", "--rigid-z"])
        .args(["--out", "/dev/full", "--json"])
        .arg(&js)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("`--out` /dev/full"), "{err}");
    assert!(json(&js)["contacts"].as_u64().is_some());
    assert!(d.join("eq.json.meta.json").exists());
    std::fs::remove_dir_all(&d).ok();
}

/// Every output file gets a sidecar with the resolved scene (σ_h, seed, E, P_crit, the mount…),
/// the parameters, the version, the command line and an input hash; the recorded scene reloads
/// as a `--scene` file to the same output and the same hash; the hash ignores the output path
/// and changes with the inputs.
#[test]
fn sidecars_record_the_inputs_and_reload() {
    let d = tmpdir("outputs-meta");
    let screen = |csv: &Path, extra: &[&str]| {
        let out = bin()
            .arg("screen")
            .args(extra)
            .args(["--theta", "0:2:1", "--load-mn", "0.01,0.02", "--out"])
            .arg(csv)
            .output()
            .unwrap();
        assert_ok(&out);
        (
            std::fs::read_to_string(csv).unwrap(),
            json(&d.join(format!(
                "{}.meta.json",
                csv.file_name().unwrap().to_str().unwrap()
            ))),
        )
    };
    let mut flags = TINY.to_vec();
    flags.extend([
        "--sigma-h-um",
        "0.002",
        "--seed",
        "7",
        "--youngs-gpa",
        "50",
        "--p-crit-gpa",
        "3.5",
        "--tilt",
        "free",
    ]);
    let (csv_a, meta) = screen(&d.join("a.csv"), &flags);
    // CSV columns stay plain.
    assert!(csv_a.starts_with("pattern,theta_deg,load_mN,contacts,"));
    let s = &meta["scene"];
    assert_eq!(s["substrate"]["sigma_h_um"], 0.002);
    assert_eq!(s["substrate"]["seed"], 7);
    assert_eq!(s["material"]["youngs_GPa"], 50.0);
    assert_eq!(s["coating"]["p_crit_GPa"], 3.5);
    assert_eq!(s["coating"]["mu2"], 0.5);
    assert_eq!(s["slider"]["tilt"], "free");
    assert_eq!(s["slider"]["radius_um"], 9.0);
    assert_eq!(meta["params"]["load_mN"], serde_json::json!([0.01, 0.02]));
    assert_eq!(
        meta["params"]["theta_deg"],
        serde_json::json!([0.0, 1.0, 2.0])
    );
    assert_eq!(meta["workflow"], "screen");
    assert_eq!(meta["rows"], 6);
    assert_eq!(meta["complete"], true);
    assert_eq!(meta["version"], env!("CARGO_PKG_VERSION"));
    let cl: Vec<&str> = meta["command_line"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(&cl[..2], &["superlube", "screen"]);
    assert!(cl.contains(&"--sigma-h-um") && cl.contains(&"0.002"));
    let hash = meta["input_hash"].as_str().unwrap();
    assert!(hash.starts_with("sha256:"));
    // Reload: the recorded scene as a scene file gives the same rows and the same hash.
    let toml = d.join("scene.toml");
    std::fs::write(&toml, meta["scene_toml"].as_str().unwrap()).unwrap();
    let (csv_b, meta_b) = screen(&d.join("b.csv"), &["--scene", toml.to_str().unwrap()]);
    assert_eq!(csv_a, csv_b);
    assert_eq!(meta_b["input_hash"], hash);
    // Another input: another hash.
    let mut other = flags.clone();
    other[7] = "0.003";
    let (_, meta_c) = screen(&d.join("c.csv"), &other);
    assert_ne!(meta_c["input_hash"], hash);
    std::fs::remove_dir_all(&d).ok();
}

/// The DEM summaries say which case they are (pattern, θ, W) and their sidecar holds the scene
/// and every protocol parameter; the time series and snapshot files get sidecars too.
#[test]
fn dem_summaries_and_sidecars_record_the_case() {
    let d = tmpdir("outputs-dem");
    let (csv, js, xyz) = (d.join("s.csv"), d.join("s.json"), d.join("s.xyz"));
    let out = bin()
        .arg("slide")
        .args(TINY)
        .args([
            "--theta",
            "10.2",
            "--load-mn",
            "0.02",
            "--alpha",
            "90",
            "--rigid-z",
        ])
        .args([
            "--equilibrate-us",
            "0.02",
            "--relax-us",
            "0.02",
            "--slide-us",
            "0.05",
        ])
        .args(["--xyz-every", "50"])
        .arg("--out")
        .arg(&csv)
        .arg("--json")
        .arg(&js)
        .arg("--xyz")
        .arg(&xyz)
        .output()
        .unwrap();
    assert_ok(&out);
    let j = json(&js);
    assert_eq!(j["pattern"], "square-tri");
    assert_eq!(j["theta_deg"], 10.2);
    assert_eq!(j["load_mN"], 0.02);
    // the model actually run and why (--rigid-z: reduced whatever auto decides)
    assert_eq!(j["model"], "reduced");
    assert_eq!(j["model_requested"], "auto");
    assert!(!j["model_reason"].as_str().unwrap().is_empty());
    assert_eq!(j["rigid_z"], true);
    for f in ["s.csv", "s.json", "s.xyz"] {
        let m = json(&d.join(format!("{f}.meta.json")));
        assert_eq!(m["workflow"], "slide", "{f}");
        assert_eq!(m["scene"]["slider"]["theta_deg"], 10.2);
        assert_eq!(m["params"]["alpha_deg"], 90.0);
        assert_eq!(m["params"]["slide_us"], 0.05);
        assert_eq!(m["params"]["force_rigid_z"], true);
        assert_eq!(m["params"]["model"], "auto");
    }
    std::fs::remove_dir_all(&d).ok();
}
