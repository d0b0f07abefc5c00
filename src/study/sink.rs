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
//! count.

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
}

impl CsvSink {
    /// CSV over `stream`.
    pub fn new(stream: StreamFile) -> CsvSink {
        CsvSink {
            w: csv::Writer::from_writer(stream),
            rows: 0,
        }
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
        self.w.serialize(row)?;
        self.rows += 1;
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
