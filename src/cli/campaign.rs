//! `superlube figures --friction`: the study's friction campaign ([`crate::study::campaign`])
//! through the batch runner — every run under `DIR/runs/<name>/`, `DIR/runs.csv`, and per figure
//! `DIR/friction_fig*.png` with the CSV behind it.

use super::checks;
use super::dem_args::ModelArg;
use super::point_args::{help, with, LoadsOr, LOAD};
use super::slide::{jobs as jobs_flag, seeds as seeds_flag};
use crate::plot::friction::friction_png;
use crate::runs::sink::csv_bytes;
use crate::runs::{
    output::check_outputs, output::Outputs, progress::Progress, progress::Reporter, shard::Shard,
};
use crate::study::batch::{run_part, summary_inputs, BatchOptions};
use crate::study::campaign::{figure_rows, study_times, CampaignParams, Fig, STUDY_LOADS_MN};
use crate::study::dem_run::ModelSpec;
use anyhow::{bail, Result};
use std::path::{Path, PathBuf};
use surrogate::units::us_to_s;

/// Options of the friction campaign (`figures --friction`).
#[derive(clap::Args, Debug, Default)]
#[command(
    mut_args(help(
        LOAD,
        "Loads in mN, a list or range [default: the study's 11, 0.35:3.5:0.35 and 3.86]"
    )),
    mut_args(with(LOAD, |a| a.requires("friction")))
)]
pub struct CampaignArgs {
    /// Run the study's friction campaign (DEM slides: friction force and μ versus load for Figs
    /// 2b, 6, 7) instead of the screening figures; default `--out-dir figures/friction`. Resumable
    /// (a rerun runs only the missing runs) and shardable (`--shard`).
    #[arg(long)]
    pub friction: bool,
    /// Only these friction figures (comma-separated: 2b, 6, 7) [default: all].
    #[arg(long, value_enum, value_delimiter = ',', requires = "friction")]
    pub fig: Vec<Fig>,
    /// Seeds of the σ_h > 0 series (Fig 7), a list or range [default: 1,2,3]; mean ± sample
    /// standard deviation over them.
    #[arg(
        long,
        value_name = "LIST",
        requires = "friction",
        allow_hyphen_values = true
    )]
    pub seeds: Option<String>,
    /// `--load-mn`: loads, a list or range (mN).
    #[command(flatten)]
    pub load: LoadsOr,
    /// DEM runs side by side, one thread each (≥ 1) [default: the available cores].
    #[arg(
        long,
        value_name = "N",
        requires = "friction",
        allow_negative_numbers = true
    )]
    pub jobs: Option<i64>,
    /// Run only shard I of N of the campaign's run list (zero-based; contiguous blocks), into
    /// the same `--out-dir` (or one per machine, copied together afterwards); the call that
    /// finds every run finished draws the figures.
    #[arg(
        long,
        value_name = "I/N",
        requires = "friction",
        allow_hyphen_values = true
    )]
    pub shard: Option<String>,
    /// DEM model [default: reduced: rigid-z, measured against the full model in
    /// docs/validation/dem-engine.md "Model choice"; `auto` runs the full model near coating
    /// failure, at the cost per run given in docs/commands/figures.md].
    #[arg(long, value_enum, requires = "friction")]
    pub model: Option<ModelArg>,
    /// Equilibration time in µs [default: the study's 10].
    #[arg(
        long = "equilibrate-us",
        value_name = "US",
        requires = "friction",
        allow_hyphen_values = true
    )]
    pub equilibrate_us: Option<f64>,
    /// Relaxation time in µs [default: the study's 10].
    #[arg(
        long = "relax-us",
        value_name = "US",
        requires = "friction",
        allow_hyphen_values = true
    )]
    pub relax_us: Option<f64>,
    /// Sliding time in µs [default: the study's 300]; friction over its last 2/3.
    #[arg(
        long = "slide-us",
        value_name = "US",
        requires = "friction",
        allow_hyphen_values = true
    )]
    pub slide_us: Option<f64>,
    /// Support speed in m/s [default: the study's 0.1].
    #[arg(
        long = "speed-m-s",
        value_name = "M_S",
        requires = "friction",
        allow_hyphen_values = true
    )]
    pub speed_m_s: Option<f64>,
    /// Time step in µs [default: 0.25 × each run's estimated stable step].
    #[arg(
        long = "dt-us",
        value_name = "US",
        requires = "friction",
        allow_hyphen_values = true
    )]
    pub dt_us: Option<f64>,
    /// Steps between checkpoints of a run (an interrupted run resumes from its last one).
    #[arg(long = "checkpoint-every", value_name = "STEPS", requires = "friction")]
    pub checkpoint_every: Option<u64>,
    /// Test scene: slider radius in µm instead of the study's (with `--substrate-um`).
    #[arg(
        long = "slider-radius-um",
        value_name = "UM",
        hide = true,
        requires = "substrate_um",
        allow_hyphen_values = true
    )]
    pub slider_radius_um: Option<f64>,
    /// Test scene: substrate size in µm `LXxLY` instead of the study's 364x270.
    #[arg(
        long = "substrate-um",
        value_name = "LXxLY",
        hide = true,
        requires = "slider_radius_um"
    )]
    pub substrate_um: Option<String>,
}

