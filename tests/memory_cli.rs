//! Memory stays flat as a sweep grows (issue 7, item 8): a screen with 100× more rows has the
//! same peak resident set size. Its own test binary: the peak RSS of children is a per-process
//! total (`getrusage(RUSAGE_CHILDREN)`), so no other test may spawn children beside it.

mod common;
use common::{assert_ok, bin};
use std::process::Stdio;

/// Largest peak RSS (kB) of any child waited for so far.
fn children_max_rss_kb() -> i64 {
    // SAFETY: getrusage only writes into the zeroed struct we pass.
    unsafe {
        let mut u: libc::rusage = std::mem::zeroed();
        assert_eq!(libc::getrusage(libc::RUSAGE_CHILDREN, &mut u), 0);
        u.ru_maxrss
    }
}

fn screen(theta: &str, extra: &[&str]) {
    let out = bin()
        .args(["screen", "--pattern", "tri-tri", "--slider-radius-um", "9"])
        .args([
            "--substrate-um",
            "60x40",
            "--load-mn",
            "0.01,0.02,0.03,0.04",
        ])
        .args(["--theta", theta])
        .args(extra)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert_ok(&out);
}

#[cfg(target_os = "linux")]
#[test]
fn screen_memory_does_not_grow_with_rows() {
    // 400 rows, then 40 000 rows (to stdout and to a file).
    screen("0:30:0.3", &[]);
    let small = children_max_rss_kb();
    screen("0:30:0.003", &[]);
    let large_stdout = children_max_rss_kb();
    let d = common::tmpdir("memory");
    let f = d.join("big.csv");
    screen("0:30:0.003", &["--out", f.to_str().unwrap()]);
    let large_file = children_max_rss_kb();
    let bytes = std::fs::metadata(&f).unwrap().len();
    std::fs::remove_dir_all(&d).ok();
    // The 40 000-row CSV is ≈ 5 MB; keeping its rows (let alone their contact lists) would add
    // more than that to the peak.
    assert!(bytes > 4_000_000, "{bytes}");
    assert!(
        large_stdout - small < 3_000 && large_file - small < 3_000,
        "peak RSS grew with the rows: {small} kB → {large_stdout} kB (stdout), {large_file} kB (file)"
    );
}
