//! Helpers of the LAMMPS tests (`tests/lammps_*.rs`): finding `lmp`, running an exported deck,
//! reading its log, time series and data file, exporting the small scene.

pub use super::bin;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("superlube-lammps-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

pub fn assert_ok(what: &str, out: &Output) {
    assert!(
        out.status.success(),
        "{what} failed ({}):\n{}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The LAMMPS binary, or `None` (after saying so) when it is absent and not required.
pub fn lmp() -> Option<String> {
    let exe = std::env::var("SUPERLUBE_LMP").unwrap_or_else(|_| "lmp".into());
    let found = Command::new(&exe)
        .arg("-h")
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    if found {
        return Some(exe);
    }
    if std::env::var("SUPERLUBE_REQUIRE_LAMMPS").is_ok_and(|v| v == "1") {
        panic!(
            "`{exe}` (LAMMPS) not found but SUPERLUBE_REQUIRE_LAMMPS=1: install Debian's `lammps`"
        );
    }
    eprintln!("SKIPPED: `{exe}` (LAMMPS) not found; apt-get install lammps to run this check");
    None
}

/// Runs the deck in `dir` with extra `-var` pairs; returns the log text.
pub fn run_deck(lmp: &str, dir: &Path, vars: &[(&str, &str)]) -> String {
    let mut c = Command::new(lmp);
    c.current_dir(dir).args([
        "-in",
        "in.superlube.lmp",
        "-log",
        "log.lammps",
        "-screen",
        "none",
    ]);
    for (k, v) in vars {
        c.args(["-var", k, v]);
    }
    let out = c.output().expect("run lmp");
    let log = std::fs::read_to_string(dir.join("log.lammps")).unwrap_or_default();
    assert!(
        out.status.success(),
        "lmp failed in {}:\n{}",
        dir.display(),
        log
    );
    log
}

/// `key=value` fields of the log's `RESULT phase=<phase>` line.
pub fn result(log: &str, phase: &str) -> std::collections::HashMap<String, f64> {
    let line = log
        .lines()
        .find(|l| l.starts_with(&format!("RESULT phase={phase} ")))
        .unwrap_or_else(|| panic!("no RESULT phase={phase} line in the log"));
    line.split_whitespace()
        .filter_map(|kv| kv.split_once('='))
        .filter_map(|(k, v)| v.parse().ok().map(|v| (k.to_string(), v)))
        .collect()
}

/// Rows of a CSV file as column-name → value maps.
pub fn csv(path: &Path) -> Vec<std::collections::HashMap<String, f64>> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let head: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|s| s.trim_start_matches("# ").to_string())
        .collect();
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            head.iter()
                .cloned()
                .zip(l.split(',').map(|v| v.parse().unwrap_or(f64::NAN)))
                .collect()
        })
        .collect()
}

/// Starts `superlube slide ARGS` (into `rust.csv`, `rust.json` of `dir`) and the exported deck
/// in LAMMPS side by side; returns the LAMMPS log and the wall time of the LAMMPS run (s), once
/// both have finished.
pub fn run_side_by_side(lmp: &str, dir: &Path, args: &[&str]) -> (String, f64) {
    let t0 = std::time::Instant::now();
    let rust = bin()
        .arg("slide")
        .args(args)
        .arg("--out")
        .arg(dir.join("rust.csv"))
        .arg("--json")
        .arg(dir.join("rust.json"))
        .spawn()
        .unwrap();
    let log = run_deck(lmp, dir, &[]);
    let lammps_s = t0.elapsed().as_secs_f64();
    assert_ok("superlube slide", &rust.wait_with_output().unwrap());
    (log, lammps_s)
}

/// Whether `lammps-check`'s frame `f` (at `t_us`) has a row of the deck's time series `lrows`;
/// where it has, its contacts are equal and its P_max agrees to 10⁻⁹ (asserted).
pub fn frame_matches(
    f: &std::collections::HashMap<String, f64>,
    t_us: f64,
    lrows: &[std::collections::HashMap<String, f64>],
) -> bool {
    let Some(r) = lrows.iter().find(|r| (r["t_us"] - t_us).abs() < 1e-6) else {
        return false;
    };
    assert_eq!(
        f["contacts"], r["contacts"],
        "contacts at step {}",
        f["step"]
    );
    let (a, b) = (f["p_max_GPa"], r["p_max_GPa"]);
    assert!(
        (a - b).abs() <= 1e-9 * b.max(1.0),
        "P_max at step {}: {a} vs {b}",
        f["step"]
    );
    true
}

/// The deck's own window mean of the spring force (`RESULT friction_mN=` line of the log, mN).
pub fn deck_friction(log: &str) -> f64 {
    log.lines()
        .find_map(|l| l.strip_prefix("RESULT friction_mN="))
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .expect("RESULT friction_mN line")
}

