//! `superlube slide`: flags → [`crate::study::slide::slide`] → time series, summary, sidecars;
//! with lists of θ, α, W or seeds (or `--out-dir`), a batch through [`crate::study::batch`]:
//! `DIR/runs/<name>/` per run, `DIR/runs.csv` and, with several seeds, `DIR/seeds.csv`.

use super::dem_args::DemArgs;
use super::parse_list_or_range;
use super::protocol_args::ProtocolArgs;
use crate::runs::sink::csv_bytes;
use crate::runs::{
    output::check_outputs, output::Outputs, progress::Progress, progress::Reporter, shard::Shard,
};
use crate::study::batch::{run_name, run_part, summary_inputs, BatchOptions, SlideJob};
use crate::study::rows::{BatchRow, ConfigStatsRow};
use crate::study::slide::slide;
use anyhow::{bail, Result};
use std::path::{Path, PathBuf};

/// Options of `superlube slide`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    dem: DemArgs,
    #[command(flatten)]
    protocol: ProtocolArgs,
    /// Seeds of the substrate heights (σ_h > 0 needed), a list `1,2,3` or a range `1:5:1`: one
    /// run per seed, and `DIR/seeds.csv` with mean, spread, min and max per configuration.
    /// Replaces `--seed`.
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    seeds: Option<String>,
    /// Batch output directory: `DIR/runs/<name>/` per run (slide.csv, slide.json or
    /// failed.json, sidecars, checkpoint while running), `DIR/runs.csv` (one row per run) and
    /// `DIR/seeds.csv` with several seeds. Needed when a list is given; a rerun reuses the
    /// finished runs and resumes an interrupted one.
    #[arg(long = "out-dir", value_name = "DIR")]
    out_dir: Option<PathBuf>,
    /// Runs side by side in a batch, one thread each (≥ 1) [default: the available cores].
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    jobs: Option<i64>,
    /// Run only shard I of N of the batch's runs (zero-based; contiguous blocks in run order);
    /// every shard writes into the same `--out-dir`, and the call that finds every run finished
    /// writes runs.csv (a final call without `--shard` does, running whatever is left).
    #[arg(long, value_name = "I/N", allow_hyphen_values = true)]
    shard: Option<String>,
}

/// `--jobs` (≥ 1; default the available cores).
pub fn jobs(v: Option<i64>) -> Result<usize> {
    match v {
        None => Ok(std::thread::available_parallelism().map_or(1, |n| n.get())),
        Some(n) if n >= 1 => Ok(n as usize),
        Some(n) => bail!("`--jobs`: {n} runs side by side; give at least 1"),
    }
}

/// `--seeds`: whole numbers ≥ 0.
pub fn seeds(text: &str) -> Result<Vec<u64>> {
    let v = parse_list_or_range(text, "--seeds")?;
    v.into_iter()
        .map(|s| {
            if s >= 0.0 && s.fract() == 0.0 && s < 1.8e19 {
                Ok(s as u64)
            } else {
                bail!("`--seeds`: {s} is not a whole number ≥ 0")
            }
        })
        .collect()
}

/// Runs `superlube slide`.
pub fn run(a: Args) -> Result<()> {
    a.protocol.check(true)?;
    let (thetas, alphas, loads) = a.dem.lists()?;
    let seed_list = a.seeds.as_deref().map(seeds).transpose()?;
    let side_by_side = jobs(a.jobs)?;
    let batch = a.out_dir.is_some()
        || thetas.len() > 1
        || alphas.len() > 1
        || loads.len() > 1
        || seed_list.as_ref().is_some_and(|s| s.len() > 1);
    if !batch {
        if a.shard.is_some() {
            bail!("`--shard` splits a batch: give `--out-dir DIR`");
        }
        let mut a = a;
        if let Some(s) = seed_list {
            if a.dem.scene.overrides.seed.is_some() {
                bail!("`--seeds` replaces `--seed`: give one of them");
            }
            a.dem.scene.overrides.seed = s.first().copied();
        }
        let (sc, params) = a.dem.setup(&a.protocol)?;
        let rep = Reporter::stderr();
        sc.log(&rep);
        let outs = a.dem.outputs("slide", &sc, &params);
        let (out, report) = slide(&sc.scene, &params, &rep)?;
        return a.dem.write(outs, out, report.as_ref());
    }
    run_batch_command(a, thetas, alphas, loads, seed_list, side_by_side)
}

