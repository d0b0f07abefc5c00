//! `superlube slurm` (issue 10, point 3): the array script, the dependent merge job and
//! `submit.sh`; running the array tasks locally one by one and then the merge gives the
//! unsharded output byte for byte; the sweep's flags are checked before anything is written,
//! with the same errors as running the sweep.

mod common;
use common::{assert_ok, bin, tmpdir};
use std::path::Path;
use std::process::{Command, Output};

const TINY: [&str; 6] = [
    "--pattern",
    "tri-tri",
    "--slider-radius-um",
    "9",
    "--substrate-um",
    "60x40",
];

fn sweep(cmd: &str, rest: &[&str]) -> Vec<String> {
    std::iter::once(cmd)
        .chain(TINY.iter().copied())
        .chain(rest.iter().copied())
        .map(String::from)
        .collect()
}

fn slurm(sweep: &[String], opts: &[&str]) -> Output {
    bin().arg("slurm").args(sweep).args(opts).output().unwrap()
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Runs every array task of `dir/array.sbatch` with bash, one after the other as Slurm would
/// (SLURM_ARRAY_TASK_ID = 0..n), then `merge.sbatch`.
fn run_locally(dir: &Path, n: usize) {
    for i in 0..n {
        let o = Command::new("bash")
            .arg(dir.join("array.sbatch"))
            .env("SLURM_ARRAY_TASK_ID", i.to_string())
            .output()
            .unwrap();
        assert_ok(&o);
    }
    let o = Command::new("bash")
        .arg(dir.join("merge.sbatch"))
        .output()
        .unwrap();
    assert_ok(&o);
}

#[test]
fn scripts_say_what_slurm_needs() {
    let d = tmpdir("slurm-script");
    let job = d.join("job");
    let s = sweep("screen", &["--theta", "0:30:1", "--load-mn", "0.01,0.02"]);
    let o = slurm(
        &s,
        &[
            "--shards",
            "3",
            "--out-dir",
            job.to_str().unwrap(),
            "--cpus-per-task",
            "2",
            "--partition",
            "short",
            "--account",
            "proj1",
            "--time",
            "2:00:00",
            "--mem",
            "2G",
        ],
    );
    assert_ok(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("submit with:  sh") && err.contains("submit.sh"),
        "{err}"
    );
    let array = read(&job.join("array.sbatch"));
    let dir = job.to_str().unwrap();
    for want in [
        "#!/bin/bash\n",
        "#SBATCH --array=0-2\n",
        "#SBATCH --cpus-per-task=2\n",
        "export RAYON_NUM_THREADS=2\n",
        "#SBATCH --job-name=superlube-screen\n",
        "#SBATCH --partition=short\n",
        "#SBATCH --account=proj1\n",
        "#SBATCH --time=2:00:00\n",
        "#SBATCH --mem=2G\n",
        &format!("#SBATCH --output={dir}/logs/%x-%A_%a.out\n"),
        &format!("  {dir}/shards/screen.0-of-3.csv\n"),
        &format!("  {dir}/shards/screen.2-of-3.csv\n"),
        "--shard \"$i/3\" --resume --out \"${shards[$i]}\"",
        "screen --pattern tri-tri --slider-radius-um 9 --substrate-um 60x40 --theta 0:30:1 --load-mn 0.01,0.02 ",
        "SLURM_ARRAY_TASK_ID",
    ] {
        assert!(array.contains(want), "array.sbatch lacks `{want}`:\n{array}");
    }
    let merge = read(&job.join("merge.sbatch"));
    for want in [
        "#SBATCH --job-name=superlube-screen-merge\n",
        "#SBATCH --partition=short\n",
        &format!("merge \"${{shards[@]}}\" --out {dir}/screen.csv\n"),
    ] {
        assert!(
            merge.contains(want),
            "merge.sbatch lacks `{want}`:\n{merge}"
        );
    }
    assert!(!merge.contains("--array"));
    let submit = read(&job.join("submit.sh"));
    assert!(submit.contains("sbatch --parsable"), "{submit}");
    assert!(submit.contains("--dependency=afterok:"), "{submit}");
    assert!(job.join("logs").is_dir() && job.join("shards").is_dir());
    // Defaults: 4 threads, a job name, a time limit of at least 30 min.
    let job2 = d.join("job2");
    assert_ok(&slurm(
        &s,
        &["--shards", "7", "--out-dir", job2.to_str().unwrap()],
    ));
    let array = read(&job2.join("array.sbatch"));
    assert!(array.contains("#SBATCH --array=0-6\n"), "{array}");
    assert!(
        array.contains("#SBATCH --cpus-per-task=4\n#SBATCH --time=00:30:00\n"),
        "{array}"
    );
    assert!(
        !array.contains("--partition") && !array.contains("--account"),
        "{array}"
    );
    // The size guard holds per task: 3·10⁶ solves are refused in one run, but not in 4 shards.
    let big = sweep("screen", &["--theta", "0:30:0.00002", "--load-mn", "1,2"]);
    let job4 = d.join("job4");
    let o = slurm(
        &big,
        &["--shards", "1", "--out-dir", job4.to_str().unwrap()],
    );
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--force"));
    assert_ok(&slurm(
        &big,
        &["--shards", "4", "--out-dir", job4.to_str().unwrap()],
    ));
    // slurm's options may come before the command too
    let job3 = d.join("job3");
    let o = bin()
        .args([
            "slurm",
            "--shards",
            "2",
            "--out-dir",
            job3.to_str().unwrap(),
        ])
        .args(&s)
        .output()
        .unwrap();
    assert_ok(&o);
    assert!(read(&job3.join("array.sbatch")).contains("--array=0-1\n"));
    std::fs::remove_dir_all(&d).ok();
}

/// submit.sh submits the array, then the merge with `--dependency=afterok:<array job id>`
/// (checked with a stand-in `sbatch` that logs its arguments).
#[test]
fn submit_makes_the_merge_depend_on_the_array() {
    let d = tmpdir("slurm-submit");
    let job = d.join("job");
    let s = sweep("screen", &["--theta", "0:30:1", "--load-mn", "0.01"]);
    assert_ok(&slurm(
        &s,
        &["--shards", "2", "--out-dir", job.to_str().unwrap()],
    ));
    let fake = d.join("bin");
    std::fs::create_dir_all(&fake).unwrap();
    let log = d.join("sbatch.log");
    let sbatch = fake.join("sbatch");
    std::fs::write(
        &sbatch,
        format!(
            "#!/bin/sh\necho \"$@\" >> {log}\nn=$(wc -l < {log})\necho \"$((4000 + n));cluster1\"\n",
            log = log.display()
        ),
    )
    .unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&sbatch, std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = format!("{}:{}", fake.display(), std::env::var("PATH").unwrap());
    let o = Command::new("sh")
        .arg(job.join("submit.sh"))
        .env("PATH", path)
        .output()
        .unwrap();
    assert_ok(&o);
    let calls = read(&log);
    let calls: Vec<&str> = calls.lines().collect();
    assert_eq!(calls.len(), 2, "{calls:?}");
    assert_eq!(
        calls[0],
        format!("--parsable {}", job.join("array.sbatch").display())
    );
    assert_eq!(
        calls[1],
        format!(
            "--parsable --dependency=afterok:4001 {}",
            job.join("merge.sbatch").display()
        )
    );
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("array job 4001") && said.contains("merge job 4002"),
        "{said}"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn tasks_run_locally_then_merge_give_the_unsharded_bytes() {
    let d = tmpdir("slurm-local");
    for (name, s, n) in [
        (
            "screen",
            sweep("screen", &["--theta", "0:30:1", "--load-mn", "0.01,0.02"]),
            3,
        ),
        (
            "landscape",
            sweep("landscape", &["--grid", "6", "--theta", "2"]),
            4,
        ),
    ] {
        let reference = d.join(format!("{name}.ref.csv"));
        assert_ok(
            &bin()
                .args(&s)
                .arg("--out")
                .arg(&reference)
                .output()
                .unwrap(),
        );
        let job = d.join(format!("job-{name}"));
        assert_ok(&slurm(
            &s,
            &[
                "--shards",
                &n.to_string(),
                "--out-dir",
                job.to_str().unwrap(),
                "--threads",
                "1",
            ],
        ));
        run_locally(&job, n);
        let merged = job.join(format!("{name}.csv"));
        assert_eq!(
            std::fs::read(&merged).unwrap(),
            std::fs::read(&reference).unwrap(),
            "{name}: merged Slurm shards differ from the unsharded run"
        );
        for i in 0..n {
            assert!(job.join(format!("shards/{name}.{i}-of-{n}.csv")).is_file());
        }
        // A task run again (a requeue) finds its output complete and its partial gone: it
        // recomputes its shard into the same bytes.
        let shard0 = job.join(format!("shards/{name}.0-of-{n}.csv"));
        let before = std::fs::read(&shard0).unwrap();
        run_locally(&job, 1);
        assert_eq!(std::fs::read(&shard0).unwrap(), before);
    }
    std::fs::remove_dir_all(&d).ok();
}

/// Bad flags are refused before anything is written, with the error running the sweep gives.
#[test]
fn bad_flags_are_refused_before_writing() {
    let d = tmpdir("slurm-bad");
    let job = d.join("job");
    let j = job.to_str().unwrap();
    let refused = |args: &[&str], words: &[&str]| {
        let o = bin().arg("slurm").args(args).output().unwrap();
        assert!(!o.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        for w in words {
            assert!(err.contains(w), "{args:?}: `{err}` lacks `{w}`");
        }
        assert!(!job.exists(), "{args:?} wrote {}", job.display());
        err
    };
    // the sweep's own checks, with the same message as running it
    let err = refused(
        &["screen", "--load-mn", "0", "--shards", "2", "--out-dir", j],
        &["--load-mn"],
    );
    let direct = bin().args(["screen", "--load-mn", "0"]).output().unwrap();
    assert_eq!(err, String::from_utf8_lossy(&direct.stderr));
    refused(
        &[
            "screen",
            "--slider-radius-um",
            "-5",
            "--shards",
            "2",
            "--out-dir",
            j,
        ],
        &["slider.radius_um"],
    );
    refused(
        &["screen", "--bogus", "--shards", "2", "--out-dir", j],
        &["--bogus"],
    );
    refused(
        &["landscape", "--grid", "1", "--shards", "2", "--out-dir", j],
        &["--grid"],
    );
    // slurm's own flags
    let s = ["screen", "--theta", "0:30:1", "--load-mn", "0.01"];
    refused(
        &[&s[..], &["--shards", "0", "--out-dir", j]].concat(),
        &["--shards"],
    );
    refused(
        &[&s[..], &["--shards", "-1", "--out-dir", j]].concat(),
        &["--shards"],
    );
    refused(
        &[&s[..], &["--shards", "32", "--out-dir", j]].concat(),
        &["--shards", "31 θ"],
    );
    refused(&[&s[..], &["--out-dir", j]].concat(), &["--shards"]);
    refused(&[&s[..], &["--shards", "2"]].concat(), &["--out-dir"]);
    refused(
        &[
            &s[..],
            &["--shards", "2", "--out-dir", j, "--cpus-per-task", "0"],
        ]
        .concat(),
        &["--cpus-per-task"],
    );
    refused(
        &[&s[..], &["--shards", "2", "--out-dir", j, "--time", "1h"]].concat(),
        &["--time"],
    );
    refused(
        &[
            &s[..],
            &["--shards", "2", "--out-dir", j, "--partition", "a b"],
        ]
        .concat(),
        &["--partition"],
    );
    refused(
        &[&s[..], &["--shards", "2", "--shards", "3", "--out-dir", j]].concat(),
        &["--shards", "multiple times"],
    );
    refused(
        &[&s[..], &["--shard", "0/2", "--shards", "2", "--out-dir", j]].concat(),
        &["--shard", "--shards N"],
    );
    refused(
        &["slide", "--shards", "2", "--out-dir", j],
        &["runs sweeps: screen", "(got `slide`)"],
    );
    std::fs::remove_dir_all(&d).ok();
}
