//! `superlube slurm <command> [its flags] --shards N --out-dir DIR`: checks the sweep command line
//! exactly as running it would, then writes the Slurm scripts of [`crate::runs::slurm`].

use super::sweep_commands::SweepCommands;
use super::sweep_plan::SweepPlan;
use crate::runs::slurm::{format_time, job, shard_file, valid_time, SlurmJob, SlurmParams};
use crate::runs::{
    meta::Inputs, output::check_outputs, output::Outputs, progress::Progress, progress::Reporter,
};
use anyhow::{bail, Context, Result};
use clap::{CommandFactory, Parser};
use std::path::{Path, PathBuf};

/// Options of `superlube slurm` (they may also follow the sweep command's flags).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct Opts {
    /// Number of shards = Slurm array tasks (1 ≤ N ≤ the sweep's items); task i computes
    /// shard i/N.
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    shards: Option<String>,
    /// Job directory: the scripts (array.sbatch, merge.sbatch, submit.sh), shards/ (the shard
    /// outputs), logs/ (Slurm's output files) and the merged CSV DIR/<command>.csv.
    #[arg(long = "out-dir", alias = "out", value_name = "DIR")]
    out: Option<PathBuf>,
    /// CPUs per array task (`#SBATCH --cpus-per-task`), also RAYON_NUM_THREADS of the task
    /// [default: 4].
    #[arg(
        long = "cpus-per-task",
        alias = "threads",
        value_name = "T",
        allow_hyphen_values = true
    )]
    threads: Option<String>,
    /// Time limit per array task in Slurm syntax (`MM`, `HH:MM:SS`, `D-HH:MM:SS`)
    /// [default: 4 × the estimated time of one shard, at least 30 minutes].
    #[arg(long, value_name = "TIME")]
    time: Option<String>,
    /// Time limit of the merge job in Slurm syntax [default: 01:00:00].
    #[arg(long = "merge-time", value_name = "TIME")]
    merge_time: Option<String>,
    /// Slurm partition of both jobs (`#SBATCH --partition`) [default: the cluster's default].
    #[arg(long, value_name = "NAME")]
    partition: Option<String>,
    /// Slurm account to charge (`#SBATCH --account`) [default: your default account].
    #[arg(long, value_name = "NAME")]
    account: Option<String>,
    /// Memory per array task in Slurm syntax, e.g. 4G (`#SBATCH --mem`) [default: the
    /// cluster's default].
    #[arg(long, value_name = "SIZE")]
    mem: Option<String>,
    /// Job name (`#SBATCH --job-name`; the merge job adds `-merge`) [default:
    /// superlube-<command>].
    #[arg(long = "job-name", value_name = "NAME")]
    job_name: Option<String>,
}

/// Options of `superlube slurm`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    opts: Opts,
    /// The sweep command and its flags, as you would run it (`screen`, `landscape`, `friction` or
    /// `corrugation`; without --out, --shard, --resume, which the scripts set), e.g.
    /// `screen --pattern tri-tri --theta-deg 0:30:0.1 --load-mn 1.4`.
    #[arg(
        value_name = "COMMAND",
        trailing_var_arg = true,
        allow_hyphen_values = true,
        required = true,
        num_args = 1..
    )]
    command: Vec<String>,
}

/// The options alone, to parse those that follow the sweep command.
#[derive(Parser, Debug)]
#[command(name = "superlube slurm", no_binary_name = true)]
struct OptsOnly {
    #[command(flatten)]
    opts: Opts,
}

/// Splits `words` into `superlube slurm`'s own options (names from [`Opts`]) and the rest.
fn split(words: &[String]) -> (Vec<String>, Vec<String>) {
    let longs: Vec<String> = OptsOnly::command()
        .get_arguments()
        .flat_map(|a| {
            a.get_long()
                .into_iter()
                .chain(a.get_all_aliases().unwrap_or_default())
                .map(|l| format!("--{l}"))
                .collect::<Vec<_>>()
        })
        .collect();
    let (mut own, mut rest) = (Vec::new(), Vec::new());
    let mut it = words.iter();
    while let Some(w) = it.next() {
        let name = w.split_once('=').map_or(w.as_str(), |(n, _)| n);
        if longs.iter().any(|l| l == name) {
            own.push(w.clone());
            if !w.contains('=') {
                if let Some(v) = it.next() {
                    own.push(v.clone());
                }
            }
        } else {
            rest.push(w.clone());
        }
    }
    (own, rest)
}