/// The batch: every check before any work, then the shard's runs, then the summary files.
fn run_batch_command(
    a: Args,
    thetas: Vec<Option<f64>>,
    alphas: Vec<f64>,
    loads: Vec<f64>,
    seed_list: Option<Vec<u64>>,
    side_by_side: usize,
) -> Result<()> {
    let Some(dir) = a.out_dir.clone() else {
        bail!("lists in `--theta-deg`, `--alpha-deg`, `--load-mn` or `--seeds` run a batch: give `--out-dir DIR` for its files");
    };
    for (given, flag) in [
        (a.dem.out.is_some(), "--out"),
        (a.dem.json.is_some(), "--json"),
        (a.dem.checkpoint.is_some(), "--checkpoint"),
        (a.dem.resume, "--resume"),
        (a.dem.xyz.is_some(), "--xyz"),
    ] {
        if given {
            bail!("`{flag}` is for a single run; a batch writes each run's files under `--out-dir DIR`/runs/<name>/ and resumes by rerunning the same command");
        }
    }
    if seed_list.is_some() && a.dem.scene.overrides.seed.is_some() {
        bail!("`--seeds` replaces `--seed`: give one of them");
    }
    let shard = a
        .shard
        .as_deref()
        .map(|s| Shard::parse(s, "--shard"))
        .transpose()?
        .unwrap_or(Shard::ALL);
    check_outputs(&[("--out-dir", Some(&dir.join("runs.csv")))])?;
    // the jobs, θ outer, then α, W, seed
    let mut jobs = Vec::new();
    let mut warnings = Vec::new();
    let seeds: Vec<Option<u64>> = match &seed_list {
        None => vec![None],
        Some(s) => s.iter().map(|&s| Some(s)).collect(),
    };
    for &t in &thetas {
        for &al in &alphas {
            for &w in &loads {
                for &seed in &seeds {
                    let mut sa = a.dem.scene.clone();
                    if seed.is_some() {
                        sa.overrides.seed = seed;
                    }
                    let sc = sa.resolve(t)?;
                    a.dem.check_line(&sc.scene)?;
                    if seeds.len() > 1 && sc.scene.substrate.sigma_h == 0.0 {
                        bail!("`--seeds`: σ_h = 0, so every seed gives the same substrate (and the same run); give `--sigma-h-um` (e.g. 0.002) or a single seed");
                    }
                    for w in &sc.warnings {
                        if !warnings.contains(w) {
                            warnings.push(w.clone());
                        }
                    }
                    let params = a.dem.params(al, w, &a.protocol)?;
                    jobs.push(SlideJob {
                        name: run_name(&sc.scene, &params),
                        scene: sc.scene,
                        params,
                    });
                }
            }
        }
    }
    if shard.count > jobs.len() {
        bail!(
            "`--shard`: {} shards for {} runs; give at most {} shards",
            shard.count,
            jobs.len(),
            jobs.len()
        );
    }
    let rep = Reporter::stderr();
    for w in &warnings {
        rep.note(&format!("warning: {w}"));
    }
    let opts = BatchOptions {
        side_by_side,
        stage: "slide batch".into(),
        run_notes: true,
    };
    let runs_dir = dir.join("runs");
    let (rows, missing) = run_part(&jobs, shard.range(jobs.len()), &opts, &runs_dir, &rep)?;
    let groups = seed_list.as_ref().map(|_| seed_groups(&rows));
    write_summary(
        &dir,
        &jobs,
        &rows,
        missing,
        groups.as_deref(),
        warnings,
        &rep,
    )
}

/// The configurations of `rows` (same inputs but the seed), each with its label and row
/// indices, in first-appearance order.
fn seed_groups(rows: &[BatchRow]) -> Vec<(String, Vec<usize>)> {
    let mut groups: Vec<(String, Vec<usize>)> = Vec::new();
    for (k, r) in rows.iter().enumerate() {
        let key = format!(
            "{} θ={}° α={}° W={} mN σ_h={} µm E={} GPa",
            r.pattern, r.theta_deg, r.alpha_deg, r.load_mN, r.sigma_h_um, r.youngs_GPa
        );
        match groups.iter_mut().find(|g| g.0 == key) {
            Some(g) => g.1.push(k),
            None => groups.push((key, vec![k])),
        }
    }
    groups
}

/// Writes `dir/runs.csv` (and `dir/seeds.csv` for `groups`) when no run is missing; otherwise
/// says how many are and writes nothing.
fn write_summary(
    dir: &Path,
    jobs: &[SlideJob],
    rows: &[BatchRow],
    missing: usize,
    groups: Option<&[(String, Vec<usize>)]>,
    warnings: Vec<String>,
    rep: &dyn Progress,
) -> Result<()> {
    let failed = rows
        .iter()
        .filter(|r| r.status == crate::study::rows::RunStatus::Failed)
        .count();
    if missing > 0 {
        rep.note(&format!(
            "{missing} of {} runs not finished yet (other shards, or an interrupted call): runs.csv is written by the call that finds every run finished — run the same command without --shard (it runs what is left) once the shards are done",
            rows.len()
        ));
        return Ok(());
    }
    let mut outs = Outputs::new(
        summary_inputs("slide batch", jobs, serde_json::Value::Null),
        warnings,
    );
    outs.write(
        "--out-dir",
        Some(&dir.join("runs.csv")),
        csv_bytes(rows),
        Some(rows.len() as u64),
    );
    if let Some(g) = groups {
        let stats: Vec<ConfigStatsRow> = g
            .iter()
            .map(|(label, ix)| {
                let rs: Vec<&BatchRow> = ix.iter().map(|&k| &rows[k]).collect();
                ConfigStatsRow::new(label, &rs)
            })
            .collect();
        outs.write(
            "--out-dir",
            Some(&dir.join("seeds.csv")),
            csv_bytes(&stats),
            Some(stats.len() as u64),
        );
    }
    rep.note(&format!(
        "batch: {} runs, {} ok, {failed} failed; wrote {}",
        rows.len(),
        rows.len() - failed,
        dir.join("runs.csv").display()
    ));
    outs.finish()?;
    if failed > 0 {
        bail!(
            "{failed} of {} runs failed (status and error in runs.csv); the others finished",
            rows.len()
        );
    }
    Ok(())
}
