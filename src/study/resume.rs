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
    let bytes = match std::fs::read(&partial) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e).with_context(|| format!("reading {}", partial.display())),
    };
    let sidecar = Sidecar::of(&partial).map_err(|e| {
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
    check_same_sweep(&partial, &sidecar, inputs, shard)
        .map_err(|e| anyhow::anyhow!("`--resume`: {e:#}"))?;
    let damaged = |why: String| {
        anyhow::anyhow!(
            "`--resume`: {} is damaged ({why}); delete it to start over",
            partial.display()
        )
    };
    let whole = match bytes.iter().rposition(|&b| b == b'\n') {
        Some(i) => i + 1,
        None => 0,
    };
    let torn = (bytes.len() - whole) as u64;
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
    let body = &bytes[..whole];
    if let Some(i) = body.iter().position(|&b| b == 0) {
        return Err(damaged(format!("a NUL byte at offset {i}")));
    }
    let mut r = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(false)
        .from_reader(body);
    let header = r
        .byte_headers()
        .map_err(|e| damaged(format!("header: {e}")))?
        .clone();
    if header.is_empty() || header.iter().all(|f| f.is_empty()) {
        return Err(damaged("no header line".into()));
    }
    let mut ends = vec![r.position().byte()];
    let max_rows = (run_items as u64).saturating_mul(rows_per_item as u64);
    let mut rec = csv::ByteRecord::new();
    loop {
        match r.read_byte_record(&mut rec) {
            Ok(true) => {}
            Ok(false) => break,
            Err(e) => {
                return Err(damaged(format!(
                    "row {} (line {}): {e}",
                    ends.len(),
                    ends.len() + 1
                )))
            }
        }
        ends.push(r.position().byte());
        if ends.len() as u64 - 1 > max_rows {
            return Err(damaged(format!("more rows than this run's {max_rows}")));
        }
    }
    let rows = ends.len() as u64 - 1;
    let items = (rows / rows_per_item.max(1) as u64) as usize;
    let keep_rows = items as u64 * rows_per_item as u64;
    Ok(Some(Kept {
        bytes: ends[keep_rows as usize],
        header: true,
        rows: keep_rows,
        items,
        torn_bytes: torn,
        dropped_rows: rows - keep_rows,
    }))
}

/// Whether `out` is already the complete output of this sweep and shard (its sidecar says
/// complete, same inputs and shard, `rows` rows): a resumed run then has nothing left to do.
pub fn is_complete(out: &Path, inputs: &Inputs, shard: Option<&ShardInfo>, rows: u64) -> bool {
    out.is_file()
        && Sidecar::of(out).is_ok_and(|s| {
            s.complete && s.rows == Some(rows) && check_same_sweep(out, &s, inputs, shard).is_ok()
        })
}
