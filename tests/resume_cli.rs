//! `--resume` (issue 10, point 2): an interrupted `screen`, `landscape` or `corrugation` run
//! again with `--resume` and the same `--out` keeps the finished rows of its partial file,
//! computes only the rest, and ends byte-identical to an uninterrupted run; a partial file from
//! other inputs or a damaged one is refused before any work.
//!
//! Interruptions: the test hook `SUPERLUBE_TEST_KILL_AFTER_ROWS=N` (the process writes N rows
//! and half of the next line, then exits 137 without clean-up: a kill at a known row) and, once,
//! a real SIGKILL while the sweep runs. "Not recomputed" is read from the resumed run's progress
//! lines: its stage counts only the items it computes (`screen: 100% (13/13 θ)`).

mod common;
use common::{assert_ok, bin, tmpdir};
use std::path::{Path, PathBuf};
use std::process::{Output, Stdio};

const TINY: [&str; 6] = [
    "--pattern",
    "tri-tri",
    "--slider-radius-um",
    "9",
    "--substrate-um",
    "60x40",
];

fn args(cmd: &str, rest: &[&str]) -> Vec<String> {
    std::iter::once(cmd)
        .chain(TINY.iter().copied())
        .chain(rest.iter().copied())
        .map(String::from)
        .collect()
}

fn run(a: &[String], out: &Path, extra: &[&str], kill_after: Option<u64>) -> Output {
    let mut c = bin();
    c.args(a).args(extra).arg("--out").arg(out);
    if let Some(n) = kill_after {
        c.env("SUPERLUBE_TEST_KILL_AFTER_ROWS", n.to_string());
    }
    c.output().unwrap()
}

fn partial(out: &Path) -> PathBuf {
    let mut p = out.as_os_str().to_owned();
    p.push(".partial");
    PathBuf::from(p)
}

/// Kills `a` after `kill_after` rows of the streamed file `stream` (the output or, for an
/// unsharded landscape, its heights file), checks what the partial file holds, resumes, and
/// returns the resumed run's stderr after checking the bytes against an uninterrupted run.
fn interrupt_and_resume(
    dir: &Path,
    a: &[String],
    name: &str,
    stream: &str,
    kill_after: u64,
    extra: &[&str],
) -> String {
    let reference = dir.join(format!("{name}.ref.csv"));
    assert_ok(&run(a, &reference, extra, None));
    let out = dir.join(format!("{name}.csv"));
    let o = run(a, &out, extra, Some(kill_after));
    assert_eq!(
        o.status.code(),
        Some(137),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!out.exists());
    let part = partial(&dir.join(stream));
    let text = std::fs::read_to_string(&part).unwrap();
    // header + kill_after complete rows + a torn line
    assert_eq!(text.matches('\n').count() as u64, 1 + kill_after, "{text}");
    assert!(!text.ends_with('\n'), "no torn line: {text}");
    let o = run(a, &out, &[extra, &["--resume"]].concat(), None);
    assert_ok(&o);
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&reference).unwrap(),
        "{name}: resumed output differs from the uninterrupted one"
    );
    assert!(!part.exists());
    assert!(!partial(&out).exists());
    let m: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join(format!("{name}.csv.meta.json"))).unwrap(),
    )
    .unwrap();
    let r: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join(format!("{name}.ref.csv.meta.json"))).unwrap(),
    )
    .unwrap();
    assert_eq!(m["input_hash"], r["input_hash"]);
    assert_eq!(m["rows"], r["rows"]);
    assert_eq!(m["complete"], true);
    String::from_utf8(o.stderr).unwrap()
}

