//! Output files of a run: checked before the work starts, written at the end (or streamed), each
//! with its sidecar ([`super::meta`]), and never one lost because another failed.
//!
//! 1. [`check_outputs`] before any work: every path named by a flag must be writable — its
//!    directory exists (or can be created under an existing, writable directory), the path is
//!    not a directory, no two flags name the same file. All problems are reported at once, each
//!    with its flag.
//! 2. [`Outputs`] during and after the run: [`Outputs::stream_sweep`] for a sweep's rows (with
//!    `--shard` and `--resume`, see [`SweepRun`]), [`Outputs::stream_csv`] /
//!    [`Outputs::commit_csv`] for other streamed rows, [`Outputs::write`] / [`Outputs::attempt`]
//!    for files written in one piece. A failed write is recorded and the others are still written; [`Outputs::finish`]
//!    then reports every failure and makes the command exit non-zero.

use super::meta::{sidecar_path, Inputs, RunMeta};
use super::progress::Progress;
use super::resume;
use super::shard::Shard;
use super::sink::{partial_path, CsvSink, StreamFile};
use super::sweep::{ShardInfo, Sweep};
use anyhow::{bail, Result};
use std::ops::Range;

/// The role recorded in the sidecar of a DEM run's time series that no flag names (a batch
/// run's `slide.csv`): the flag that names it in a single run, `slide --out`.
pub const SERIES_ROLE: &str = "--out";
/// The role of a DEM run's JSON summary that no flag names (a batch run's `slide.json`):
/// `slide --json`.
pub const SUMMARY_ROLE: &str = "--json";
use std::path::{Path, PathBuf};

/// How one process runs a sweep: the sweep, its shard (`--shard i/n`; `None` = the whole
/// sweep, unsharded) and whether it continues an interrupted run (`--resume`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SweepRun {
    /// The sweep's items.
    pub sweep: Sweep,
    /// The shard record (also written into the output's sidecar).
    pub shard: Option<ShardInfo>,
    /// Continue from `OUT.partial`.
    pub resume: bool,
}

impl SweepRun {
    /// The run of `shard` of `sweep` (`--shard` named in errors: more shards than items).
    pub fn new(sweep: Sweep, shard: Option<Shard>, resume: bool) -> Result<SweepRun> {
        let shard = match shard {
            Some(s) => Some(sweep.shard(s, "--shard")?),
            None => None,
        };
        Ok(SweepRun {
            sweep,
            shard,
            resume,
        })
    }

    /// The items this process is responsible for.
    pub fn range(&self) -> Range<usize> {
        self.shard
            .as_ref()
            .map_or(0..self.sweep.items, ShardInfo::range)
    }

    /// Rows of this process's output when complete.
    pub fn rows(&self) -> u64 {
        (self.range().len() as u64).saturating_mul(self.sweep.rows_per_item as u64)
    }

    /// Whether it runs the whole sweep in one go (no shard, nothing resumed): only then do the
    /// rows it computes cover the sweep.
    pub fn is_whole(&self) -> bool {
        self.shard.is_none()
    }
}

/// Checks that each `(flag, path)` with a path can be written (see the module docs). The error
/// lists every unwritable path with its flag.
pub fn check_outputs(outputs: &[(&str, Option<&Path>)]) -> Result<()> {
    let mut problems = Vec::new();
    let mut seen: Vec<(&str, PathBuf)> = Vec::new();
    for &(flag, path) in outputs {
        let Some(path) = path else { continue };
        let key = normalise(path);
        let device = std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir());
        if let Some((other, _)) = seen.iter().find(|(_, p)| *p == key && !device) {
            problems.push(format!(
                "`{flag}` and `{other}` both name {}",
                path.display()
            ));
            continue;
        }
        seen.push((flag, key));
        if let Err(why) = check_writable(path) {
            problems.push(format!("`{flag}`: cannot write {}: {why}", path.display()));
        }
    }
    if !problems.is_empty() {
        bail!(
            "{} (checked before starting; nothing was computed)",
            problems.join("; ")
        );
    }
    Ok(())
}