impl CampaignArgs {
    /// The campaign's parameters; every flag checked, naming it.
    fn params(&self) -> Result<CampaignParams> {
        let figs = if self.fig.is_empty() {
            vec![Fig::F2b, Fig::F6, Fig::F7]
        } else {
            let mut f = self.fig.clone();
            f.dedup();
            f
        };
        let loads_mn = self.load.mn_or(&STUDY_LOADS_MN)?;
        let seeds = seeds_flag(self.seeds.as_deref().unwrap_or("1,2,3"))?;
        let mut seen = seeds.clone();
        seen.sort();
        seen.dedup();
        if seen.len() != seeds.len() {
            bail!("`--seeds`: a seed is given twice");
        }
        let st = study_times();
        let time = |v: Option<f64>, flag: &str, default: f64, zero_ok: bool| -> Result<f64> {
            match v {
                None => Ok(default),
                Some(v) if v.is_finite() && (v > 0.0 || (zero_ok && v == 0.0)) => Ok(us_to_s(v)),
                Some(v) => bail!(
                    "`{flag}`: {v} must be a {} time in µs",
                    if zero_ok { "non-negative" } else { "positive" }
                ),
            }
        };
        let times = [
            time(self.equilibrate_us, "--equilibrate-us", st[0], false)?,
            time(self.relax_us, "--relax-us", st[1], true)?,
            time(self.slide_us, "--slide-us", st[2], false)?,
        ];
        let speed = match self.speed_m_s {
            None => 0.1,
            Some(v) => checks::positive(v, "--speed-m-s")?,
        };
        let dt = self
            .dt_us
            .map(|d| checks::time_us(d, "--dt-us"))
            .transpose()?;
        let checkpoint_every = checks::every(
            self.checkpoint_every.unwrap_or(100_000),
            "--checkpoint-every",
            "checkpoint",
        )?;
        let small_scene = match (&self.slider_radius_um, &self.substrate_um) {
            (Some(r), Some(s)) => {
                let parts: Vec<&str> = s.split(['x', 'X']).collect();
                let num = |t: &str| -> Result<f64> {
                    t.trim()
                        .parse()
                        .map_err(|_| anyhow::anyhow!("`--substrate-um`: `{t}` is not a number"))
                };
                if parts.len() != 2 {
                    bail!("`--substrate-um`: `{s}` must be LXxLY, e.g. 60x40");
                }
                Some((
                    checks::positive(*r, "--slider-radius-um")?,
                    [num(parts[0])?, num(parts[1])?],
                ))
            }
            _ => None,
        };
        Ok(CampaignParams {
            figs,
            loads_mn,
            seeds,
            times,
            speed,
            dt,
            model: ModelSpec {
                request: self.model.unwrap_or(ModelArg::Reduced).request(),
                force_rigid_z: false,
                active_set: true,
            },
            checkpoint_every,
            small_scene,
        })
    }
}

