//! `superlube lammps-check`: reads the contact dump of an exported LAMMPS run and reports the
//! contacts, P_max and the contacts above P_crit per frame (engine: `dem::export::check`).

use crate::runs::meta::Inputs;
use crate::runs::output::{check_outputs, Outputs};
use anyhow::{bail, Context, Result};
use dem::export::{check_dump, files, ExportMeta, FailedContact};
use std::io::{BufReader, Write};
use std::path::PathBuf;

/// Options of `superlube lammps-check`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The contact dump written by the exported deck (contacts.dump).
    #[arg(value_name = "DUMP")]
    dump: PathBuf,
    /// The export's export.json [default: beside DUMP].
    #[arg(long, value_name = "FILE.json")]
    meta: Option<PathBuf>,
    /// Per-frame CSV (step,t_us,phase,contacts,p_max_GPa,failed_contacts), written atomically;
    /// stdout if absent.
    #[arg(long, value_name = "FILE.csv")]
    out: Option<PathBuf>,
    /// CSV of every contact above P_crit (step,t_us,slider_index,substrate_index,p0_GPa).
    #[arg(long = "failed-out", value_name = "FILE.csv")]
    failed_out: Option<PathBuf>,
}

/// Runs `superlube lammps-check`.
pub fn run(a: Args) -> Result<()> {
    check_outputs(&[
        ("--out", a.out.as_deref()),
        ("--failed-out", a.failed_out.as_deref()),
    ])?;
    if !a.dump.is_file() {
        bail!("`DUMP`: {} is not a readable file", a.dump.display());
    }
    let meta_path = match &a.meta {
        Some(p) => p.clone(),
        None => a
            .dump
            .parent()
            .map(|d| d.join(files::META))
            .unwrap_or_else(|| PathBuf::from(files::META)),
    };
    let text = std::fs::read_to_string(&meta_path).map_err(|e| {
        anyhow::anyhow!(
            "`--meta`: cannot read {}: {} (the export.json of the export that wrote the dump)",
            meta_path.display(),
            surrogate::io_error::plain(&e)
        )
    })?;
    let meta: ExportMeta = serde_json::from_str(&text)
        .with_context(|| format!("`--meta`: {} is not an export.json", meta_path.display()))?;
    let input = BufReader::new(std::fs::File::open(&a.dump).map_err(|e| {
        anyhow::anyhow!(
            "`DUMP`: cannot read {}: {}",
            a.dump.display(),
            surrogate::io_error::plain(&e)
        )
    })?);
    // Rows go to memory-light CSV writers; files are written atomically at the end.
    let mut frames = csv::Writer::from_writer(Vec::new());
    let mut failed = csv::Writer::from_writer(Vec::new());
    let keep_failed = a.failed_out.is_some();
    let name = a.dump.display().to_string();
    let summary = check_dump(input, &name, &meta, &mut |r, f: &[FailedContact]| {
        frames
            .serialize(r)
            .map_err(|e| dem::DemError::invalid("out", "csv", &e.to_string()))?;
        if keep_failed {
            for c in f {
                failed
                    .serialize(c)
                    .map_err(|e| dem::DemError::invalid("failed-out", "csv", &e.to_string()))?;
            }
        }
        Ok(())
    })?;
    let mut outs = Outputs::new(
        Inputs {
            workflow: "lammps-check".into(),
            scene: None,
            params: serde_json::json!({
                "dump": a.dump.display().to_string(),
                "export": serde_json::to_value(&meta)?,
            }),
        },
        Vec::new(),
    );
    let n_frames = summary.frames as u64;
    outs.write(
        "frames",
        a.out.as_deref(),
        frames.into_inner().map_err(anyhow::Error::from),
        Some(n_frames),
    );
    if let Some(p) = &a.failed_out {
        let text = failed.into_inner().map_err(anyhow::Error::from).map(|b| {
            if b.is_empty() {
                b"step,t_us,slider_index,substrate_index,p0_GPa\n".to_vec()
            } else {
                b
            }
        });
        outs.write("failed", Some(p), text, None);
    }
    let mut err = std::io::stderr().lock();
    write!(err, "lammps-check: {}", summary.text())?;
    outs.finish()
}
