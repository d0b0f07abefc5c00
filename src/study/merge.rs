//! `superlube merge`: the shards of one sweep joined into exactly the output of the unsharded
//! run (same rows, same order, same bytes) and its sidecar (same `input_hash`, `rows`).
//!
//! [`check`] refuses, naming the file and what differs, before anything is written:
//! a file without a sidecar, not written with `--shard`, incomplete (`complete: false`, e.g. a
//! `.partial` file), made by another superlube version, whose sidecar no longer matches its own
//! `input_hash`, or whose row count is not its shard's; shards of different sweeps (input hash,
//! with the parameters that differ), with different shard counts, item counts, rows per item or
//! schemas; a shard given twice; a missing shard. While merging, every file's header must be the
//! same and its CSV rows must number what its sidecar says.
//!
//! [`merge`] then writes the rows by the schema's merge: concatenation of the shards' data rows
//! in shard order (every schema whose rows are final per item: screen, corrugation, and any
//! later sweep), or, for the landscape's z rows ([`LANDSCAPE_Z`]), [`landscape::finish`] over
//! the shards in order (Δz = z − min z over the whole grid) — the same function an unsharded
//! landscape runs on its own spill file.

use super::landscape;
use crate::runs::meta::{input_differences, Sidecar, VERSION};
use crate::runs::resume::short;
use crate::runs::shard::Shard;
use crate::runs::sink::{CsvSink, StreamFile};
use crate::runs::sweep::{ShardInfo, LANDSCAPE_Z};
use anyhow::{bail, Context, Result};
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};

/// One checked shard file.
#[derive(Debug, Clone)]
pub struct ShardFile {
    /// The file.
    pub path: PathBuf,
    /// Its sidecar.
    pub sidecar: Sidecar,
    /// Its shard record.
    pub info: ShardInfo,
}

