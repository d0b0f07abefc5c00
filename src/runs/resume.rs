//! `--resume`: what an interrupted sweep's partial output `OUT.partial` may keep.
//!
//! A partial file is resumed only when its sidecar `OUT.partial.meta.json` says it comes from
//! the same sweep — same `input_hash` (workflow, scene, parameters, tool version) and the same
//! shard — and its content is sound: a header line, then rows that parse as CSV with the
//! header's field count, no NUL bytes, no more rows than the run has. A torn last line (the
//! process died mid-write) is cut back to the last complete row, and the rows of an item that
//! was not finished (fewer than `rows_per_item`) are dropped, so the run continues at an item
//! boundary and appends exactly the rows an uninterrupted run would have written next. Anything
//! else is refused with the reason, before any work; the partial file is then left as it is.

use super::meta::{input_differences, Inputs, Sidecar};
use super::sink::partial_path;
use super::sweep::ShardInfo;
use anyhow::{bail, Context, Result};
use std::collections::VecDeque;
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::Path;

/// The part of a partial file a resumed run keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Kept {
    /// Bytes kept (header and complete items); the file is cut to this length.
    pub bytes: u64,
    /// Whether a header line is kept (false: the file was empty or held only a torn header).
    pub header: bool,
    /// Rows kept.
    pub rows: u64,
    /// Items of this run those rows complete.
    pub items: usize,
    /// Bytes of a torn last line cut off.
    pub torn_bytes: u64,
    /// Complete rows dropped because their item was not finished.
    pub dropped_rows: u64,
}

impl Kept {
    /// One log line: what was kept and what was cut.
    pub fn describe(&self, file: &Path, unit: &str, run_items: usize) -> String {
        let mut s = format!(
            "resuming {}: {} rows kept ({} of this run's {} {unit} done)",
            file.display(),
            self.rows,
            self.items,
            run_items
        );
        if self.torn_bytes > 0 {
            s += &format!(", a torn last line ({} bytes) cut off", self.torn_bytes);
        }
        if self.dropped_rows > 0 {
            s += &format!(
                ", {} row(s) of an unfinished item dropped",
                self.dropped_rows
            );
        }
        s += &format!(
            "; computing the remaining {} {unit}",
            run_items - self.items
        );
        s
    }
}

/// Checks that `sidecar` describes the same sweep as `inputs` and `shard`; `what` names the
/// file in the error.
pub fn check_same_sweep(
    what: &Path,
    sidecar: &Sidecar,
    inputs: &Inputs,
    shard: Option<&ShardInfo>,
) -> Result<()> {
    let hash = inputs.hash();
    if sidecar.input_hash != hash {
        let mut diff = input_differences(&sidecar.inputs(), inputs, 4);
        if sidecar.version != super::meta::VERSION {
            diff.insert(
                0,
                format!(
                    "made by superlube {}, this is {}",
                    sidecar.version,
                    super::meta::VERSION
                ),
            );
        }
        bail!(
            "{} was made from different inputs (input_hash {} ≠ this run's {}{}); \
             delete it to start over, or run with the inputs it was made from",
            what.display(),
            short(&sidecar.input_hash),
            short(&hash),
            if diff.is_empty() {
                String::new()
            } else {
                format!("; the file vs this run: {}", diff.join(", "))
            }
        );
    }
    if sidecar.shard.as_ref() != shard {
        let name = |s: Option<&ShardInfo>| {
            s.map_or("the whole sweep (no --shard)".to_string(), |s| {
                format!("shard {}", s.label())
            })
        };
        bail!(
            "{} holds {}, this run computes {}; give the same --shard, or delete it",
            what.display(),
            name(sidecar.shard.as_ref()),
            name(shard)
        );
    }
    Ok(())
}

/// `sha256:0123456789ab…`.
pub fn short(hash: &str) -> String {
    format!("{}…", &hash[..hash.len().min(19)])
}

/// Inspects the partial file of output `out` for a resumed run with `inputs` and `shard` whose
/// items give `rows_per_item` rows each, `run_items` items in all. `Ok(None)`: no partial file
/// (the run starts from the beginning). Errors: the sidecar is missing, from another sweep or
/// shard, or the file is damaged (see the module docs).
pub fn inspect(
    out: &Path,
    inputs: &Inputs,
    shard: Option<&ShardInfo>,
    rows_per_item: usize,
    run_items: usize,
) -> Result<Option<Kept>> {
    let partial = partial_path(out);
    let mut file = match std::fs::File::open(&partial) {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e).with_context(|| format!("reading {}", partial.display())),
    };
    check_sidecar(&partial, inputs, shard)?;
    let damaged = |why: String| {
        anyhow::anyhow!(
            "`--resume`: {} is damaged ({why}); delete it to start over",
            partial.display()
        )
    };
    let len = file.metadata()?.len();
    let whole = end_of_last_line(&mut file, len)
        .with_context(|| format!("reading {}", partial.display()))?;
    let torn = len - whole;
    if whole == 0 {
        // Empty, or only a torn header: start the file again.
        return Ok(Some(Kept {
            bytes: 0,
            header: false,
            rows: 0,
            items: 0,
            torn_bytes: torn,
            dropped_rows: 0,
        }));
    }
    // Stream the complete lines (memory flat in the file's size): the end of each of the last
    // rows_per_item + 1 rows is kept, enough to cut back to an item boundary.
    let rpi = rows_per_item.max(1) as u64;
    let (rows, ends) = scan(file, whole, rpi, run_items, &damaged)?;
    let items = rows / rpi;
    let keep_rows = items * rpi;
    // ends[k] is the end of row rows − (ends.len() − 1) + k
    let first = rows + 1 - ends.len() as u64;
    Ok(Some(Kept {
        bytes: ends[(keep_rows - first) as usize],
        header: true,
        rows: keep_rows,
        items: items as usize,
        torn_bytes: torn,
        dropped_rows: rows - keep_rows,
    }))
}

