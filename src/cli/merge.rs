//! `superlube merge`: shard files → [`crate::study::merge`] → the unsharded output + sidecar.

use crate::runs::output::same_file;
use crate::runs::sink::StreamFile;
use crate::runs::{output::check_outputs, output::Outputs, progress::Progress, progress::Reporter};
use crate::study::merge::{check, merge};
use anyhow::{bail, Result};
use std::path::PathBuf;

/// Options of `superlube merge`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The shard files of one sweep (the `--out` files of its `--shard i/n` runs, each with its
    /// sidecar), in any order. Checked before anything is written: same sweep (input hash),
    /// same shard count, every shard 0..n-1 exactly once, each complete, row counts as the
    /// sidecars say.
    #[arg(value_name = "SHARD.csv", required = true)]
    shards: Vec<PathBuf>,
    /// The merged CSV: exactly the rows of the unsharded run in its order (byte-identical; for
    /// a landscape Δz is computed from the shards' heights), streamed through FILE.csv.partial,
    /// with the sidecar the unsharded run would write (same input hash and rows). Stdout if
    /// absent.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
}

/// Runs `superlube merge`.
pub fn run(a: Args) -> Result<()> {
    check_outputs(&[("--out", a.out.as_deref())])?;
    if let Some(out) = &a.out {
        if let Some(s) = a.shards.iter().find(|s| same_file(s, out)) {
            bail!(
                "`--out` {} is one of the shard files ({}): give another output file",
                out.display(),
                s.display()
            );
        }
    }
    let shards = check(&a.shards)?;
    let first = &shards[0];
    let rep = Reporter::stderr();
    let mut outs = Outputs::new(first.sidecar.inputs(), first.sidecar.warnings.clone());
    let stream = StreamFile::create(a.out.as_deref())?;
    let rows = match merge(&shards, stream) {
        Ok(r) => r,
        Err(e) => {
            if let Some(out) = &a.out {
                let _ = std::fs::remove_file(crate::runs::sink::partial_path(out));
            }
            return Err(e);
        }
    };
    if let Some(out) = &a.out {
        let from: Vec<String> = shards
            .iter()
            .map(|s| s.path.display().to_string())
            .collect();
        outs.sidecar_with("--out", out, Some(rows), |m| m.merged_from = Some(from));
    }
    let i = &first.info;
    rep.note(&format!(
        "merged {} shards of a {} sweep ({} {}, {rows} rows){}",
        i.count,
        first.sidecar.workflow,
        i.items,
        i.unit,
        a.out
            .as_ref()
            .map_or(String::new(), |o| format!(" into {}", o.display()))
    ));
    outs.finish()
}
