//! Streamed sweeps (issue 7, item 8): rows go out in order as they are computed, through
//! `OUT.partial`; runs above the size limit are refused with their estimated cost unless
//! `--force`; range values are the decimals meant.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};
use std::io::{BufRead, BufReader};
use std::process::Stdio;

const TINY: [&str; 6] = [
    "--pattern",
    "tri-tri",
    "--slider-radius-um",
    "9",
    "--substrate-um",
    "60x40",
];

/// Oversized runs are refused before any work, with the estimated time, memory and output size
/// and the way out (`--force`).
#[test]
fn oversized_runs_are_refused_with_their_cost() {
    for args in [
        vec!["landscape", "--grid", "100000"],
        vec!["screen", "--theta", "0:30:0.00001", "--load-mn", "1,2"],
        vec!["corrugation", "--alpha", "0:90:0.01", "--step-um", "0.001"],
        vec!["figures", "--theta-step-deg", "0.00001"],
    ] {
        let t0 = std::time::Instant::now();
        let out = bin().args(&args).output().unwrap();
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        for word in ["--force", "estimated", "memory", "output", "solves"] {
            assert!(err.contains(word), "{args:?}: `{err}` lacks {word}");
        }
        assert!(
            t0.elapsed().as_secs_f64() < 20.0,
            "{args:?} did not refuse at once"
        );
    }
    // Under the limit it runs as before.
    let out = bin()
        .args(["landscape", "--grid", "3"])
        .args(TINY)
        .output()
        .unwrap();
    assert_ok(&out);
    fails_naming(&["landscape", "--grid", "1"], "--grid");
}

/// A row of a range sweep is the row of a run at that single value (the range value is the
/// decimal 0.3, not 0.30000000000000004).
#[test]
fn range_rows_equal_single_value_runs() {
    let run = |theta: &str| {
        let out = bin()
            .arg("screen")
            .args(TINY)
            .args(["--load-mn", "0.02", "--theta", theta])
            .output()
            .unwrap();
        assert_ok(&out);
        String::from_utf8(out.stdout).unwrap()
    };
    let range = run("0:0.6:0.1");
    let single = run("0.3");
    assert_eq!(
        range.lines().nth(4).unwrap(),
        single.lines().nth(1).unwrap()
    );
    assert!(single
        .lines()
        .nth(1)
        .unwrap()
        .starts_with("tri-tri,0.3,0.02,"));
}

/// An interrupted screen leaves the previous output untouched and its rows so far, complete
/// lines in order, in `OUT.partial` with a sidecar saying it is incomplete; a finished one
/// renames it into place.
#[test]
fn interrupted_stream_keeps_a_partial_file() {
    let d = tmpdir("stream-partial");
    let out = d.join("s.csv");
    std::fs::write(&out, "previous result\n").unwrap();
    let partial = d.join("s.csv.partial");
    let mut child = bin()
        .arg("screen")
        .args(TINY)
        .args(["--theta", "0:30:0.0002", "--load-mn", "0.01,0.02"])
        .arg("--out")
        .arg(&out)
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let t0 = std::time::Instant::now();
    loop {
        let n = std::fs::read_to_string(&partial)
            .map(|t| t.lines().count())
            .unwrap_or(0);
        if n > 100 || t0.elapsed().as_secs() > 60 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "previous result\n");
    let text = std::fs::read_to_string(&partial).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines.len() > 100, "{} lines", lines.len());
    assert!(lines[0].starts_with("pattern,theta_deg,load_mN"));
    // Row k is data line k + 1, in the sweep's order (θ outer, load inner).
    for (k, l) in lines[1..lines.len() - 1].iter().enumerate() {
        let f: Vec<&str> = l.split(',').collect();
        let theta = (k / 2) as f64 * 0.0002;
        assert!(
            (f[1].parse::<f64>().unwrap() - theta).abs() < 1e-9,
            "row {k}: {l}"
        );
        assert_eq!(f[2], ["0.01", "0.02"][k % 2]);
    }
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("s.csv.partial.meta.json")).unwrap())
            .unwrap();
    assert_eq!(meta["complete"], false);
    assert!(meta["input_hash"].as_str().unwrap().starts_with("sha256:"));
    std::fs::remove_dir_all(&d).ok();
}

/// `superlube screen | head` ends quietly with exit 0: no panic, no error message.
#[test]
fn broken_pipe_ends_quietly() {
    let mut child = bin()
        .arg("screen")
        .args(TINY)
        .args(["--theta", "0:30:0.001", "--load-mn", "0.01,0.02"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    {
        let mut r = BufReader::new(child.stdout.take().unwrap());
        let mut line = String::new();
        r.read_line(&mut line).unwrap();
        assert!(line.starts_with("pattern,"));
    } // the reader closes the pipe here, like `head -1`
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(!err.contains("error") && !err.contains("panic"), "{err}");
}