/// Runs the campaign into `dir` (see the module docs).
pub fn run(dir: &Path, a: &CampaignArgs) -> Result<()> {
    let params = a.params()?;
    let side_by_side = jobs_flag(a.jobs)?;
    let plan = params.plan()?;
    let n = plan.jobs.len();
    let shard = a
        .shard
        .as_deref()
        .map(|s| Shard::parse(s, "--shard"))
        .transpose()?
        .unwrap_or(Shard::ALL);
    if shard.count > n {
        bail!(
            "`--shard`: {} shards for {n} runs; give at most {n} shards",
            shard.count
        );
    }
    check_outputs(&[("--out-dir", Some(&dir.join("runs.csv")))])?;
    let rep = Reporter::stderr();
    rep.note(&format!(
        "friction campaign: figures {}, {} loads, seeds {:?} for σ_h > 0, model {} — {n} runs into {}",
        params
            .figs
            .iter()
            .map(|f| f.stem().trim_start_matches("friction_fig"))
            .collect::<Vec<_>>()
            .join(", "),
        params.loads_mn.len(),
        params.seeds,
        params.model.request.name(),
        dir.join("runs").display()
    ));
    let opts = BatchOptions {
        side_by_side,
        stage: "friction campaign".into(),
        run_notes: false,
    };
    let (rows, missing) = run_part(&plan.jobs, shard.range(n), &opts, &dir.join("runs"), &rep)?;
    if missing > 0 {
        rep.note(&format!(
            "{missing} of {n} runs not finished yet (other shards, or an interrupted call): the figures are drawn by the call that finds every run finished — run the same command without --shard once the shards are done (it runs whatever is left, then draws)"
        ));
        return Ok(());
    }
    let record = serde_json::json!({
        "figures": params.figs.iter().map(|f| f.stem()).collect::<Vec<_>>(),
        "loads_mN": params.loads_mn,
        "seeds": params.seeds,
        "model": params.model.request.name(),
    });
    let mut outs = Outputs::new(
        summary_inputs("friction campaign", &plan.jobs, record),
        vec![],
    );
    outs.write(
        "--out-dir",
        Some(&dir.join("runs.csv")),
        csv_bytes(&rows),
        Some(rows.len() as u64),
    );
    for (fig, series) in &plan.figs {
        let frows = figure_rows(series, &rows);
        let base = dir.join(fig.stem());
        let (csv, png) = (with_ext(&base, "csv"), with_ext(&base, "png"));
        outs.write(
            "--out-dir",
            Some(&csv),
            csv_bytes(&frows),
            Some(frows.len() as u64),
        );
        outs.attempt("--out-dir", &png, || {
            friction_png(&png, fig.title(), &frows)
        });
        rep.note(&format!("wrote {} and {}", png.display(), csv.display()));
    }
    let failed: Vec<&str> = rows
        .iter()
        .filter(|r| r.status == crate::study::rows::RunStatus::Failed)
        .map(|r| r.name.as_str())
        .collect();
    if !failed.is_empty() {
        rep.note(&format!(
            "warning: {} of {n} runs failed (left out of the means; status and error in runs.csv): {}",
            failed.len(),
            failed.join(", ")
        ));
    }
    outs.finish()
}

/// `base` + `.ext` (keeps dots in the stem).
fn with_ext(base: &Path, ext: &str) -> PathBuf {
    let mut s = base.as_os_str().to_owned();
    s.push(".");
    s.push(ext);
    PathBuf::from(s)
}