#[test]
fn screen_resumes_without_recomputing_finished_rows() {
    let d = tmpdir("resume-screen");
    // 31 θ × 2 loads; killed after 37 rows: 18 θ complete, one row of the 19th, a torn line.
    let a = args("screen", &["--theta", "0:30:1", "--load-mn", "0.01,0.02"]);
    let err = interrupt_and_resume(&d, &a, "s", "s.csv", 37, &[]);
    assert!(
        err.contains("36 rows kept (18 of this run's 31 θ done)")
            && err.contains("torn last line")
            && err.contains("1 row(s) of an unfinished item dropped"),
        "{err}"
    );
    // only the 13 θ left were solved
    assert!(err.contains("screen: 100% (13/13 θ)"), "{err}");
    assert!(!err.contains("/31 θ"), "{err}");
    // a shard resumes the same way
    let err = interrupt_and_resume(&d, &a, "sh", "sh.csv", 5, &["--shard", "1/2"]);
    assert!(
        err.contains("4 rows kept (2 of this run's 16 θ done)"),
        "{err}"
    );
    assert!(err.contains("screen: 100% (14/14 θ)"), "{err}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn landscape_and_corrugation_resume() {
    let d = tmpdir("resume-maps");
    // The unsharded landscape resumes its heights (OUT.z.partial), then writes Δz.
    let a = args("landscape", &["--grid", "7", "--theta", "3"]);
    let err = interrupt_and_resume(&d, &a, "l", "l.csv.z", 20, &[]);
    assert!(
        err.contains("20 rows kept (20 of this run's 49 grid points done)"),
        "{err}"
    );
    assert!(err.contains("landscape: 100% (29/29 grid points)"), "{err}");
    assert!(!d.join("l.csv.z").exists() && !d.join("l.csv.z.meta.json").exists());
    // …and with a plot, whose Δz comes from all 49 heights
    let plot = d.join("l.png");
    let err = interrupt_and_resume(
        &d,
        &a,
        "lp",
        "lp.csv.z",
        30,
        &["--plot", plot.to_str().unwrap()],
    );
    assert!(err.contains("(19/19 grid points)"), "{err}");
    assert!(plot.exists());
    // a landscape shard resumes its z rows
    let err = interrupt_and_resume(&d, &a, "ls", "ls.csv", 3, &["--shard", "2/3"]);
    assert!(err.contains("(14/14 grid points)"), "{err}"); // 17 in shard 2/3 of 49
                                                           // corrugation: one row per α; the plot of a resumed run reads the kept rows back
    let a = args(
        "corrugation",
        &[
            "--alpha",
            "0,20,45,70,90",
            "--distance-um",
            "3",
            "--step-um",
            "0.5",
        ],
    );
    let plot = d.join("c.png");
    let err = interrupt_and_resume(&d, &a, "c", "c.csv", 2, &["--plot", plot.to_str().unwrap()]);
    assert!(
        err.contains("2 rows kept (2 of this run's 5 α done)"),
        "{err}"
    );
    assert!(err.contains("corrugation: 100% (21/21 solves)"), "{err}"); // 3 α × 7 samples
    assert!(plot.exists());
    std::fs::remove_dir_all(&d).ok();
}

/// A real SIGKILL in the middle of a long screen (the partial file ends wherever the kill
/// landed, usually inside a line), then `--resume`.
#[test]
fn killed_screen_resumes_to_the_same_bytes() {
    let d = tmpdir("resume-kill");
    let a = args(
        "screen",
        &["--theta", "0:30:0.0005", "--load-mn", "0.01,0.02"],
    );
    let out = d.join("k.csv");
    let mut child = bin()
        .args(&a)
        .arg("--out")
        .arg(&out)
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let t0 = std::time::Instant::now();
    loop {
        let n = std::fs::metadata(partial(&out)).map_or(0, |m| m.len());
        if n > 20_000 || t0.elapsed().as_secs() > 60 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(!out.exists(), "the sweep finished before the kill");
    let kept = std::fs::read_to_string(partial(&out))
        .unwrap()
        .matches('\n')
        .count();
    let o = run(&a, &out, &["--resume"], None);
    assert_ok(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("resuming"), "{err}");
    let reference = d.join("ref.csv");
    assert_ok(&run(&a, &reference, &[], None));
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&reference).unwrap()
    );
    // The resumed run solved only what was missing: its stage counted the θ left.
    let left = 60001 - (kept - 1) / 2;
    assert!(
        err.contains(&format!("screen: 100% ({left}/{left} θ)")),
        "{kept} lines kept: {err}"
    );
    std::fs::remove_dir_all(&d).ok();
}

fn fails_with(o: &Output, words: &[&str]) {
    assert!(!o.status.success(), "should fail");
    let err = String::from_utf8_lossy(&o.stderr);
    for w in words {
        assert!(err.contains(w), "`{err}` lacks `{w}`");
    }
}

#[test]
fn resume_refuses_other_inputs_and_damaged_files() {
    let d = tmpdir("resume-refuse");
    let a = args("screen", &["--theta", "0:30:1", "--load-mn", "0.01,0.02"]);
    let out = d.join("r.csv");
    let part = partial(&out);
    let kill = |n| assert_eq!(run(&a, &out, &[], Some(n)).status.code(), Some(137));
    kill(20);
    let before = std::fs::read(&part).unwrap();
    // other inputs: refused, naming the difference; the partial file is left as it was
    let b = args("screen", &["--theta", "0:30:1", "--load-mn", "0.01,0.03"]);
    let o = run(&b, &out, &["--resume"], None);
    fails_with(&o, &["`--resume`", "different inputs", "load_mN"]);
    assert_eq!(std::fs::read(&part).unwrap(), before);
    // another shard
    let o = run(&a, &out, &["--resume", "--shard", "0/2"], None);
    fails_with(&o, &["`--resume`", "whole sweep", "shard 0/2"]);
    // damaged: a row with a missing field in the middle
    let text = String::from_utf8(before.clone()).unwrap();
    let mut lines: Vec<String> = text.split_inclusive('\n').map(String::from).collect();
    lines[5] = lines[5].split_once(',').unwrap().1.to_string();
    std::fs::write(&part, lines.concat()).unwrap();
    let o = run(&a, &out, &["--resume"], None);
    fails_with(&o, &["`--resume`", "damaged", "line 6"]);
    // damaged: NUL bytes (what a crash can leave)
    let mut z = before.clone();
    z.extend([0u8; 64]);
    z.push(b'\n');
    std::fs::write(&part, &z).unwrap();
    fails_with(&run(&a, &out, &["--resume"], None), &["damaged", "NUL"]);
    // no sidecar: cannot tell its inputs
    std::fs::write(&part, &before).unwrap();
    let side = d.join("r.csv.partial.meta.json");
    let side_text = std::fs::read(&side).unwrap();
    std::fs::remove_file(&side).unwrap();
    fails_with(
        &run(&a, &out, &["--resume"], None),
        &["`--resume`", "sidecar"],
    );
    std::fs::write(&side, side_text).unwrap();
    // intact again: resumes to the uninterrupted bytes
    assert_ok(&run(&a, &out, &["--resume"], None));
    let reference = d.join("ref.csv");
    assert_ok(&run(&a, &reference, &[], None));
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&reference).unwrap()
    );
    // nothing to resume: starts from the beginning
    let fresh = d.join("fresh.csv");
    let o = run(&a, &fresh, &["--resume"], None);
    assert_ok(&o);
    assert_eq!(
        std::fs::read(&fresh).unwrap(),
        std::fs::read(&reference).unwrap()
    );
    // stdout cannot be resumed
    let o = bin().args(&a).arg("--resume").output().unwrap();
    fails_with(&o, &["`--resume`", "--out"]);
    std::fs::remove_dir_all(&d).ok();
}