/// While the spring loads up (support travel 0.1–0.5 µm, before the first slip) the Rust
/// (`rows`) and LAMMPS (`lrows`) trajectories must coincide: the spring force at the same steps
/// within 0.5 %, on at least `min` samples.
pub fn assert_ramp_agrees(
    rows: &[std::collections::HashMap<String, f64>],
    lrows: &[std::collections::HashMap<String, f64>],
    min: usize,
) {
    let mut ramp = 0;
    for r in rows
        .iter()
        .filter(|r| r["support_x_um"] > 0.1 && r["support_x_um"] < 0.5)
    {
        let l = lrows
            .iter()
            .find(|l| (l["t_us"] - r["t_us"]).abs() < 1e-6)
            .expect("same sample");
        let (a, b) = (l["spring_force_mN"], r["spring_force_mN"]);
        assert!(
            (a - b).abs() < 0.005 * b.abs(),
            "t = {} µs: spring force LAMMPS {a} vs Rust {b}",
            r["t_us"]
        );
        ramp += 1;
    }
    assert!(ramp >= min, "{ramp} ramp samples");
}

pub fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The small scene of these tests: 81 slider spheres on a 66 × 54 µm substrate.
pub const SMALL: &[&str] = &[
    "--pattern",
    "square-tri",
    "--slider-radius-um",
    "15",
    "--substrate-um",
    "66x54",
];

pub fn export(dir: &Path, args: &[&str]) -> serde_json::Value {
    let out = bin()
        .arg("export-lammps")
        .args(args)
        .arg("--out")
        .arg(dir)
        .output()
        .unwrap();
    assert_ok("export-lammps", &out);
    json(&dir.join("export.json"))
}

/// Reads `scene.data`'s Atoms section: id → (type, x, y, z) in µm.
pub fn data_atoms(path: &Path) -> Vec<(u64, u32, [f64; 3])> {
    let text = std::fs::read_to_string(path).unwrap();
    let atoms = text
        .split("Atoms")
        .nth(1)
        .unwrap()
        .split("Bonds")
        .next()
        .unwrap();
    atoms
        .lines()
        .skip(1)
        .filter(|l| l.split_whitespace().count() == 8)
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            (
                f[0].parse().unwrap(),
                f[1].parse().unwrap(),
                [
                    f[2].parse().unwrap(),
                    f[3].parse().unwrap(),
                    f[4].parse().unwrap(),
                ],
            )
        })
        .collect()
}

/// The small scene with 2 µm slider spheres on the 3 µm substrate (a scene file in `dir`).
pub fn two_size_scene(dir: &Path) -> PathBuf {
    let f = dir.join("two.toml");
    std::fs::write(
        &f,
        "pattern = 'square-tri'\n[substrate]\nsize_um = [66, 54]\n\
         [slider]\nradius_um = 15\nsphere_diameter_um = 2.0\n",
    )
    .unwrap();
    f
}

/// Reads `scene.data`'s Atoms section: (type, diameter µm) of every atom.
pub fn data_diameters(path: &Path) -> Vec<(u32, f64)> {
    let text = std::fs::read_to_string(path).unwrap();
    let atoms = text.split("Atoms").nth(1).unwrap();
    let atoms = atoms.split("Bonds").next().unwrap();
    atoms
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|f| f.len() == 8)
        .map(|f| (f[1].parse().unwrap(), f[5].parse().unwrap()))
        .collect()
}

/// The friction of the LAMMPS run (the mean spring force of its `log`) against the Rust run's
/// (`dir/rust.json`): the slider slides and the two agree within 5 %. `what` and `p_max`
/// (LAMMPS, Rust; GPa) go into the log line.
pub fn assert_friction_agrees(what: &str, dir: &Path, log: &str, (pl, pr): (f64, f64)) {
    let fr = json(&dir.join("rust.json"))["friction_mN"]
        .as_f64()
        .unwrap();
    let fl = deck_friction(log);
    eprintln!("{what}: P_max {pl} / {pr} GPa; friction LAMMPS {fl} / Rust {fr} mN");
    assert!(fr > 0.3 * 0.5 * 0.05, "the slider must slide: {fr} mN");
    assert!(
        (fl - fr).abs() < 0.05 * fr,
        "friction LAMMPS {fl} vs Rust {fr} mN"
    );
}

/// `superlube lammps-check` on the run's dump in `dir` (export `meta`): at least `min` of its
/// frames match the deck's time series `lrows` at a common step.
pub fn assert_check_matches(
    dir: &Path,
    meta: &serde_json::Value,
    lrows: &[std::collections::HashMap<String, f64>],
    min: usize,
) {
    let out = bin()
        .arg("lammps-check")
        .arg(dir.join("contacts.dump"))
        .arg("--out")
        .arg(dir.join("check.csv"))
        .output()
        .unwrap();
    assert_ok("lammps-check", &out);
    let dt = meta["dt_us"].as_f64().unwrap();
    let mut matched = 0;
    for f in &csv(&dir.join("check.csv")) {
        let t = f["step"] * dt;
        if frame_matches(f, t, lrows) {
            matched += 1;
        }
    }
    assert!(matched >= min, "{matched} frames matched the time series");
}