/// `a` and `b` (options before and after the command) into one; an option given twice is an
/// error naming it.
fn combine(a: Opts, b: Opts) -> Result<Opts> {
    fn one<T>(x: Option<T>, y: Option<T>, flag: &str) -> Result<Option<T>> {
        match (x, y) {
            (Some(_), Some(_)) => bail!("`{flag}` is given twice"),
            (x, y) => Ok(x.or(y)),
        }
    }
    Ok(Opts {
        shards: one(a.shards, b.shards, "--shards")?,
        out: one(a.out, b.out, "--out-dir")?,
        threads: one(a.threads, b.threads, "--cpus-per-task")?,
        time: one(a.time, b.time, "--time")?,
        merge_time: one(a.merge_time, b.merge_time, "--merge-time")?,
        partition: one(a.partition, b.partition, "--partition")?,
        account: one(a.account, b.account, "--account")?,
        mem: one(a.mem, b.mem, "--mem")?,
        job_name: one(a.job_name, b.job_name, "--job-name")?,
    })
}

/// A whole number ≥ 1 for `flag`.
fn count(text: Option<&str>, flag: &str, default: usize) -> Result<usize> {
    let Some(t) = text else { return Ok(default) };
    match t.trim().parse::<usize>() {
        Ok(0) => bail!("`{flag}`: 0 — give a whole number ≥ 1"),
        Ok(n) => Ok(n),
        Err(_) => bail!("`{flag}`: `{t}` must be a whole number ≥ 1"),
    }
}

/// A Slurm word for `flag` (no blanks, quotes or control characters: it goes on an `#SBATCH`
/// line).
fn word(v: Option<String>, flag: &str) -> Result<Option<String>> {
    if let Some(s) = &v {
        if s.is_empty()
            || s.chars()
                .any(|c| c.is_whitespace() || c.is_control() || "'\"\\$`;&|<>".contains(c))
        {
            bail!("`{flag}`: `{s}` must be one word without blanks, quotes or shell characters");
        }
    }
    Ok(v)
}

/// The absolute, lexically normalised form of `p`.
fn absolute(p: &Path) -> Result<PathBuf> {
    let abs = std::env::current_dir()
        .context("the current directory")?
        .join(p);
    let mut out = PathBuf::new();
    for c in abs.components() {
        match c {
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir => {
                out.pop();
            }
            c => out.push(c),
        }
    }
    Ok(out)
}

/// `superlube slurm`'s own options, checked: the job directory (absolute), the shard and CPU
/// counts and the `#SBATCH` words.
struct Checked {
    /// The options as given (the time limits are read from them).
    o: Opts,
    /// The job directory, absolute.
    dir: PathBuf,
    /// Array tasks.
    shards: usize,
    /// CPUs per task.
    threads: usize,
    partition: Option<String>,
    account: Option<String>,
    mem: Option<String>,
    job_name: Option<String>,
}

/// Parses `own` (the options after the sweep command) and checks every option of `superlube
/// slurm` (`before`: those before it), and that `rest` (the sweep command line) leaves
/// `--shard` and `--resume` to the scripts.
fn checked_options(before: Opts, own: &[String], rest: &[String]) -> Result<Checked> {
    let after = OptsOnly::try_parse_from(own).map_err(super::checks::clap_error)?;
    let o = combine(before, after.opts)?;
    let Some(out) = o.out.clone() else {
        bail!("`--out-dir DIR` is required: the job directory for the scripts, shards, logs and the merged CSV");
    };
    let Some(shards_text) = o.shards.as_deref() else {
        bail!("`--shards N` is required: the number of array tasks (shards)");
    };
    let shards = count(Some(shards_text), "--shards", 1)?;
    let threads = count(o.threads.as_deref(), "--cpus-per-task", 4)?;
    for (flag, v) in [("--time", &o.time), ("--merge-time", &o.merge_time)] {
        if let Some(t) = v {
            if !valid_time(t) {
                bail!("`{flag}`: `{t}` is not a Slurm time (MM, HH:MM:SS or D-HH:MM:SS)");
            }
        }
    }
    let partition = word(o.partition.clone(), "--partition")?;
    let account = word(o.account.clone(), "--account")?;
    let mem = word(o.mem.clone(), "--mem")?;
    let job_name = word(o.job_name.clone(), "--job-name")?;
    for flag in ["--shard", "--resume"] {
        if rest
            .iter()
            .any(|w| w == flag || w.starts_with(&format!("{flag}=")))
        {
            bail!("`{flag}` is set by the scripts (task i runs --shard i/N --resume); give `--shards N` instead");
        }
    }
    Ok(Checked {
        dir: job_dir(&out)?,
        o,
        shards,
        threads,
        partition,
        account,
        mem,
        job_name,
    })
}

/// The job directory `out`, absolute: an error when it is a file or has characters the
/// `#SBATCH --output` lines cannot take.
fn job_dir(out: &Path) -> Result<PathBuf> {
    let dir = absolute(out)?;
    if dir.exists() && !dir.is_dir() {
        bail!(
            "`--out-dir`: {} exists and is not a directory",
            dir.display()
        );
    }
    if dir
        .to_string_lossy()
        .chars()
        .any(|c| c.is_whitespace() || c.is_control() || c == '%')
    {
        bail!(
            "`--out-dir`: {} has blanks or `%`, which Slurm's #SBATCH --output lines cannot take; choose another directory",
            dir.display()
        );
    }
    Ok(dir)
}

