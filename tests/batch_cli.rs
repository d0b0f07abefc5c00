//! `superlube slide` batches (lists of θ, α, W, seeds; `--out-dir`, `--jobs`, `--shard`) and
//! the friction campaign (`superlube figures --friction`) end to end on tiny scenes with
//! sub-µs protocols: bit-identical runs side by side and one by one, resume without repeating
//! finished runs, a blown-up run reported in its row while the others finish, shards giving
//! the unsharded result, refusals before any work.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};

use std::path::{Path, PathBuf};
use std::process::Command;

/// A tiny square-tri scene and a 0.1 + 0.1 + 0.3 µs protocol at 1 m/s.
const TINY: [&str; 16] = [
    "--pattern",
    "square-tri",
    "--slider-radius-um",
    "9",
    "--substrate-um",
    "60x40",
    "--equilibrate-us",
    "0.1",
    "--relax-us",
    "0.1",
    "--slide-us",
    "0.3",
    "--speed-m-s",
    "1",
    "--model",
    "reduced",
];

fn slide(extra: &[&str]) -> Command {
    let mut c = bin();
    c.arg("slide").args(TINY).args(extra);
    c
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// The CSV rows of `runs.csv` as maps column → value.
fn rows(p: &Path) -> Vec<std::collections::BTreeMap<String, String>> {
    let mut r = csv::Reader::from_path(p).unwrap();
    let h = r.headers().unwrap().clone();
    r.records()
        .map(|rec| {
            h.iter()
                .zip(rec.unwrap().iter())
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect()
        })
        .collect()
}

/// `runs.csv` without the columns that measure the machine (wall time).
fn without_wall(p: &Path) -> Vec<std::collections::BTreeMap<String, String>> {
    let mut v = rows(p);
    for r in &mut v {
        r.remove("wall_s");
    }
    v
}

fn run_dirs(d: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(d.join("runs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    v.sort();
    v
}

#[test]
fn side_by_side_equals_one_by_one_and_a_single_run() {
    let d = tmpdir("batch-same");
    let (a, b) = (d.join("a"), d.join("b"));
    let loads = ["--load-mn", "0.02,0.04", "--alpha", "0,90"];
    let out = slide(&loads)
        .args(["--jobs", "2", "--out-dir"])
        .arg(&a)
        .output()
        .unwrap();
    assert_ok(&out);
    let out = slide(&loads)
        .args(["--jobs", "1", "--out-dir"])
        .arg(&b)
        .output()
        .unwrap();
    assert_ok(&out);
    let (ra, rb) = (run_dirs(&a), run_dirs(&b));
    assert_eq!(ra.len(), 4);
    for (x, y) in ra.iter().zip(&rb) {
        assert_eq!(x.file_name(), y.file_name());
        assert_eq!(read(&x.join("slide.csv")), read(&y.join("slide.csv")));
        assert!(
            !x.join("slide.ckpt").exists(),
            "checkpoint of a finished run removed"
        );
    }
    // rows in config order (θ, α, W), every input and result column
    let r = rows(&a.join("runs.csv"));
    let order: Vec<(&str, &str)> = r
        .iter()
        .map(|r| (r["alpha_deg"].as_str(), r["load_mN"].as_str()))
        .collect();
    assert_eq!(
        order,
        [
            ("0.0", "0.02"),
            ("0.0", "0.04"),
            ("90.0", "0.02"),
            ("90.0", "0.04")
        ]
    );
    for k in [
        "pattern",
        "theta_deg",
        "sigma_h_um",
        "seed",
        "youngs_GPa",
        "p_crit_GPa",
        "mu1",
        "mu2",
        "mount",
        "model_requested",
        "model",
        "rigid_z",
        "equilibrate_us",
        "slide_us",
        "speed_m_s",
        "dt_us",
        "friction_mN",
        "friction_std_mN",
        "mu",
        "mean_contacts",
        "max_p_max_GPa",
        "mean_failed_contacts",
        "locked_in",
        "advance_ratio",
        "steps",
        "wall_s",
        "status",
        "error",
    ] {
        assert!(r[0].contains_key(k), "runs.csv lacks {k}");
    }
    assert!(r
        .iter()
        .all(|r| r["status"] == "ok" && r["model"] == "reduced"));
    assert!(a.join("runs.csv.meta.json").exists());
    assert!(!a.join("seeds.csv").exists());
    // the same run as a single `superlube slide` gives the same time series
    let single = d.join("single.csv");
    let out = slide(&["--load-mn", "0.04", "--alpha", "90", "--out"])
        .arg(&single)
        .output()
        .unwrap();
    assert_ok(&out);
    assert_eq!(read(&single), read(&ra[3].join("slide.csv")));
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn an_interrupted_batch_resumes_without_repeating_finished_runs() {
    let d = tmpdir("batch-resume");
    let (full, part) = (d.join("full"), d.join("part"));
    let batch = ["--load-mn", "0.02,0.03,0.04", "--jobs", "1"];
    let out = slide(&batch).arg("--out-dir").arg(&full).output().unwrap();
    assert_ok(&out);
    let names: Vec<_> = run_dirs(&full)
        .iter()
        .map(|p| p.file_name().unwrap().to_owned())
        .collect();
    assert_eq!(names.len(), 3);
    // The state an interruption during the second run leaves: the first run finished (here
    // by a batch of its load alone: the same run, the same directory), the second with a
    // mid-run checkpoint (made by a single run checkpointing every 500 steps into the
    // batch's checkpoint path: the same inputs), the third not started.
    let out = slide(&["--load-mn", "0.02", "--out-dir"])
        .arg(&part)
        .output()
        .unwrap();
    assert_ok(&out);
    let second = part.join("runs").join(&names[1]);
    std::fs::create_dir_all(&second).unwrap();
    let out = slide(&[
        "--load-mn",
        "0.03",
        "--checkpoint-every",
        "500",
        "--checkpoint",
    ])
    .arg(second.join("slide.ckpt"))
    .arg("--out")
    .arg(d.join("scratch.csv"))
    .output()
    .unwrap();
    assert_ok(&out);
    assert!(second.join("slide.ckpt").exists());
    let first_json = part.join("runs").join(&names[0]).join("slide.json");
    let before = std::fs::metadata(&first_json).unwrap().modified().unwrap();
    std::thread::sleep(std::time::Duration::from_millis(20));
    // rerun the whole batch into the same directory
    let out = slide(&batch).arg("--out-dir").arg(&part).output().unwrap();
    assert_ok(&out);
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(log.contains("3 runs in all, 1 finished earlier"), "{log}");
    let first = names[0].to_string_lossy();
    assert!(
        !log.contains(&format!("{first}: model:")),
        "the finished run was repeated: {log}"
    );
    let second_name = names[1].to_string_lossy();
    assert!(
        log.contains(&format!("{second_name}: resumed at step")),
        "{log}"
    );
    let third = names[2].to_string_lossy();
    assert!(log.contains(&format!("{third}: no checkpoint")), "{log}");
    assert_eq!(
        std::fs::metadata(&first_json).unwrap().modified().unwrap(),
        before,
        "the finished run's summary was rewritten"
    );
    // and the result is the uninterrupted batch's, bit for bit
    for n in &names {
        assert_eq!(
            read(&full.join("runs").join(n).join("slide.csv")),
            read(&part.join("runs").join(n).join("slide.csv"))
        );
    }
    assert_eq!(
        without_wall(&full.join("runs.csv")),
        without_wall(&part.join("runs.csv"))
    );
    // a third call has nothing left to run
    let out = slide(&batch).arg("--out-dir").arg(&part).output().unwrap();
    assert_ok(&out);
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(log.contains("3 finished earlier"), "{log}");
    assert!(!log.contains(": model:"), "{log}");
    // two stored runs of other inputs (as an older build's would be): one refusal names both,
    // before anything runs
    for n in &names[..2] {
        let side = part.join("runs").join(n).join("slide.json.meta.json");
        let text = read(&side);
        std::fs::write(&side, text.replace("\"sha256:", "\"sha256:0")).unwrap();
    }
    let out = slide(&batch).arg("--out-dir").arg(&part).output().unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("2 of 3 stored runs")
            && err.contains("nothing was run")
            && err.contains(&*names[0].to_string_lossy())
            && err.contains(&*names[1].to_string_lossy())
            && !err.contains(&*third),
        "{err}"
    );
    assert_eq!(
        std::fs::metadata(&first_json).unwrap().modified().unwrap(),
        before,
        "a refused batch rewrote a run"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn a_blown_up_run_is_reported_in_its_row_and_the_others_finish() {
    let d = tmpdir("batch-blowup");
    // 50 mN on this tiny slider overlaps beyond the bound: the run stops (blow-up)
    let out = slide(&["--load-mn", "0.02,50,0.04", "--jobs", "2", "--out-dir"])
        .arg(&d)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("1 of 3 runs failed"), "{err}");
    let r = rows(&d.join("runs.csv"));
    assert_eq!(r.len(), 3);
    assert_eq!(r[0]["status"], "ok");
    assert_eq!(r[2]["status"], "ok");
    assert_eq!(r[1]["status"], "failed");
    assert!(r[1]["error"].contains("unstable"), "{:?}", r[1]);
    assert_eq!(r[1]["friction_mN"], "");
    assert!(!r[0]["friction_mN"].is_empty());
    let dirs = run_dirs(&d);
    assert!(
        dirs[1].join("failed.json").exists() || dirs.iter().any(|p| p.join("failed.json").exists())
    );
    // a rerun does not repeat the failed run either
    let out = slide(&["--load-mn", "0.02,50,0.04", "--out-dir"])
        .arg(&d)
        .output()
        .unwrap();
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(log.contains("3 finished earlier"), "{log}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn seeds_give_per_configuration_statistics() {
    let d = tmpdir("batch-seeds");
    let out = slide(&[
        "--load-mn",
        "0.02",
        "--sigma-h-um",
        "0.002",
        "--seeds",
        "1,2,3",
        "--out-dir",
    ])
    .arg(&d)
    .output()
    .unwrap();
    assert_ok(&out);
    let r = rows(&d.join("runs.csv"));
    assert_eq!(
        r.iter().map(|r| r["seed"].as_str()).collect::<Vec<_>>(),
        ["1", "2", "3"]
    );
    let s = rows(&d.join("seeds.csv"));
    assert_eq!(s.len(), 1);
    assert_eq!(s[0]["n"], "3");
    let f: Vec<f64> = r
        .iter()
        .map(|r| r["friction_mN"].parse().unwrap())
        .collect();
    let mean = f.iter().sum::<f64>() / 3.0;
    let std = (f.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 2.0).sqrt();
    let got_mean: f64 = s[0]["friction_mean_mN"].parse().unwrap();
    let got_std: f64 = s[0]["friction_std_mN"].parse().unwrap();
    assert!((got_mean - mean).abs() <= 1e-12 * mean.abs());
    assert!((got_std - std).abs() <= 1e-9 * mean.abs());
    assert!(
        std > 0.0,
        "different seeds give different substrates: {f:?}"
    );
    assert!(d.join("seeds.csv.meta.json").exists());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn shards_write_into_one_directory_and_give_the_unsharded_result() {
    let d = tmpdir("batch-shard");
    let (whole, sh) = (d.join("whole"), d.join("sharded"));
    let batch = ["--load-mn", "0.02,0.03,0.04"];
    assert_ok(&slide(&batch).arg("--out-dir").arg(&whole).output().unwrap());
    let out = slide(&batch)
        .args(["--shard", "0/2", "--out-dir"])
        .arg(&sh)
        .output()
        .unwrap();
    assert_ok(&out);
    assert!(String::from_utf8_lossy(&out.stderr).contains("2 of 3 runs not finished yet"));
    assert!(!sh.join("runs.csv").exists());
    let out = slide(&batch)
        .args(["--shard", "1/2", "--out-dir"])
        .arg(&sh)
        .output()
        .unwrap();
    assert_ok(&out);
    assert_eq!(
        without_wall(&whole.join("runs.csv")),
        without_wall(&sh.join("runs.csv"))
    );
    // the summary's sidecar records the same inputs as the unsharded batch's
    let hash = |p: &Path| {
        let v: serde_json::Value = serde_json::from_str(&read(p)).unwrap();
        v["input_hash"].as_str().unwrap().to_string()
    };
    assert_eq!(
        hash(&whole.join("runs.csv.meta.json")),
        hash(&sh.join("runs.csv.meta.json"))
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn bad_batch_input_is_refused_before_any_work() {
    let d = tmpdir("batch-bad");
    let dir = d.join("out");
    let dir_s = dir.to_str().unwrap();
    let tiny = |extra: &[&str]| -> Vec<String> {
        let mut v: Vec<String> = ["slide"].iter().map(|s| s.to_string()).collect();
        v.extend(TINY.iter().map(|s| s.to_string()));
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    for (extra, flag) in [
        (vec!["--seeds", "1,2", "--out-dir", dir_s], "--seeds"),
        (
            vec!["--load-mn", "0.02,0.04", "--jobs", "0", "--out-dir", dir_s],
            "--jobs",
        ),
        (vec!["--load-mn", "", "--out-dir", dir_s], "--load-mn"),
        (vec!["--theta", "", "--out-dir", dir_s], "--theta"),
        (vec!["--alpha", "0,500", "--out-dir", dir_s], "--alpha"),
        (
            vec!["--seeds", "", "--sigma-h-um", "0.002", "--out-dir", dir_s],
            "--seeds",
        ),
        (
            vec![
                "--seeds",
                "1,-2",
                "--sigma-h-um",
                "0.002",
                "--out-dir",
                dir_s,
            ],
            "--seeds",
        ),
        (vec!["--load-mn", "0.02,0.04"], "--out-dir"),
        (
            vec![
                "--load-mn",
                "0.02,0.04",
                "--out-dir",
                dir_s,
                "--out",
                "x.csv",
            ],
            "--out",
        ),
        (
            vec![
                "--load-mn",
                "0.02,0.04",
                "--out-dir",
                dir_s,
                "--shard",
                "3/2",
            ],
            "--shard",
        ),
        (
            vec![
                "--load-mn",
                "0.02,0.04",
                "--out-dir",
                dir_s,
                "--shard",
                "0/3",
            ],
            "--shard",
        ),
    ] {
        let args = tiny(&extra);
        let a: Vec<&str> = args.iter().map(|s| s.as_str()).collect();
        fails_naming(&a, flag);
    }
    assert!(!dir.exists(), "nothing written before the checks");
    fails_naming(&["equilibrate", "--load-mn", "0.02,0.04"], "--load-mn");
    std::fs::remove_dir_all(&d).ok();
}

/// The friction campaign's machinery on the tiny scene and protocol: run list, files, figures,
/// shards into one directory, resume.
#[test]
fn friction_campaign_runs_resumes_and_shards() {
    let d = tmpdir("campaign");
    let (whole, sh) = (d.join("whole"), d.join("sharded"));
    let args = [
        "figures",
        "--friction",
        "--fig",
        "2b,6",
        "--load-mn",
        "0.02",
        "--slider-radius-um",
        "9",
        "--substrate-um",
        "60x40",
        "--equilibrate-us",
        "0.1",
        "--relax-us",
        "0.1",
        "--slide-us",
        "0.3",
        "--speed-m-s",
        "1",
        "--jobs",
        "2",
    ];
    let out = bin()
        .args(args)
        .arg("--out-dir")
        .arg(&whole)
        .output()
        .unwrap();
    assert_ok(&out);
    // Fig 6 holds the tri-tri series of Fig 2b: 3 + 4 runs, not 10
    let r = rows(&whole.join("runs.csv"));
    assert_eq!(r.len(), 7);
    assert!(r
        .iter()
        .all(|r| r["status"] == "ok" && r["model_requested"] == "reduced"));
    for f in ["friction_fig2b", "friction_fig6"] {
        for ext in ["png", "csv"] {
            let p = whole.join(format!("{f}.{ext}"));
            assert!(p.exists(), "{}", p.display());
            assert!(whole.join(format!("{f}.{ext}.meta.json")).exists());
        }
    }
    assert!(!whole.join("friction_fig7.csv").exists());
    let f6 = rows(&whole.join("friction_fig6.csv"));
    assert_eq!(f6.len(), 7);
    assert!(f6.iter().all(|r| r["n"] == "1" && r["load_mN"] == "0.02"));
    assert_eq!(f6[1]["series"], "square-tri θ=0° α=90°");
    // the tri-tri row of Fig 6 is the tri-tri run's result
    let tri = r
        .iter()
        .find(|r| r["pattern"] == "tri-tri" && r["theta_deg"] == "30.0")
        .unwrap();
    assert_eq!(f6[6]["friction_mean_mN"], tri["friction_mN"]);
    // a rerun runs nothing and leaves the figures as they were
    let out = bin()
        .args(args)
        .arg("--out-dir")
        .arg(&whole)
        .output()
        .unwrap();
    assert_ok(&out);
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(log.contains("7 finished earlier"), "{log}");
    assert!(log.contains("this call runs 0"), "{log}");
    // shards into one directory: the first draws nothing, the last draws the same figures
    let out = bin()
        .args(args)
        .args(["--shard", "0/2", "--out-dir"])
        .arg(&sh)
        .output()
        .unwrap();
    assert_ok(&out);
    assert!(!sh.join("friction_fig6.png").exists());
    assert!(!sh.join("runs.csv").exists());
    let out = bin()
        .args(args)
        .args(["--shard", "1/2", "--out-dir"])
        .arg(&sh)
        .output()
        .unwrap();
    assert_ok(&out);
    assert_eq!(
        without_wall(&whole.join("runs.csv")),
        without_wall(&sh.join("runs.csv"))
    );
    assert_eq!(
        read(&whole.join("friction_fig6.csv")),
        read(&sh.join("friction_fig6.csv"))
    );
    // flags of the campaign are refused without --friction, and bad ones name themselves
    fails_naming(&["figures", "--seeds", "1,2"], "--friction");
    fails_naming(&["figures", "--friction", "--seeds", "1,1"], "--seeds");
    fails_naming(&["figures", "--friction", "--jobs", "0"], "--jobs");
    fails_naming(&["figures", "--friction", "--shard", "0/500"], "--shard");
    std::fs::remove_dir_all(&d).ok();
}

/// A slide too short for an advance ratio (`"advance_ratio": null` in its summary) is still a
/// finished run: the batch reads it back (it used to stop with "not a run summary of this
/// version") and leaves the column empty.
#[test]
fn a_run_without_an_advance_ratio_is_read_back() {
    let d = tmpdir("batch-null-ratio");
    let out = bin()
        .arg("slide")
        .args([
            "--pattern",
            "tri-tri",
            "--slider-radius-um",
            "9",
            "--substrate-um",
            "60x40",
            "--equilibrate-us",
            "0.02",
            "--relax-us",
            "0.02",
            "--slide-us",
            "0.02",
            "--model",
            "reduced",
            "--load-mn",
            "0.35,0.7",
            "--jobs",
            "2",
            "--out-dir",
        ])
        .arg(&d)
        .output()
        .unwrap();
    assert_ok(&out);
    let r = rows(&d.join("runs.csv"));
    assert_eq!(r.len(), 2);
    for row in &r {
        assert_eq!(row["status"], "ok", "{row:?}");
        assert_eq!(row["advance_ratio"], "", "{row:?}");
    }
    std::fs::remove_dir_all(&d).ok();
}
