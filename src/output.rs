//! Atomic output: every file is written to a temporary sibling and renamed into place, so an
//! interrupted run never leaves a half-written result.

use anyhow::{Context, Result};
use std::io::Write;
use std::path::Path;

/// Writes `bytes` to `path` atomically (temp file in the same directory, fsync, rename); see
/// [`surrogate::atomic_file::write_atomic`].
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    surrogate::atomic_file::write_atomic(path, bytes)
        .with_context(|| format!("writing {}", path.display()))
}

/// Writes `text` to `path` atomically, or to stdout when `path` is `None`.
pub fn write_or_stdout(path: Option<&Path>, text: &str) -> Result<()> {
    match path {
        Some(p) => write_atomic(p, text.as_bytes()),
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(text.as_bytes())?;
            out.flush()?;
            Ok(())
        }
    }
}

/// Serialises rows with a header to CSV text.
pub fn csv_text<R: serde::Serialize>(rows: &[R]) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r)?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

/// Rounds a grid or range coordinate to 1e-9 of its unit, removing the binary noise of
/// `start + k·step` (0.06000000000000001 → 0.06) in CSV files.
pub fn clean(v: f64) -> f64 {
    (v * 1e9).round() / 1e9
}
