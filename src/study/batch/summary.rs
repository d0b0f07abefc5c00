//! What a batch adds up to: the rows of `runs.csv`, the inputs of its summary files, and a
//! shard's part of a batch.

use super::job::{job_inputs, run_facts, BatchOptions, RunFacts, SlideJob, SlideOutcome};
use super::run::{finished_runs, run_batch_with};
use crate::runs::meta::Inputs;
use crate::runs::progress::Progress;
use crate::study::rows::BatchRow;
use anyhow::Result;
use std::path::Path;

/// The rows of `runs.csv` for `jobs`, from their outcomes (`None`: not run yet), in order.
pub fn batch_rows(jobs: &[SlideJob], outcomes: &[Option<SlideOutcome>]) -> Vec<BatchRow> {
    jobs.iter()
        .zip(outcomes)
        .map(|(j, o)| {
            let facts = o.as_ref().and_then(run_facts);
            BatchRow::new(j, o.as_ref(), facts.as_ref())
        })
        .collect()
}

/// The inputs of a batch's summary files: the run names and each run's input hash (the same
/// for a sharded and an unsharded batch).
pub fn summary_inputs(workflow: &str, jobs: &[SlideJob], extra: serde_json::Value) -> Inputs {
    let runs: Vec<serde_json::Value> = jobs
        .iter()
        .map(|j| serde_json::json!({"name": j.name, "input_hash": job_inputs(j).hash()}))
        .collect();
    Inputs {
        workflow: workflow.into(),
        scene: None,
        params: serde_json::json!({"runs": runs, "batch": extra}),
    }
}

/// A shard's part of a batch and what is left: runs the jobs `range` (with `opts`) after
/// checking every job's earlier files (errors before any work), then reads back every job's
/// outcome. Returns the rows of all jobs in order and the number still missing (other shards).
pub fn run_part(
    jobs: &[SlideJob],
    range: std::ops::Range<usize>,
    opts: &BatchOptions,
    dir: &Path,
    progress: &dyn Progress,
) -> Result<(Vec<BatchRow>, usize)> {
    let before = finished_runs(jobs, dir)?;
    let done = before.iter().filter(|o| o.is_some()).count();
    let todo_here = range.clone().filter(|&k| before[k].is_none()).count();
    progress.note(&format!(
        "{} runs in all, {} finished earlier (reused, not rerun); this call runs {} of runs {}..{} ({} side by side)",
        jobs.len(),
        done,
        todo_here,
        range.start,
        range.end,
        opts.side_by_side.min(todo_here.max(1))
    ));
    run_batch_with(&jobs[range], opts, dir, progress)?;
    let after = finished_runs(jobs, dir)?;
    let missing = after.iter().filter(|o| o.is_none()).count();
    Ok((batch_rows(jobs, &after), missing))
}

impl BatchRow {
    /// The row of `job` with its outcome (`None`: not run yet) and the model facts of its
    /// summary.
    pub fn new(job: &SlideJob, o: Option<&SlideOutcome>, facts: Option<&RunFacts>) -> BatchRow {
        use crate::study::rows::{label, RunStatus};
        use surrogate::units::{m_to_um, n_to_mn, pa_to_gpa, rad_to_deg, s_to_us};
        let (s, p) = (&job.scene, &job.params.sim);
        let r = o.and_then(|o| o.result.as_ref());
        let (status, error) = match o {
            None => (
                RunStatus::Missing,
                "not run yet (another shard's run, or an interrupted batch)".to_string(),
            ),
            Some(o) => match (&o.result, &o.error) {
                (Some(_), _) => (RunStatus::Ok, String::new()),
                (None, e) => (
                    RunStatus::Failed,
                    e.clone().unwrap_or_else(|| "no result".to_string()),
                ),
            },
        };
        BatchRow {
            name: job.name.clone(),
            pattern: s.pattern.clone(),
            theta_deg: label(rad_to_deg(s.slider.theta)),
            alpha_deg: label(rad_to_deg(job.params.alpha)),
            load_mN: label(n_to_mn(p.protocol.load)),
            sigma_h_um: label(m_to_um(s.substrate.sigma_h)),
            seed: s.substrate.seed,
            youngs_GPa: label(pa_to_gpa(s.slider_material().youngs)),
            p_crit_GPa: label(pa_to_gpa(s.coating.p_crit)),
            mu1: s.coating.mu1,
            mu2: s.coating.mu2,
            mu_constant: match &job.params.friction {
                Some(dem::model::Friction::Constant(c)) => Some(c.mu),
                _ => None,
            },
            mount: s.slider.mount.name().to_string(),
            model_requested: job.params.model.request.name().to_string(),
            model: facts.map(|f| f.model.clone()).unwrap_or_default(),
            rigid_z: facts.map(|f| f.rigid_z),
            equilibrate_us: label(s_to_us(p.protocol.equilibrate_time)),
            relax_us: label(s_to_us(p.protocol.relax_time)),
            slide_us: label(s_to_us(p.protocol.slide_time)),
            speed_m_s: p.protocol.support_speed,
            dt_us: facts
                .map(|f| f.dt_us)
                .or(p.numerics.dt.map(|d| label(s_to_us(d)))),
            friction_mN: r.map(|r| r.friction_mN),
            friction_std_mN: r.map(|r| r.friction_std_mN),
            mu: r.map(|r| r.mu),
            mean_contacts: r.map(|r| r.mean_contacts),
            max_p_max_GPa: r.map(|r| r.max_p_max_GPa),
            mean_failed_contacts: r.map(|r| r.mean_failed_contacts),
            locked_in: r.map(|r| r.locked_in),
            advance_ratio: r.and_then(|r| r.advance_ratio),
            steps: r.map(|r| r.steps),
            wall_s: r.map(|r| r.wall_s),
            status,
            error,
        }
    }
}
