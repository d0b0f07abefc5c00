//! Command-line details (issue 7, items 9, 11 and 13): negative values reach the field checks,
//! a zero checkpoint interval is refused, tiny values print in full, progress shows in logs
//! (with the DEM phase), the help texts are right.

mod common;
use common::{assert_ok, bin, fails_naming};

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

/// Negative numbers are values, so the message names the field (not clap's "unexpected
/// argument"); a zero step interval is refused naming its flag.
#[test]
fn negative_values_and_zero_intervals_name_the_flag() {
    fails_naming(&["slide", "--mu", "-1"], "--mu");
    fails_naming(&["screen", "--seed", "-1"], "--seed");
    fails_naming(
        &["equilibrate", "--start", "gap", "--gap-nm", "-5"],
        "--gap-nm",
    );
    fails_naming(&["slide", "--speed-m-s", "-1"], "--speed-m-s");
    fails_naming(&["landscape", "--load-mn", "-1"], "--load-mn");
    fails_naming(&["corrugation", "--distance-um", "-3"], "--distance-um");
    fails_naming(&["equilibrate", "--sample-us", "-0.1"], "--sample-us");
    fails_naming(
        &[
            "slide",
            "--checkpoint",
            "/tmp/superlube-x.ckpt",
            "--checkpoint-every",
            "0",
        ],
        "--checkpoint-every",
    );
    fails_naming(&["equilibrate", "--xyz-every", "0"], "--xyz-every");
    for args in [
        ["slide", "--mu", "-1"],
        ["screen", "--seed", "-1"],
        ["equilibrate", "--gap-nm", "-5"],
    ] {
        let out = bin().args(args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("unexpected argument"), "{args:?}: {err}");
    }
}

/// A tiny load prints in full (shortest round trip), not as `0.0`.
#[test]
fn tiny_values_print_in_full() {
    let out = bin()
        .args(["screen", "--pattern", "tri-tri", "--slider-radius-um", "9"])
        .args([
            "--substrate-um",
            "60x40",
            "--theta",
            "0",
            "--load-mn",
            "1e-20,3.5e-13",
        ])
        .output()
        .unwrap();
    assert_ok(&out);
    let text = String::from_utf8(out.stdout).unwrap();
    let loads: Vec<&str> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(2).unwrap())
        .collect();
    assert_eq!(loads, ["1e-20", "3.5e-13"]);
}

/// With stderr not a terminal (a log file, a batch job), progress appears as plain lines every
/// few percent, with the DEM phase, the simulated time, the elapsed time and the ETA.
#[test]
fn progress_lines_in_logs_show_the_phase() {
    let out = bin()
        .arg("slide")
        .args(TINY)
        .args(["--rigid-z", "--equilibrate-us", "0.2", "--relax-us", "0.2"])
        .args([
            "--slide-us",
            "0.6",
            "--sample-us",
            "0.05",
            "--speed-m-s",
            "1",
        ])
        .args(["--out", "/dev/null", "--json", "/dev/null"])
        .output()
        .unwrap();
    assert_ok(&out);
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("slide: ") && l.contains("% ("))
        .collect();
    assert!(lines.len() >= 10, "{err}");
    for phase in ["equilibrate, t = ", "relax, t = ", "slide, t = "] {
        assert!(lines.iter().any(|l| l.contains(phase)), "no {phase}: {err}");
    }
    assert!(lines.iter().any(|l| l.contains("ETA")), "{err}");
    assert!(lines
        .iter()
        .all(|l| l.contains("elapsed") && l.contains("µs")));
    assert!(lines.last().unwrap().contains("100%"), "{err}");
    // The quasi-static sweeps report the same way.
    let out = bin()
        .args(["screen", "--theta", "0:10:0.5"])
        .args(TINY)
        .output()
        .unwrap();
    assert_ok(&out);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.lines().any(|l| l.starts_with("screen: 100% (21/21 θ)")),
        "{err}"
    );
}

/// `--help` names the README section that exists ("Scenes") and every option has a help text.
#[test]
fn help_texts() {
    for cmd in [
        "screen",
        "landscape",
        "corrugation",
        "figures",
        "equilibrate",
        "slide",
    ] {
        let out = bin().args([cmd, "--help"]).output().unwrap();
        assert_ok(&out);
        let h = String::from_utf8(out.stdout).unwrap();
        assert!(!h.contains("\"Scene files\""), "{cmd}: {h}");
        if cmd != "figures" {
            assert!(h.contains("\"Scenes\""), "{cmd}");
        }
        // Every option line is followed by a description.
        let lines: Vec<&str> = h.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            if l.trim_start().starts_with("--") && !l.contains("--help") {
                let described = l
                    .trim_start()
                    .split_once("  ")
                    .is_some_and(|(_, s)| !s.trim().is_empty())
                    || lines
                        .get(i + 1)
                        .is_some_and(|n| n.starts_with("          "));
                assert!(described, "{cmd}: `{l}` has no description");
            }
        }
    }
}

/// Renamed flags (one name per concept): the old names still work for a release and say so;
/// the new names give the same output without the note.
#[test]
fn old_flag_names_still_work_with_a_note() {
    let old = bin()
        .args(["screen", "--theta", "0", "--model", "rigid-z"])
        .args(TINY)
        .output()
        .unwrap();
    assert_ok(&old);
    let new = bin()
        .args(["screen", "--theta-deg", "0", "--solver", "rigid-z"])
        .args(TINY)
        .output()
        .unwrap();
    assert_ok(&new);
    assert_eq!(old.stdout, new.stdout);
    let note = String::from_utf8_lossy(&old.stderr);
    assert!(
        note.contains("`superlube screen --model` is now `--solver`"),
        "{note}"
    );
    assert!(!String::from_utf8_lossy(&new.stderr).contains("note:"));
    let dir = std::env::temp_dir().join(format!("superlube-renamed-{}", std::process::id()));
    let o = bin()
        .args(["patterns", "--family", "presets:s=3"])
        .args([
            "--slider-radius-um",
            "9",
            "--substrate-um",
            "60x40",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_ok(&o);
    assert!(dir.join("index.csv").exists());
    assert!(String::from_utf8_lossy(&o.stderr).contains("is now `--out-dir`"));
    std::fs::remove_dir_all(&dir).ok();
    // slurm's CPUs per task: `--threads` is now `--cpus-per-task` (Slurm's own name)
    let job = std::env::temp_dir().join(format!("superlube-renamed-slurm-{}", std::process::id()));
    let o = bin()
        .args(["slurm", "screen", "--theta", "0:2:1"])
        .args(TINY)
        .args(["--shards", "2", "--threads", "3", "--out-dir"])
        .arg(&job)
        .output()
        .unwrap();
    assert_ok(&o);
    assert!(
        String::from_utf8_lossy(&o.stderr)
            .contains("`superlube slurm --threads` is now `--cpus-per-task`"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let array = std::fs::read_to_string(job.join("array.sbatch")).unwrap();
    assert!(array.contains("--cpus-per-task=3"), "{array}");
    std::fs::remove_dir_all(&job).ok();
}
