//! Row sinks: where a workflow streams its rows, in order, as they are computed.
//!
//! A workflow never holds more than a bounded window of rows; it pushes each finished row into a
//! [`RowSink`]. The command line passes a [`CsvSink`] over a [`StreamFile`] (or stdout); tests and
//! figure code may pass a `Vec`.
//!
//! ## Streaming files (atomic, resumable later)
//! A [`StreamFile`] for `OUT` writes the rows to `OUT.partial` (same directory, so the final
//! rename is atomic) and renames it to `OUT` only when the run completed. An interrupted run
//! leaves `OUT` untouched (the previous result, if any) and `OUT.partial` holding the header and
//! every row finished so far, each a complete line, in the run's deterministic order: row `k`
//! (0-based) is data line `k + 1`. Its inputs are described by `OUT.partial.meta.json` (see
//! [`super::meta`]). A later `--resume` can check that sidecar's `input_hash`, drop a trailing
//! incomplete line and continue at row `k`; `--shard i/n` can write a contiguous block of row
//! indices and `merge` concatenate blocks: the order is fixed by the inputs, never by the thread
//! count. [`StreamFile::resume`] reopens a checked partial file (see [`super::resume`]) and
//! [`CsvSink::resumed`] appends to it without a second header.
//!
//! ## Test hook
//! `SUPERLUBE_TEST_KILL_AFTER_ROWS=N` (tests only) makes a streamed file behave like a process
//! killed mid-write: after this process has written `N` rows into a partial file, it flushes
//! them, writes the first half of the next row's line, and exits at once with status 137, no
//! clean-up run (the interrupted-and-resumed tests use it to stop at a known row).

use anyhow::{Context, Result};
use serde::Serialize;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Receives rows in order.
pub trait RowSink<R> {
    /// Takes the next row.
    fn push(&mut self, row: &R) -> Result<()>;
}

impl<R: Clone> RowSink<R> for Vec<R> {
    fn push(&mut self, row: &R) -> Result<()> {
        Vec::push(self, row.clone());
        Ok(())
    }
}

/// Forwards each row to two sinks (e.g. a CSV file and an in-memory plot buffer).
pub struct Tee<'a, R>(pub &'a mut dyn RowSink<R>, pub &'a mut dyn RowSink<R>);

impl<R> RowSink<R> for Tee<'_, R> {
    fn push(&mut self, row: &R) -> Result<()> {
        self.0.push(row)?;
        self.1.push(row)
    }
}

/// The temporary name `OUT.partial` of a streaming output `OUT`.
pub fn partial_path(path: &Path) -> PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(".partial");
    PathBuf::from(s)
}

/// Where a stream's bytes go.
enum Target {
    /// A regular file: `OUT.partial`, renamed to `OUT` by [`StreamFile::commit`].
    File { out: PathBuf, tmp: PathBuf },
    /// An existing non-regular file (`/dev/null`, a FIFO): written in place.
    Device(PathBuf),
    /// Standard output.
    Stdout,
}

/// A byte stream to an output file (through `OUT.partial`, see the module docs) or stdout.
pub struct StreamFile {
    w: Box<dyn Write>,
    target: Target,
}

impl StreamFile {
    /// Opens the stream for `path` (`None` = stdout). Creates missing parent directories.
    pub fn create(path: Option<&Path>) -> Result<StreamFile> {
        let Some(out) = path else {
            return Ok(StreamFile {
                w: Box::new(BufWriter::new(std::io::stdout())),
                target: Target::Stdout,
            });
        };
        if let Ok(m) = std::fs::metadata(out) {
            if !m.is_file() && !m.is_dir() {
                let f = std::fs::OpenOptions::new()
                    .write(true)
                    .open(out)
                    .with_context(|| format!("opening {}", out.display()))?;
                return Ok(StreamFile {
                    w: Box::new(BufWriter::new(f)),
                    target: Target::Device(out.to_path_buf()),
                });
            }
        }
        if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        }
        let tmp = partial_path(out);
        let f = File::create(&tmp).with_context(|| format!("creating {}", tmp.display()))?;
        Ok(StreamFile {
            w: Box::new(BufWriter::new(f)),
            target: Target::File {
                out: out.to_path_buf(),
                tmp,
            },
        })
    }

    /// Reopens the partial file `OUT.partial` of an interrupted run for appending, cut to its
    /// first `keep` bytes (the complete rows kept by [`super::resume`]).
    pub fn resume(out: &Path, keep: u64) -> Result<StreamFile> {
        let tmp = partial_path(out);
        let f = std::fs::OpenOptions::new()
            .write(true)
            .open(&tmp)
            .with_context(|| format!("opening {}", tmp.display()))?;
        f.set_len(keep)
            .with_context(|| format!("cutting {} to its complete rows", tmp.display()))?;
        let mut f = f;
        use std::io::Seek;
        f.seek(std::io::SeekFrom::End(0))?;
        Ok(StreamFile {
            w: Box::new(BufWriter::new(f)),
            target: Target::File {
                out: out.to_path_buf(),
                tmp,
            },
        })
    }

    /// The file the stream ends up in (`None` for stdout).
    pub fn path(&self) -> Option<&Path> {
        match &self.target {
            Target::File { out, .. } | Target::Device(out) => Some(out),
            Target::Stdout => None,
        }
    }

    /// Whether the stream ends in a regular file (which gets a sidecar).
    pub fn is_regular_file(&self) -> bool {
        matches!(self.target, Target::File { .. })
    }

    /// Flushes, fsyncs and renames `OUT.partial` to `OUT` (regular files); flushes otherwise.
    pub fn commit(mut self) -> Result<()> {
        self.w.flush().context(self.describe())?;
        if let Target::File { out, tmp } = &self.target {
            drop(self.w);
            File::open(tmp)
                .and_then(|f| f.sync_all())
                .with_context(|| format!("syncing {}", tmp.display()))?;
            std::fs::rename(tmp, out)
                .with_context(|| format!("renaming {} to {}", tmp.display(), out.display()))?;
        }
        Ok(())
    }

    fn describe(&self) -> String {
        match &self.target {
            Target::File { out, .. } | Target::Device(out) => format!("writing {}", out.display()),
            Target::Stdout => "writing to stdout".into(),
        }
    }
}

