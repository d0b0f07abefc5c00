//! Slurm job scripts for a sharded sweep (`superlube slurm`): an array job with one shard per
//! task, a merge job that runs after every task succeeded, and a `submit.sh` that submits both.
//!
//! Files in the job directory `DIR` (absolute paths inside the scripts):
//! - `array.sbatch`: `#SBATCH --array=0-(N-1)`, `--cpus-per-task=T` (and
//!   `RAYON_NUM_THREADS=T`), job name, time, optional partition/account/memory, log files
//!   `DIR/logs/%x-%A_%a.out`; task `i` runs the sweep command with
//!   `--shard i/N --resume --out DIR/shards/<command>.<i>-of-<N>.csv` (a requeued or re-run task
//!   continues its partial output instead of starting over);
//! - `merge.sbatch`: `superlube merge <the N shard files> --out DIR/<command>.csv`;
//! - `submit.sh`: `sbatch --parsable array.sbatch`, then
//!   `sbatch --dependency=afterok:<array job id> merge.sbatch`.
//!
//! The scripts `cd` to the directory `superlube slurm` ran in, so relative paths in the sweep's
//! flags (`--scene FILE`) mean what they meant there; the binary is the one that wrote the
//! scripts, unless `SUPERLUBE` is set in the job's environment.

use std::path::{Path, PathBuf};

/// What the scripts run and ask Slurm for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SlurmParams {
    /// The sweep command (`screen`, `landscape`, `corrugation`).
    pub command: String,
    /// Its flags, without `--out`, `--shard`, `--resume` (the scripts add them).
    pub args: Vec<String>,
    /// Array tasks = shards (≥ 1).
    pub shards: usize,
    /// CPUs per task and `RAYON_NUM_THREADS`.
    pub threads: usize,
    /// Time limit per array task (Slurm syntax, e.g. `02:00:00`).
    pub time: String,
    /// Time limit of the merge job.
    pub merge_time: String,
    /// `--partition`, if any.
    pub partition: Option<String>,
    /// `--account`, if any.
    pub account: Option<String>,
    /// `--mem` per task, if any (Slurm syntax, e.g. `4G`).
    pub mem: Option<String>,
    /// Job name (the merge job: `<name>-merge`).
    pub job_name: String,
    /// The job directory (absolute).
    pub dir: PathBuf,
    /// The working directory of the jobs (absolute): where `superlube slurm` ran.
    pub workdir: PathBuf,
    /// The superlube binary (absolute).
    pub binary: PathBuf,
}

/// The generated files.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SlurmJob {
    /// `array.sbatch` text.
    pub array: String,
    /// `merge.sbatch` text.
    pub merge: String,
    /// `submit.sh` text.
    pub submit: String,
    /// The shard outputs, in shard order.
    pub shard_files: Vec<PathBuf>,
    /// The merged output.
    pub merged: PathBuf,
}

/// `DIR/shards/<command>.<i>-of-<n>.csv`, `i` zero-padded to the width of `n − 1`.
pub fn shard_file(dir: &Path, command: &str, i: usize, n: usize) -> PathBuf {
    let w = (n.max(2) - 1).to_string().len();
    dir.join("shards")
        .join(format!("{command}.{i:0w$}-of-{n}.csv"))
}

/// `DIR/<command>.csv`.
pub fn merged_file(dir: &Path, command: &str) -> PathBuf {
    dir.join(format!("{command}.csv"))
}

/// A word for `sh`/`bash`: as is when it has only safe characters, else single-quoted.
pub fn sh_quote(s: &str) -> String {
    let safe = !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "_./:=,+-@%".contains(c));
    if safe {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', r"'\''"))
    }
}

fn path_word(p: &Path) -> String {
    sh_quote(&p.to_string_lossy())
}

fn sbatch_common(p: &SlurmParams, name: &str) -> String {
    let mut s = format!("#SBATCH --job-name={name}\n#SBATCH --ntasks=1\n");
    for (k, v) in [("partition", &p.partition), ("account", &p.account)] {
        if let Some(v) = v {
            s += &format!("#SBATCH --{k}={v}\n");
        }
    }
    s
}

fn shard_list(files: &[PathBuf]) -> String {
    let mut s = String::from("shards=(\n");
    for f in files {
        s += &format!("  {}\n", path_word(f));
    }
    s + ")\n"
}

fn binary_line(p: &SlurmParams) -> String {
    format!(
        "SUPERLUBE=\"${{SUPERLUBE:-{}}}\"\n",
        p.binary.to_string_lossy().replace('"', "\\\"")
    )
}

