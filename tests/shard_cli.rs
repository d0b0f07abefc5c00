//! `--shard i/n` and `superlube merge` (issue 10, point 1): merged shards are byte for byte the
//! unsharded output, with the unsharded run's input hash and row count; shards of different
//! sweeps, a missing or duplicate shard, incomplete or damaged shard files are refused, naming
//! the file and what differs; bad `--shard` values are refused naming the flag.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};
use std::path::{Path, PathBuf};

const TINY: [&str; 6] = [
    "--pattern",
    "tri-tri",
    "--slider-radius-um",
    "9",
    "--substrate-um",
    "60x40",
];

/// The 31-angle screen of the check (θ = 0:30:1°, two loads).
fn screen_args(load: &str) -> Vec<String> {
    let mut v: Vec<String> = ["screen"]
        .iter()
        .chain(TINY.iter())
        .map(|s| s.to_string())
        .collect();
    v.extend(["--theta", "0:30:1", "--load-mn", load].map(String::from));
    v
}

/// Runs `args` with `--out out` and extra flags; asserts success.
fn run_to(args: &[String], out: &Path, extra: &[&str]) {
    let o = bin()
        .args(args)
        .args(extra)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap();
    assert_ok(&o);
}

fn meta(file: &Path) -> serde_json::Value {
    let mut p = file.as_os_str().to_owned();
    p.push(".meta.json");
    serde_json::from_str(&std::fs::read_to_string(PathBuf::from(p)).unwrap()).unwrap()
}