impl Write for StreamFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.w.write(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.w.flush()
    }
}

/// Streams rows as CSV (header from the row type's field names, written before the first row).
pub struct CsvSink {
    w: csv::Writer<StreamFile>,
    rows: u64,
    /// Rows written by this process (for the test hook).
    written: u64,
    kill_after: Option<u64>,
}

/// `SUPERLUBE_TEST_KILL_AFTER_ROWS` (see the module docs).
fn kill_after() -> Option<u64> {
    std::env::var("SUPERLUBE_TEST_KILL_AFTER_ROWS")
        .ok()
        .and_then(|v| v.parse().ok())
}

impl CsvSink {
    /// CSV over `stream`.
    pub fn new(stream: StreamFile) -> CsvSink {
        CsvSink::build(csv::Writer::from_writer(stream), 0)
    }

    /// CSV appended to a resumed `stream` that already holds the header and `rows` rows.
    pub fn resumed(stream: StreamFile, rows: u64) -> CsvSink {
        CsvSink::build(
            csv::WriterBuilder::new()
                .has_headers(false)
                .from_writer(stream),
            rows,
        )
    }

    fn build(w: csv::Writer<StreamFile>, rows: u64) -> CsvSink {
        let kill_after = if w.get_ref().is_regular_file() {
            kill_after()
        } else {
            None
        };
        CsvSink {
            w,
            rows,
            written: 0,
            kill_after,
        }
    }

    /// The test hook: half of `row`'s line after the rows so far, then exit without clean-up.
    fn die_mid_row<R: Serialize>(&mut self, row: &R) -> ! {
        let mut line = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(Vec::new());
        let _ = line.serialize(row);
        let bytes = line.into_inner().unwrap_or_default();
        let w = std::mem::replace(
            &mut self.w,
            csv::Writer::from_writer(StreamFile {
                w: Box::new(std::io::sink()),
                target: Target::Stdout,
            }),
        );
        if let Ok(mut s) = w.into_inner() {
            let _ = s.write_all(&bytes[..bytes.len() / 2]);
            let _ = s.flush();
        }
        std::process::exit(137);
    }

    /// Rows written so far.
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// Flushes the CSV buffer to the stream (done automatically by [`CsvSink::commit`]).
    pub fn flush(&mut self) -> Result<()> {
        self.w.flush()?;
        Ok(())
    }

    /// Finishes the stream ([`StreamFile::commit`]); returns the row count.
    pub fn commit(self) -> Result<u64> {
        let rows = self.rows;
        let stream = self
            .w
            .into_inner()
            .map_err(|e| anyhow::Error::new(e.into_error()))?;
        stream.commit()?;
        Ok(rows)
    }
}

impl<R: Serialize> RowSink<R> for CsvSink {
    fn push(&mut self, row: &R) -> Result<()> {
        if self.kill_after == Some(self.written) {
            self.die_mid_row(row);
        }
        self.w.serialize(row)?;
        self.rows += 1;
        self.written += 1;
        Ok(())
    }
}

/// Serialises rows with a header to CSV bytes (for small outputs written in one piece).
pub fn csv_bytes<R: Serialize>(rows: &[R]) -> Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r)?;
    }
    w.into_inner()
        .map_err(|e| anyhow::Error::new(e.into_error()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stream_goes_through_partial_and_is_renamed_on_commit() {
        let d = std::env::temp_dir().join(format!("superlube-sink-{}", std::process::id()));
        let out = d.join("x.csv");
        let mut s = CsvSink::new(StreamFile::create(Some(&out)).unwrap());
        #[derive(Serialize)]
        struct R {
            a: u32,
        }
        s.push(&R { a: 1 }).unwrap();
        s.flush().unwrap();
        assert!(!out.exists());
        assert_eq!(
            std::fs::read_to_string(partial_path(&out)).unwrap(),
            "a\n1\n"
        );
        assert_eq!(s.commit().unwrap(), 1);
        assert_eq!(std::fs::read_to_string(&out).unwrap(), "a\n1\n");
        assert!(!partial_path(&out).exists());
        std::fs::remove_dir_all(&d).ok();
    }
}