/// Checks the sidecar of the partial file `partial`: there, not complete, and of the same
/// sweep and shard as this run (`inputs`, `shard`).
fn check_sidecar(partial: &Path, inputs: &Inputs, shard: Option<&ShardInfo>) -> Result<()> {
    let sidecar = Sidecar::of(partial).map_err(|e| {
        anyhow::anyhow!(
            "`--resume`: {e:#}; cannot tell which inputs {} comes from: delete it to start over",
            partial.display()
        )
    })?;
    if sidecar.complete {
        bail!(
            "`--resume`: the sidecar of {} says it is complete, which a partial file never is; delete it to start over",
            partial.display()
        );
    }
    check_same_sweep(partial, &sidecar, inputs, shard)
        .map_err(|e| anyhow::anyhow!("`--resume`: {e:#}"))?;
    Ok(())
}

/// Streams the first `whole` bytes of the partial `file` as CSV with a header, `rpi` rows per
/// item, at most `run_items` items: the number of rows and the byte ends of the last `rpi + 1`
/// (the header's end first while fewer). Errors through `damaged` on a NUL byte, a bad row or
/// too many rows.
fn scan(
    mut file: std::fs::File,
    whole: u64,
    rpi: u64,
    run_items: usize,
    damaged: &dyn Fn(String) -> anyhow::Error,
) -> Result<(u64, VecDeque<u64>)> {
    file.seek(SeekFrom::Start(0))?;
    let mut r = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(false)
        .from_reader(NulCheck::new(BufReader::new(file.take(whole))));
    let nul = |r: &csv::Reader<NulCheck<_>>| {
        r.get_ref()
            .nul_at
            .map(|at| damaged(format!("a NUL byte at offset {at}, as a crash can leave")))
    };
    let header = match r.byte_headers() {
        Ok(h) => h.clone(),
        Err(e) => return Err(nul(&r).unwrap_or_else(|| damaged(format!("header: {e}")))),
    };
    if let Some(e) = nul(&r) {
        return Err(e);
    }
    if header.iter().all(|f| f.is_empty()) {
        return Err(damaged("no header line".into()));
    }
    let max_rows = (run_items as u64).saturating_mul(rpi);
    let mut ends: VecDeque<u64> = VecDeque::from([r.position().byte()]);
    let mut rows = 0u64;
    let mut rec = csv::ByteRecord::new();
    loop {
        match r.read_byte_record(&mut rec) {
            Ok(true) => {}
            Ok(false) => break,
            Err(e) => {
                return Err(nul(&r).unwrap_or_else(|| {
                    damaged(format!("row {} (line {}): {e}", rows + 1, rows + 2))
                }))
            }
        }
        rows += 1;
        if let Some(e) = nul(&r) {
            return Err(e);
        }
        if rows > max_rows {
            return Err(damaged(format!("more rows than this run's {max_rows}")));
        }
        ends.push_back(r.position().byte());
        if ends.len() as u64 > rpi + 1 {
            ends.pop_front();
        }
    }
    Ok((rows, ends))
}

/// A reader that notes the offset of the first NUL byte read through it.
struct NulCheck<R> {
    inner: R,
    offset: u64,
    nul_at: Option<u64>,
}

impl<R> NulCheck<R> {
    fn new(inner: R) -> Self {
        NulCheck {
            inner,
            offset: 0,
            nul_at: None,
        }
    }
}

impl<R: Read> Read for NulCheck<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        if self.nul_at.is_none() {
            if let Some(i) = buf[..n].iter().position(|&b| b == 0) {
                self.nul_at = Some(self.offset + i as u64);
            }
        }
        self.offset += n as u64;
        Ok(n)
    }
}

/// The length of `file` (`len` bytes) up to and including its last newline (0 if none).
fn end_of_last_line(file: &mut std::fs::File, len: u64) -> std::io::Result<u64> {
    let mut end = len;
    let mut buf = vec![0u8; 64 * 1024];
    while end > 0 {
        let start = end.saturating_sub(buf.len() as u64);
        let chunk = &mut buf[..(end - start) as usize];
        file.seek(SeekFrom::Start(start))?;
        file.read_exact(chunk)?;
        if let Some(i) = chunk.iter().rposition(|&b| b == b'\n') {
            return Ok(start + i as u64 + 1);
        }
        end = start;
    }
    Ok(0)
}

/// Whether `out` is already the complete output of this sweep and shard (its sidecar says
/// complete, same inputs and shard, `rows` rows): a resumed run then has nothing left to do.
pub fn is_complete(out: &Path, inputs: &Inputs, shard: Option<&ShardInfo>, rows: u64) -> bool {
    out.is_file()
        && Sidecar::of(out).is_ok_and(|s| {
            s.complete && s.rows == Some(rows) && check_same_sweep(out, &s, inputs, shard).is_ok()
        })
}