/// Checks the sweep command line `rest` as running it would: whole, then cut into `shards`
/// (enough items), then task 0's exact command line. The command's name and task 0's plan.
fn check_tasks(
    sweeps: &SweepCommands,
    rest: &[String],
    dir: &Path,
    shards: usize,
) -> Result<(&'static str, SweepPlan)> {
    let command = rest.first().cloned().unwrap_or_default();
    if !sweeps.names.contains(&command.as_str()) {
        bail!(
            "`superlube slurm` runs sweeps: {} (got `{command}`)",
            sweeps.names.join(", ")
        );
    }
    // 1. The sweep command as the user gave it, on its own (the same errors as running it; the
    //    size guard is left to step 2: each task is held to it for its own shard).
    let mut words = rest.to_vec();
    words.extend([
        "--out".into(),
        shard_file(dir, &command, 0, 1).to_string_lossy().into(),
    ]);
    if !rest.iter().any(|w| w == "--force") {
        words.push("--force".into());
    }
    let (name, whole) = (sweeps.check)(&words)?;
    // 2. Enough items for the shards, then task 0's exact command line.
    whole.sweep.shard(
        crate::runs::shard::Shard {
            index: 0,
            count: shards,
        },
        "--shards",
    )?;
    let mut task0 = rest.to_vec();
    task0.extend([
        "--shard".into(),
        format!("0/{shards}"),
        "--resume".into(),
        "--out".into(),
        shard_file(dir, &command, 0, shards)
            .to_string_lossy()
            .into(),
    ]);
    let (_, part) = (sweeps.check)(&task0)?;
    Ok((name, part))
}

/// Writes the job's scripts `files` (array, merge, submit) with their sidecars, and makes its
/// `shards/` and `logs/` folders.
fn write_job(p: &SlurmParams, files: &[PathBuf; 3]) -> Result<SlurmJob> {
    let j = job(p);
    for sub in ["shards", "logs"] {
        std::fs::create_dir_all(p.dir.join(sub))
            .with_context(|| format!("creating {}", p.dir.join(sub).display()))?;
    }
    let mut outs = Outputs::new(
        Inputs {
            workflow: format!("slurm/{}", p.command),
            scene: None,
            params: serde_json::json!({
                "command": std::iter::once(p.command.clone()).chain(p.args.iter().cloned()).collect::<Vec<_>>(),
                "shards": p.shards,
                "threads": p.threads,
                "time": p.time,
                "merge_time": p.merge_time,
                "partition": p.partition,
                "account": p.account,
                "mem": p.mem,
                "job_name": p.job_name,
            }),
        },
        vec![],
    );
    for (path, text) in files.iter().zip([&j.array, &j.merge, &j.submit]) {
        outs.write("--out-dir", Some(path), Ok(text.clone().into_bytes()), None);
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let _ = std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o755));
        }
    }
    outs.finish()?;
    Ok(j)
}

/// Runs `superlube slurm`.
pub fn run(a: Args, sweeps: &SweepCommands) -> Result<()> {
    let (own, rest) = split(&a.command);
    let c = checked_options(a.opts, &own, &rest)?;
    let dir = c.dir.clone();
    let (name, part) = check_tasks(sweeps, &rest, &dir, c.shards)?;
    let files = ["array.sbatch", "merge.sbatch", "submit.sh"].map(|f| dir.join(f));
    check_outputs(&[
        ("--out-dir", Some(&files[0])),
        ("--out-dir (merge.sbatch)", Some(&files[1])),
        ("--out-dir (submit.sh)", Some(&files[2])),
    ])?;
    let (shards, threads) = (c.shards, c.threads);
    let est = part.estimate.seconds_on(threads);
    let time =
        c.o.time
            .clone()
            .unwrap_or_else(|| format_time((4.0 * est).max(1800.0)));
    let p = SlurmParams {
        command: name.to_string(),
        args: rest[1..].to_vec(),
        shards,
        threads,
        time: time.clone(),
        merge_time: c.o.merge_time.clone().unwrap_or_else(|| "01:00:00".into()),
        partition: c.partition,
        account: c.account,
        mem: c.mem,
        job_name: c.job_name.unwrap_or_else(|| format!("superlube-{name}")),
        dir: dir.clone(),
        workdir: std::env::current_dir()?,
        binary: std::env::current_exe()
            .and_then(|p| p.canonicalize())
            .context("locating the superlube binary")?,
    };
    let j = write_job(&p, &files)?;
    let rep = Reporter::stderr();
    rep.note(&format!(
        "wrote {} ({} array tasks × {} CPUs, time limit {} per task; estimated {:.0} s per shard), {} and {}\n\
         submit with:  sh {}\n\
         shards go to {}/, the merged result to {}",
        files[0].display(),
        shards,
        threads,
        time,
        est,
        files[1].display(),
        files[2].display(),
        files[2].display(),
        dir.join("shards").display(),
        j.merged.display()
    ));
    Ok(())
}