/// Checks `files` (see the module docs); returns them in shard order.
pub fn check(files: &[PathBuf]) -> Result<Vec<ShardFile>> {
    if files.is_empty() {
        bail!("no shard files given");
    }
    let mut shards: Vec<ShardFile> = Vec::with_capacity(files.len());
    for path in files {
        let shard = check_one(path)?;
        if let Some(first) = shards.first() {
            same_sweep(first, &shard)?;
            if let Some(other) = shards.iter().find(|s| s.info.index == shard.info.index) {
                bail!(
                    "{} and {} are both shard {}: each shard must be given once",
                    other.path.display(),
                    shard.path.display(),
                    shard.info.label()
                );
            }
        }
        shards.push(shard);
    }
    let count = shards[0].info.count;
    let missing: Vec<String> = (0..count)
        .filter(|i| !shards.iter().any(|s| s.info.index == *i))
        .map(|i| format!("{i}/{count}"))
        .collect();
    if !missing.is_empty() {
        bail!(
            "shard{} {} of the sweep {} missing (given: {})",
            if missing.len() > 1 { "s" } else { "" },
            missing.join(", "),
            if missing.len() > 1 { "are" } else { "is" },
            shards
                .iter()
                .map(|s| format!("{} = {}", s.info.label(), s.path.display()))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    shards.sort_by_key(|s| s.info.index);
    Ok(shards)
}

fn check_one(path: &Path) -> Result<ShardFile> {
    let d = path.display();
    match std::fs::metadata(path) {
        Ok(m) if m.is_file() => {}
        Ok(_) => bail!("{d} is not a regular file"),
        Err(e) => bail!("{d}: {e}"),
    }
    let sidecar = Sidecar::of(path)?;
    if sidecar.version != VERSION {
        bail!(
            "{d} was made by superlube {}; merge it with that version (this is {VERSION})",
            sidecar.version
        );
    }
    if !sidecar.complete {
        bail!(
            "{d} is incomplete (its sidecar says `complete: false`): the shard is still running or was interrupted; finish it (run it again with {}) and merge its final output",
            crate::study::input::Input::Resume
        );
    }
    let Some(info) = sidecar.shard.clone() else {
        bail!(
            "{d} is not a shard (its sidecar has no `shard`: it was made without {} i/n)",
            crate::study::input::Input::Shard
        );
    };
    if sidecar.inputs().hash() != sidecar.input_hash {
        bail!(
            "{d}: its sidecar's recorded inputs do not hash to its input_hash {} (edited?)",
            short(&sidecar.input_hash)
        );
    }
    let expect = Shard {
        index: info.index,
        count: info.count,
    };
    if info.count == 0
        || info.index >= info.count
        || info.range() != expect.range(info.items)
        || info.rows_per_item == 0
    {
        bail!(
            "{d}: inconsistent shard record {} (items {:?} of {})",
            info.label(),
            info.item_range,
            info.items
        );
    }
    if sidecar.rows != Some(info.rows()) {
        bail!(
            "{d} has {} rows, but shard {} ({} {} × {} rows) has {}: incomplete or damaged",
            sidecar.rows.map_or("no".into(), |r| r.to_string()),
            info.label(),
            info.range().len(),
            info.unit,
            info.rows_per_item,
            info.rows()
        );
    }
    Ok(ShardFile {
        path: path.to_path_buf(),
        sidecar,
        info,
    })
}

/// `b` must be a shard of the same sweep as `a`.
fn same_sweep(a: &ShardFile, b: &ShardFile) -> Result<()> {
    let (da, db) = (a.path.display(), b.path.display());
    if a.sidecar.input_hash != b.sidecar.input_hash {
        let diff = input_differences(&b.sidecar.inputs(), &a.sidecar.inputs(), 4);
        bail!(
            "{db} belongs to another sweep than {da}: input_hash {} vs {}{}",
            short(&b.sidecar.input_hash),
            short(&a.sidecar.input_hash),
            if diff.is_empty() {
                String::new()
            } else {
                format!(" ({db} vs {da} in {})", diff.join(", "))
            }
        );
    }
    let (x, y) = (&a.info, &b.info);
    if x.count != y.count {
        bail!(
            "{db} is shard {} but {da} is shard {}: the shards of one sweep share one count",
            y.label(),
            x.label()
        );
    }
    for (what, p, q) in [
        ("items", x.items.to_string(), y.items.to_string()),
        (
            "rows per item",
            x.rows_per_item.to_string(),
            y.rows_per_item.to_string(),
        ),
        ("row schema", x.schema.clone(), y.schema.clone()),
    ] {
        if p != q {
            bail!("{db} has {what} {q} but {da} has {p}: not shards of one sweep");
        }
    }
    Ok(())
}

/// Reads `path`'s header line (bytes, with its newline) and counts its CSV rows, checking that
/// every row parses with the header's field count and that the file ends with a newline.
fn scan(path: &Path) -> Result<(Vec<u8>, u64)> {
    let d = path.display();
    let f = std::fs::File::open(path)
        .map_err(|e| anyhow::anyhow!("cannot open {d}: {}", surrogate::io_error::plain(&e)))?;
    let mut r = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(false)
        .from_reader(BufReader::new(f));
    r.byte_headers()
        .with_context(|| format!("{d}: reading the header"))?;
    let header_len = r.position().byte();
    let mut rec = csv::ByteRecord::new();
    let mut rows = 0u64;
    while r
        .read_byte_record(&mut rec)
        .with_context(|| format!("{d}: row {}", rows + 1))?
    {
        rows += 1;
    }
    use std::io::{Read, Seek, SeekFrom};
    let mut f = std::fs::File::open(path)?;
    let len = f.metadata()?.len();
    let mut last = [0u8; 1];
    f.seek(SeekFrom::Start(len.saturating_sub(1)))?;
    if len == 0 || f.read_exact(&mut last).is_err() || last[0] != b'\n' {
        bail!("{d}: does not end with a complete line (damaged?)");
    }
    let mut header = vec![0u8; header_len as usize];
    f.seek(SeekFrom::Start(0))?;
    f.read_exact(&mut header)?;
    Ok((header, rows))
}

/// Merges checked `shards` (from [`check`], in shard order) into `out`; returns the rows
/// written. Errors before the first byte is written when a file's header or row count is not
/// what its sidecar and the first shard say.
pub fn merge(shards: &[ShardFile], out: StreamFile) -> Result<u64> {
    let mut header: Option<(Vec<u8>, &Path)> = None;
    let mut total = 0u64;
    for s in shards {
        let (h, rows) = scan(&s.path)?;
        if rows != s.info.rows() {
            bail!(
                "{} holds {rows} CSV rows but its sidecar says {}: damaged",
                s.path.display(),
                s.info.rows()
            );
        }
        match &header {
            Some((first, p)) if *first != h => bail!(
                "{} has another header than {}: `{}` vs `{}`",
                s.path.display(),
                p.display(),
                String::from_utf8_lossy(&h).trim_end(),
                String::from_utf8_lossy(first).trim_end()
            ),
            Some(_) => {}
            None => header = Some((h, &s.path)),
        }
        total += rows;
    }
    let expect = shards[0].info.total_rows();
    if total != expect {
        bail!("the shards hold {total} rows, the sweep has {expect}");
    }
    let files: Vec<PathBuf> = shards.iter().map(|s| s.path.clone()).collect();
    if shards[0].info.schema == LANDSCAPE_Z {
        let items = shards[0].info.items;
        let n = (items as f64).sqrt().round() as usize;
        if n * n != items || n < 2 {
            bail!("a landscape of {items} grid points is not an N×N grid");
        }
        let mut sink = CsvSink::new(out);
        landscape::finish(n, &files, &mut sink)?;
        return sink.commit();
    }
    let mut out = out;
    let (h, _) = header.expect("at least one shard");
    out.write_all(&h)?;
    for s in shards {
        let mut r = BufReader::new(std::fs::File::open(&s.path)?);
        let mut skip = Vec::new();
        r.read_until(b'\n', &mut skip)?;
        if skip != h {
            bail!("{} changed while merging", s.path.display());
        }
        std::io::copy(&mut r, &mut out)?;
    }
    out.commit()?;
    Ok(total)
}
