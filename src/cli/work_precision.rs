//! `superlube figures --work-precision`: flags → [`crate::study::work_precision::work_precision`]
//! → per tier `work_precision_<tier>.csv` and `.png` (and their sidecars), written as soon as
//! the tier is done.

use crate::plot::work_precision::work_precision_png;
use crate::runs::progress::{Progress, Reporter};
use crate::runs::sink::csv_bytes;
use crate::runs::{meta::Inputs, output::check_outputs, output::Outputs};
use crate::study::work_precision::{work_precision, Tier, WorkPrecisionParams};
use anyhow::Result;
use std::path::Path;

#[derive(clap::Args, Debug, Default)]
pub struct WorkPrecisionArgs {
    /// Draw the work-precision diagrams (CPU cost against error for every accuracy knob of each
    /// tier, on the study's three scenes) instead of the screening figures; default `--out-dir
    /// figures/work_precision`. ~30 min on 2 cores (docs/validation/work-precision.md).
    #[arg(long = "work-precision", conflicts_with = "friction")]
    pub work_precision: bool,
    /// The quick set: a 10 µm slider, short paths and a 40 µs DEM slide (about a minute; what CI
    /// checks).
    #[arg(long, requires = "work_precision")]
    pub quick: bool,
    /// Only these tiers (comma-separated) [default: all].
    #[arg(long, value_enum, value_delimiter = ',', requires = "work_precision")]
    pub tier: Vec<Tier>,
    /// Leave LAMMPS out of the tiers diagram even where `lmp` is found (its run of the full
    /// set's 30 µm scenes takes about an hour each on one core).
    #[arg(long, requires = "work_precision")]
    pub no_lammps: bool,
}

/// Runs the diagrams into `dir`.
pub fn run(dir: &Path, a: &WorkPrecisionArgs) -> Result<()> {
    let mut tiers: Vec<Tier> = if a.tier.is_empty() {
        Tier::ALL.to_vec()
    } else {
        a.tier.clone()
    };
    tiers.sort_by_key(|t| Tier::ALL.iter().position(|x| x == t));
    tiers.dedup();
    let params = WorkPrecisionParams {
        quick: a.quick,
        tiers,
        lammps: !a.no_lammps,
    };
    check_outputs(&[("--out-dir", Some(&dir.join("x.csv")))])?;
    let rep = Reporter::stderr();
    let mut outs = Outputs::new(
        Inputs {
            workflow: "work-precision".into(),
            scene: None,
            params: params.record(),
        },
        vec![],
    );
    work_precision(&params, &rep, &mut |tier, rows| {
        let base = dir.join(tier.stem());
        let (csv, png) = (base.with_extension("csv"), base.with_extension("png"));
        outs.write(
            "--out-dir",
            Some(&csv),
            csv_bytes(&rows),
            Some(rows.len() as u64),
        );
        outs.attempt("--out-dir", &png, || {
            work_precision_png(
                &png,
                &format!("work-precision, {}", tier.name()),
                tier,
                &rows,
            )
        });
        rep.note(&format!("wrote {} and {}", csv.display(), png.display()));
        Ok(())
    })?;
    outs.finish()
}