/// Runs `superlube merge files… --out out`.
fn merge(files: &[PathBuf], out: &Path) -> std::process::Output {
    bin()
        .arg("merge")
        .args(files)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

/// The shard files of `args` cut into `n` shards, written into `dir` as `name.i.csv`.
fn shards(args: &[String], dir: &Path, name: &str, n: usize) -> Vec<PathBuf> {
    (0..n)
        .map(|i| {
            let f = dir.join(format!("{name}.{i}.csv"));
            run_to(args, &f, &["--shard", &format!("{i}/{n}")]);
            f
        })
        .collect()
}

#[test]
fn screen_shards_merge_to_the_unsharded_bytes() {
    let d = tmpdir("shard-screen");
    let args = screen_args("0.01,0.02");
    let whole = d.join("whole.csv");
    run_to(&args, &whole, &[]);
    let expect = std::fs::read(&whole).unwrap();
    assert_eq!(String::from_utf8_lossy(&expect).lines().count(), 1 + 31 * 2);
    let wm = meta(&whole);
    for n in [1usize, 2, 3, 7] {
        let mut files = shards(&args, &d, &format!("s{n}"), n);
        for (i, f) in files.iter().enumerate() {
            let m = meta(f);
            // the shard is recorded beside the sweep's unchanged input hash
            assert_eq!(m["input_hash"], wm["input_hash"], "shard {i}/{n}");
            assert_eq!(m["shard"]["index"], i);
            assert_eq!(m["shard"]["count"], n);
            assert_eq!(m["shard"]["items"], 31);
            assert_eq!(m["shard"]["rows_per_item"], 2);
            let r = &m["shard"]["item_range"];
            assert_eq!(r[0], 31 * i / n);
            assert_eq!(r[1], 31 * (i + 1) / n);
            assert_eq!(m["rows"], 2 * (31 * (i + 1) / n - 31 * i / n));
        }
        files.reverse(); // any order
        let out = d.join(format!("merged{n}.csv"));
        assert_ok(&merge(&files, &out));
        assert_eq!(std::fs::read(&out).unwrap(), expect, "{n} shards");
        let mm = meta(&out);
        assert_eq!(mm["input_hash"], wm["input_hash"]);
        assert_eq!(mm["rows"], 62);
        assert_eq!(mm["complete"], true);
        assert_eq!(mm["workflow"], "screen");
        assert_eq!(mm["params"], wm["params"]);
        assert_eq!(mm["scene"], wm["scene"]);
        assert!(mm.get("shard").is_none());
        assert_eq!(mm["merged_from"].as_array().unwrap().len(), n);
    }
    // to stdout too
    let files = shards(&args, &d, "o", 2);
    let o = bin().arg("merge").args(&files).output().unwrap();
    assert_ok(&o);
    assert_eq!(o.stdout, expect);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn landscape_and_corrugation_shards_merge_to_the_unsharded_bytes() {
    let d = tmpdir("shard-maps");
    // Landscape: the shards hold exact heights z; the merge computes Δz over the whole grid.
    let mut land: Vec<String> = ["landscape", "--grid", "7", "--theta", "3"]
        .iter()
        .chain(TINY.iter())
        .map(|s| s.to_string())
        .collect();
    let whole = d.join("land.csv");
    run_to(&land, &whole, &[]);
    assert!(!d.join("land.csv.z").exists(), "spill file left behind");
    for n in [2usize, 3] {
        let files = shards(&land, &d, &format!("l{n}"), n);
        let head = std::fs::read_to_string(&files[0]).unwrap();
        assert!(head.starts_with("x_um,y_um,z_um\n"), "{head}");
        let out = d.join(format!("lm{n}.csv"));
        assert_ok(&merge(&files, &out));
        assert_eq!(
            std::fs::read(&out).unwrap(),
            std::fs::read(&whole).unwrap(),
            "landscape, {n} shards"
        );
        assert_eq!(meta(&out)["input_hash"], meta(&whole)["input_hash"]);
        assert_eq!(meta(&out)["rows"], 49);
    }
    // Corrugation: one row per α.
    land.clear();
    let corr: Vec<String> = [
        "corrugation",
        "--alpha",
        "0,20,45,70,90",
        "--distance-um",
        "3",
        "--step-um",
        "0.5",
    ]
    .iter()
    .chain(TINY.iter())
    .map(|s| s.to_string())
    .collect();
    let whole = d.join("corr.csv");
    run_to(&corr, &whole, &[]);
    let files = shards(&corr, &d, "c", 3);
    let out = d.join("cm.csv");
    assert_ok(&merge(&files, &out));
    assert_eq!(std::fs::read(&out).unwrap(), std::fs::read(&whole).unwrap());
    std::fs::remove_dir_all(&d).ok();
}

/// Asserts that merging `files` fails naming every word of `words`, and writes nothing.
fn refused(files: &[PathBuf], out: &Path, words: &[&str]) {
    let o = merge(files, out);
    assert!(!o.status.success(), "{files:?} should be refused");
    let err = String::from_utf8_lossy(&o.stderr);
    for w in words {
        assert!(err.contains(w), "`{err}` lacks `{w}`");
    }
    assert!(!out.exists(), "{} written", out.display());
    let mut p = out.as_os_str().to_owned();
    p.push(".partial");
    assert!(!PathBuf::from(p).exists());
}

#[test]
fn merge_refuses_what_is_not_one_whole_sweep() {
    let d = tmpdir("shard-refuse");
    let out = d.join("all.csv");
    let a = shards(&screen_args("0.01,0.02"), &d, "a", 3);
    let b = shards(&screen_args("0.01,0.03"), &d, "b", 3);
    // shards of two different sweeps: the file and the differing parameter are named
    let name = |p: &PathBuf| p.file_name().unwrap().to_string_lossy().into_owned();
    refused(
        &[a[0].clone(), b[1].clone(), a[2].clone()],
        &out,
        &[&name(&b[1]), "another sweep", "load_mN"],
    );
    // a missing shard
    refused(&[a[0].clone(), a[2].clone()], &out, &["1/3", "missing"]);
    // a duplicate
    refused(
        &[a[0].clone(), a[1].clone(), a[1].clone(), a[2].clone()],
        &out,
        &["both shard 1/3"],
    );
    // shards of another cut of the same sweep
    let c = shards(&screen_args("0.01,0.02"), &d, "c", 2);
    refused(
        &[a[0].clone(), c[1].clone(), a[2].clone()],
        &out,
        &["1/2", "0/3"],
    );
    // an unsharded output
    let whole = d.join("whole.csv");
    run_to(&screen_args("0.01,0.02"), &whole, &[]);
    refused(
        std::slice::from_ref(&whole),
        &out,
        &["not a shard", "whole.csv"],
    );
    // an incomplete (partial) file
    let partial = d.join("a.1.csv.partial");
    std::fs::copy(&a[1], &partial).unwrap();
    std::fs::write(
        d.join("a.1.csv.partial.meta.json"),
        std::fs::read_to_string(d.join("a.1.csv.meta.json"))
            .unwrap()
            .replace("\"complete\": true", "\"complete\": false"),
    )
    .unwrap();
    refused(
        &[a[0].clone(), partial.clone(), a[2].clone()],
        &out,
        &["a.1.csv.partial", "incomplete"],
    );
    // no sidecar
    let bare = d.join("bare.csv");
    std::fs::copy(&a[1], &bare).unwrap();
    refused(
        &[a[0].clone(), bare, a[2].clone()],
        &out,
        &["bare.csv", "sidecar"],
    );
    // a damaged shard: a row lost
    let text = std::fs::read_to_string(&a[1]).unwrap();
    let mut lines: Vec<&str> = text.lines().collect();
    lines.remove(3);
    std::fs::write(&a[1], lines.join("\n") + "\n").unwrap();
    refused(&a, &out, &[&name(&a[1]), "damaged"]);
    // a hand-edited sidecar
    let a = shards(&screen_args("0.01,0.02"), &d, "e", 3);
    let m = d.join("e.2.csv.meta.json");
    std::fs::write(
        &m,
        std::fs::read_to_string(&m)
            .unwrap()
            .replace("\"model\": \"auto\"", "\"model\": \"compliant\""),
    )
    .unwrap();
    refused(&a, &out, &["e.2.csv", "edited"]);
    // the output must not be one of the inputs
    let a = shards(&screen_args("0.01,0.02"), &d, "f", 2);
    let o = merge(&a, &a[0]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("`--out`"));
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn bad_shard_flags_name_the_flag() {
    let d = tmpdir("shard-flags");
    let out = d.join("x.csv");
    let out = out.to_str().unwrap();
    let base = [
        "screen",
        "--theta",
        "0:30:1",
        "--load-mn",
        "0.01",
        "--out",
        out,
    ];
    for bad in ["3/3", "-1/2", "1/0", "1", "a/2"] {
        let mut args = base.to_vec();
        args.extend(["--shard", bad]);
        fails_naming(&args, "--shard");
    }
    // more shards than θ values
    let mut args = base.to_vec();
    args.extend(["--shard", "0/40"]);
    fails_naming(&args, "31 θ");
    // a shard needs --out; --contacts-out / --plot cannot be sharded
    fails_naming(&["screen", "--theta", "0:30:1", "--shard", "0/2"], "--out");
    fails_naming(
        &[
            "screen",
            "--theta",
            "1",
            "--load-mn",
            "1",
            "--shard",
            "0/1",
            "--out",
            out,
            "--contacts-out",
            "c.csv",
        ],
        "--contacts-out",
    );
    fails_naming(
        &[
            "landscape",
            "--grid",
            "3",
            "--shard",
            "0/2",
            "--out",
            out,
            "--plot",
            "p.png",
        ],
        "--plot",
    );
    fails_naming(&["screen", "--resume"], "--out");
    assert!(!Path::new(out).exists());
    std::fs::remove_dir_all(&d).ok();
}