/// The scripts of `p` (see the module docs).
pub fn job(p: &SlurmParams) -> SlurmJob {
    let n = p.shards;
    let files: Vec<PathBuf> = (0..n)
        .map(|i| shard_file(&p.dir, &p.command, i, n))
        .collect();
    let merged = merged_file(&p.dir, &p.command);
    let logs = p.dir.join("logs");
    let generated = format!(
        "# Written by `superlube slurm` (superlube {}). Submit with: sh {}\n",
        super::meta::VERSION,
        path_word(&p.dir.join("submit.sh"))
    );
    let mut sweep_words = vec![sh_quote(&p.command)];
    sweep_words.extend(p.args.iter().map(|a| sh_quote(a)));
    let sweep = sweep_words.join(" ");

    let mut array = String::from("#!/bin/bash\n");
    array += &sbatch_common(p, &p.job_name);
    array += &format!(
        "#SBATCH --array=0-{}\n#SBATCH --cpus-per-task={}\n#SBATCH --time={}\n",
        n - 1,
        p.threads,
        p.time
    );
    if let Some(m) = &p.mem {
        array += &format!("#SBATCH --mem={m}\n");
    }
    array += &format!("#SBATCH --output={}/%x-%A_%a.out\n", logs.to_string_lossy());
    array += &generated;
    array += &format!(
        "# Array task i computes shard i/{n} of `superlube {}`;\n\
         # --resume continues the partial output of a requeued or re-run task.\n",
        sweep.replace(['\n', '\r'], " ")
    );
    array += "set -euo pipefail\n";
    array += &format!("cd {}\n", path_word(&p.workdir));
    array += &format!("export RAYON_NUM_THREADS={}\n", p.threads);
    array += &binary_line(p);
    array += &shard_list(&files);
    array += "i=\"${SLURM_ARRAY_TASK_ID:?run this as a Slurm array task (or set SLURM_ARRAY_TASK_ID)}\"\n";
    array += &format!(
        "exec \"$SUPERLUBE\" {sweep} --shard \"$i/{n}\" --resume --out \"${{shards[$i]}}\"\n"
    );

    let mut merge = String::from("#!/bin/bash\n");
    merge += &sbatch_common(p, &format!("{}-merge", p.job_name));
    merge += &format!(
        "#SBATCH --cpus-per-task=1\n#SBATCH --time={}\n#SBATCH --output={}/%x-%j.out\n",
        p.merge_time,
        logs.to_string_lossy()
    );
    merge += &generated;
    merge += &format!(
        "# Merges the {n} shards into the output of the unsharded run (checked: same sweep,\n\
         # every shard once, each complete); submitted with --dependency=afterok:<array job>.\n"
    );
    merge += "set -euo pipefail\n";
    merge += &format!("cd {}\n", path_word(&p.workdir));
    merge += &binary_line(p);
    merge += &shard_list(&files);
    merge += &format!(
        "exec \"$SUPERLUBE\" merge \"${{shards[@]}}\" --out {}\n",
        path_word(&merged)
    );

    let dir = path_word(&p.dir);
    let submit = format!(
        "#!/bin/sh\n\
         {generated}\
         # Submits the array job ({n} tasks), then the merge job, which starts only when every\n\
         # array task succeeded (--dependency=afterok).\n\
         set -eu\n\
         cd {workdir}\n\
         array=$(sbatch --parsable {dir}/array.sbatch)\n\
         array=${{array%%;*}}\n\
         merge=$(sbatch --parsable --dependency=afterok:\"$array\" {dir}/merge.sbatch)\n\
         merge=${{merge%%;*}}\n\
         echo \"submitted array job $array ({n} tasks) and merge job $merge (runs after all succeed); result: {merged}\"\n",
        workdir = path_word(&p.workdir),
        merged = merged.to_string_lossy().replace('"', "\\\"")
    );
    SlurmJob {
        array,
        merge,
        submit,
        shard_files: files,
        merged,
    }
}

/// Whether `t` is a Slurm time limit: `M`, `M:S`, `H:M:S`, `D-H`, `D-H:M`, `D-H:M:S`.
pub fn valid_time(t: &str) -> bool {
    let nums = |s: &str, max_parts: usize| {
        let parts: Vec<&str> = s.split(':').collect();
        parts.len() <= max_parts
            && parts
                .iter()
                .all(|p| !p.is_empty() && p.chars().all(|c| c.is_ascii_digit()))
    };
    match t.split_once('-') {
        Some((d, rest)) => !d.is_empty() && d.chars().all(|c| c.is_ascii_digit()) && nums(rest, 3),
        None => nums(t, 3),
    }
}

/// `D-HH:MM:SS` (or `HH:MM:SS`) of `seconds`, rounded up to whole minutes.
pub fn format_time(seconds: f64) -> String {
    let m = (seconds / 60.0).ceil().max(1.0) as u64;
    let (d, h, mm) = (m / 1440, (m / 60) % 24, m % 60);
    if d > 0 {
        format!("{d}-{h:02}:{mm:02}:00")
    } else {
        format!("{h:02}:{mm:02}:00")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoting_and_times() {
        assert_eq!(sh_quote("0:30:0.1"), "0:30:0.1");
        assert_eq!(sh_quote("a b"), "'a b'");
        assert_eq!(sh_quote("it's"), r"'it'\''s'");
        assert_eq!(sh_quote(""), "''");
        for ok in ["30", "1:00", "02:00:00", "1-0", "1-12:00", "2-00:00:00"] {
            assert!(valid_time(ok), "{ok}");
        }
        for bad in ["", "1h", "-1", "1:2:3:4", "a-1", "1 day"] {
            assert!(!valid_time(bad), "{bad}");
        }
        assert_eq!(format_time(1.0), "00:01:00");
        assert_eq!(format_time(3600.0 * 25.0 + 1.0), "1-01:01:00");
        assert_eq!(
            shard_file(Path::new("/j"), "screen", 3, 12),
            PathBuf::from("/j/shards/screen.03-of-12.csv")
        );
        assert_eq!(
            shard_file(Path::new("/j"), "screen", 0, 1),
            PathBuf::from("/j/shards/screen.0-of-1.csv")
        );
    }
}