/// Whether `a` and `b` name the same file (lexically, after making them absolute; or the same
/// existing file).
pub fn same_file(a: &Path, b: &Path) -> bool {
    if normalise(a) == normalise(b) {
        return true;
    }
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

/// The path made absolute (lexically) for duplicate detection.
fn normalise(p: &Path) -> PathBuf {
    let abs = if p.is_absolute() {
        p.to_path_buf()
    } else {
        std::env::current_dir().unwrap_or_default().join(p)
    };
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
    out
}

/// Why `path` cannot be written, if it cannot.
fn check_writable(path: &Path) -> std::result::Result<(), String> {
    if path.as_os_str().is_empty() {
        return Err("empty path".into());
    }
    if let Ok(m) = std::fs::metadata(path) {
        if m.is_dir() {
            return Err("it is a directory; give a file name".into());
        }
        if !m.is_file() {
            // A device or FIFO is written in place.
            return std::fs::OpenOptions::new()
                .write(true)
                .open(path)
                .map(|_| ())
                .map_err(|e| e.to_string());
        }
    }
    // The nearest existing ancestor directory must accept a new file (the temp file and the
    // sidecar are created next to the output; missing directories are created below it).
    let mut dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    if dir.as_os_str().is_empty() {
        dir = PathBuf::from(".");
    }
    loop {
        match std::fs::metadata(&dir) {
            Ok(m) if m.is_dir() => break,
            Ok(_) => return Err(format!("{} is not a directory", dir.display())),
            Err(_) => match dir.parent() {
                Some(p) if !p.as_os_str().is_empty() => dir = p.to_path_buf(),
                _ => {
                    dir = PathBuf::from(".");
                    break;
                }
            },
        }
    }
    let probe = dir.join(format!(".superlube-write-check-{}", std::process::id()));
    match std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
    {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Ok(()),
        Err(e) => Err(format!("directory {} is not writable ({e})", dir.display())),
    }
}

/// Whether `path` is (or will be) a regular file, i.e. gets a sidecar.
fn is_regular_target(path: &Path) -> bool {
    std::fs::metadata(path).map(|m| m.is_file()).unwrap_or(true)
}

/// The output files of one run (see the module docs).
pub struct Outputs {
    inputs: Inputs,
    warnings: Vec<String>,
    failures: Vec<String>,
}

impl Outputs {
    /// Outputs of a run with `inputs`; `warnings` go into every sidecar.
    pub fn new(inputs: Inputs, warnings: Vec<String>) -> Outputs {
        Outputs {
            inputs,
            warnings,
            failures: Vec::new(),
        }
    }

    /// Replaces the inputs recorded in the following sidecars (a command that writes the
    /// outputs of several workflows, e.g. `figures`).
    pub fn set_inputs(&mut self, inputs: Inputs) {
        self.inputs = inputs;
    }

    /// The inputs recorded now.
    pub fn inputs(&self) -> &Inputs {
        &self.inputs
    }

    fn meta(&self, path: &Path, role: &str, rows: Option<u64>, complete: bool) -> RunMeta {
        let mut m = RunMeta::new(&self.inputs, &self.warnings, path, role);
        m.rows = rows;
        m.complete = complete;
        m
    }

    fn write_sidecar(&self, path: &Path, meta: &RunMeta) -> Result<()> {
        surrogate::atomic_file::write_atomic(&sidecar_path(path), meta.to_json().as_bytes())
            .map_err(|e| anyhow::anyhow!("writing {}: {e}", sidecar_path(path).display()))
    }

    /// Opens a streamed CSV for `path` (`None` = stdout): `path.partial` with its sidecar
    /// `path.partial.meta.json` (`complete: false`) until [`Outputs::commit_csv`].
    pub fn stream_csv(&self, role: &str, path: Option<&Path>) -> Result<CsvSink> {
        let stream = StreamFile::create(path)?;
        if let (Some(p), true) = (path, stream.is_regular_file()) {
            let partial = partial_path(p);
            self.write_sidecar(&partial, &self.meta(&partial, role, None, false))?;
        }
        Ok(CsvSink::new(stream))
    }

    /// Finishes a streamed CSV: renames the partial file into place and writes its sidecar. A
    /// failure is recorded (see [`Outputs::finish`]).
    pub fn commit_csv(&mut self, role: &str, path: Option<&Path>, sink: CsvSink) {
        let res = sink.commit().and_then(|rows| match path {
            Some(p) if is_regular_target(p) => {
                self.write_sidecar(p, &self.meta(p, role, Some(rows), true))?;
                let _ = std::fs::remove_file(sidecar_path(&partial_path(p)));
                Ok(())
            }
            _ => Ok(()),
        });
        if let Err(e) = res {
            self.fail(role, path, e);
        }
    }

    /// Streams a CSV for `path` (`None` = stdout) through `run`: [`Outputs::stream_csv`], then
    /// [`Outputs::commit_csv`] when `run` succeeds, or [`Outputs::abandon_csv`] when it fails
    /// (its error is returned).
    pub fn stream<T>(
        &mut self,
        role: &str,
        path: Option<&Path>,
        run: impl FnOnce(&mut CsvSink) -> Result<T>,
    ) -> Result<T> {
        let mut sink = self.stream_csv(role, path)?;
        match run(&mut sink) {
            Ok(v) => {
                self.commit_csv(role, path, sink);
                Ok(v)
            }
            Err(e) => {
                self.abandon_csv(path, sink);
                Err(e)
            }
        }
    }

    /// Streams the rows of `run` into `path` (`None` = stdout): opens `path.partial` — fresh, or,
    /// with `run.resume`, the checked partial file of an interrupted run ([`resume::inspect`]),
    /// cut to its complete items — writes its sidecar (with the shard), calls
    /// `work(items, sink)` on the items still to compute (not at all when none are left) and
    /// commits, or abandons the partial file when `work` fails (its error is returned).
    /// `Ok(None)`: nothing was left to compute.
    pub fn stream_sweep<T>(
        &mut self,
        role: &str,
        path: Option<&Path>,
        run: &SweepRun,
        progress: &dyn Progress,
        work: impl FnOnce(Range<usize>, &mut CsvSink) -> Result<T>,
    ) -> Result<Option<T>> {
        let range = run.range();
        let shard = run.shard.as_ref();
        let regular = path.is_some_and(is_regular_target);
        let kept = match (run.resume, path) {
            (true, Some(p)) if regular => {
                resume::inspect(p, &self.inputs, shard, run.sweep.rows_per_item, range.len())?
            }
            (true, _) => {
                bail!("`--resume` needs `--out FILE` (the file whose partial output it continues)")
            }
            (false, _) => None,
        };
        let (mut sink, done) = match (kept, path) {
            (Some(k), Some(p)) if k.header => {
                progress.note(&k.describe(&partial_path(p), run.sweep.unit, range.len()));
                (
                    CsvSink::resumed(StreamFile::resume(p, k.bytes)?, k.rows),
                    k.items,
                )
            }
            (kept, _) => {
                if let (None, Some(p)) = (kept, path) {
                    if regular && partial_path(p).exists() {
                        progress.note(&format!(
                            "note: replacing {} left by an interrupted run (pass --resume to continue it instead)",
                            partial_path(p).display()
                        ));
                    }
                } else if let (Some(_), Some(p)) = (kept, path) {
                    progress.note(&format!(
                        "resuming {}: no complete row yet; starting from the beginning",
                        partial_path(p).display()
                    ));
                }
                (CsvSink::new(StreamFile::create(path)?), 0)
            }
        };
        if let (Some(p), true) = (path, regular) {
            let partial = partial_path(p);
            let mut m = self.meta(&partial, role, None, false);
            m.shard = run.shard.clone();
            self.write_sidecar(&partial, &m)?;
        }
        let todo = range.start + done..range.end;
        let result = if todo.is_empty() {
            Ok(None)
        } else {
            work(todo, &mut sink).map(Some)
        };
        match result {
            Ok(v) => {
                let res = sink.commit().and_then(|rows| match path {
                    Some(p) if regular => {
                        let mut m = self.meta(p, role, Some(rows), true);
                        m.shard = run.shard.clone();
                        self.write_sidecar(p, &m)?;
                        let _ = std::fs::remove_file(sidecar_path(&partial_path(p)));
                        Ok(())
                    }
                    _ => Ok(()),
                });
                if let Err(e) = res {
                    self.fail(role, path, e);
                }
                Ok(v)
            }
            Err(e) => {
                self.abandon_csv(path, sink);
                Err(e)
            }
        }
    }

    /// Gives up a streamed CSV after a failed run: a partial file without rows (and its
    /// sidecar) is removed; one with rows is kept for a later resume.
    pub fn abandon_csv(&self, path: Option<&Path>, sink: CsvSink) {
        let rows = sink.rows();
        drop(sink);
        if let (Some(p), 0) = (path, rows) {
            let partial = partial_path(p);
            let _ = std::fs::remove_file(sidecar_path(&partial));
            let _ = std::fs::remove_file(partial);
        }
    }

    /// Writes `bytes` to `path` atomically (`None` = stdout) with its sidecar; `rows` = data
    /// rows of a CSV. A failure (also of producing `bytes`) is recorded and the run goes on.
    pub fn write(
        &mut self,
        role: &str,
        path: Option<&Path>,
        bytes: Result<Vec<u8>>,
        rows: Option<u64>,
    ) {
        let res = bytes.and_then(|b| match path {
            Some(p) => surrogate::atomic_file::write_atomic(p, &b)
                .map_err(|e| anyhow::anyhow!("writing {}: {e}", p.display())),
            None => {
                use std::io::Write;
                let mut out = std::io::stdout().lock();
                out.write_all(&b)?;
                out.flush()?;
                Ok(())
            }
        });
        match (res, path) {
            (Ok(()), Some(p)) => self.sidecar(role, p, rows),
            (Ok(()), None) => {}
            (Err(e), _) => self.fail(role, path, e),
        }
    }

    /// Runs `write` (which writes `path` itself, e.g. a plot) and adds the sidecar; a failure is
    /// recorded and the run goes on.
    pub fn attempt(&mut self, role: &str, path: &Path, write: impl FnOnce() -> Result<()>) {
        match write() {
            Ok(()) => self.sidecar(role, path, None),
            Err(e) => self.fail(role, Some(path), e),
        }
    }

    /// Writes the sidecar of a file that was written by other means (regular files only).
    pub fn sidecar(&mut self, role: &str, path: &Path, rows: Option<u64>) {
        if is_regular_target(path) {
            if let Err(e) = self.write_sidecar(path, &self.meta(path, role, rows, true)) {
                self.fail(role, Some(path), e);
            }
        }
    }

    /// Writes the sidecar of `path` (written by other means) after `edit` changed it (e.g. a
    /// merge recording `merged_from`); a failure is recorded.
    pub fn sidecar_with(
        &mut self,
        role: &str,
        path: &Path,
        rows: Option<u64>,
        edit: impl FnOnce(&mut RunMeta),
    ) {
        if is_regular_target(path) {
            let mut m = self.meta(path, role, rows, true);
            edit(&mut m);
            if let Err(e) = self.write_sidecar(path, &m) {
                self.fail(role, Some(path), e);
            }
        }
    }

    /// Records a failed output.
    pub fn fail(&mut self, role: &str, path: Option<&Path>, e: anyhow::Error) {
        let what = path.map_or("stdout".to_string(), |p| p.display().to_string());
        self.failures.push(format!("`{role}` {what}: {e:#}"));
    }

    /// Ok if every output was written; otherwise one error listing every failure.
    pub fn finish(self) -> Result<()> {
        if self.failures.is_empty() {
            return Ok(());
        }
        bail!(
            "{} output(s) could not be written (the others were): {}",
            self.failures.len(),
            self.failures.join("; ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inputs() -> Inputs {
        Inputs {
            workflow: "test".into(),
            scene: None,
            params: serde_json::json!({}),
        }
    }

    #[test]
    fn one_failed_write_does_not_stop_the_others() {
        let d = std::env::temp_dir().join(format!("superlube-outputs-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let mut o = Outputs::new(inputs(), vec![]);
        let (a, b) = (d.join("a.csv"), d.join("b.json"));
        std::fs::write(d.join("file"), b"x").unwrap();
        let bad = d.join("file/c.csv"); // parent is a file
        o.write("--out", Some(&a), Ok(b"a\n".to_vec()), Some(0));
        o.write("--contacts-out", Some(&bad), Ok(b"c\n".to_vec()), None);
        o.write("--json", Some(&b), Ok(b"{}\n".to_vec()), None);
        let e = o.finish().unwrap_err().to_string();
        assert!(
            e.contains("--contacts-out") && e.contains("1 output(s)"),
            "{e}"
        );
        assert_eq!(std::fs::read(&a).unwrap(), b"a\n");
        assert_eq!(std::fs::read(&b).unwrap(), b"{}\n");
        assert!(sidecar_path(&a).exists() && sidecar_path(&b).exists());
        std::fs::remove_dir_all(&d).ok();
    }

    #[test]
    fn checks_name_every_bad_flag() {
        let d = std::env::temp_dir().join(format!("superlube-check-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        std::fs::write(d.join("file"), b"x").unwrap();
        let e = check_outputs(&[
            ("--out", Some(&d)),
            ("--json", Some(&d.join("file/x.json"))),
            ("--plot", Some(&d.join("new/dir/p.png"))),
            ("--xyz", Some(&d.join("a.xyz"))),
            ("--checkpoint", Some(&d.join("./a.xyz"))),
        ])
        .unwrap_err()
        .to_string();
        assert!(e.contains("`--out`") && e.contains("directory"), "{e}");
        assert!(
            e.contains("`--json`") && e.contains("not a directory"),
            "{e}"
        );
        assert!(!e.contains("`--plot`"), "{e}");
        assert!(e.contains("`--checkpoint` and `--xyz`"), "{e}");
        assert!(check_outputs(&[("--out", Some(&d.join("ok.csv"))), ("--json", None)]).is_ok());
        std::fs::remove_dir_all(&d).ok();
    }
}
