//! Stage 6 of a design, the DEM confirmation ([`ConfirmStage`], its knobs [`ConfirmParams`]):
//! the batch of independent `slide` runs of the top designs side by side, then — when the
//! confirmation protocol is shorter than the study's — the study's protocol once on the design
//! the report recommends ([`protocol_check_design`]). The runs go through a [`DemRunner`]
//! (the study layer's batch runner in a design, [`BatchRunner`]).

use super::estimates::confirm_estimates;
use super::jobs::{confirm_jobs, design_dem_params, run_name, to_entries};
use super::params::ConfirmParams;
use super::protocol_check::{protocol_check_design, ProtocolCheck};
#[cfg(doc)]
use super::runner::BatchRunner;
use super::runner::DemRunner;
use crate::study::batch::{SlideJob, SlideOutcome};
use crate::study::design::model::answer::{answer, Answer};
use crate::study::design::model::{ConfirmEntry, DemEntry, DemProtocol, PatternResult};
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use anyhow::Result;
use std::path::Path;
use surrogate::units::deg_to_rad;

/// Stage 6 of a design (module docs): its knobs are [`ConfirmParams`]; it reads the shared
/// limit knobs (the loads, the contact line, the tolerance box) and runs the DEM through
/// `runner`.
pub struct ConfirmStage<'a> {
    env: StageEnv<'a>,
    params: &'a ConfirmParams,
    runner: &'a dyn DemRunner,
}

impl<'a> ConfirmStage<'a> {
    /// The stage in `env` with its knobs, running the DEM through `runner`.
    pub fn new(env: StageEnv<'a>, params: &'a ConfirmParams, runner: &'a dyn DemRunner) -> Self {
        ConfirmStage {
            env,
            params,
            runner,
        }
    }

    /// The friction estimates of `pr`'s designs to confirm at the confirmation loads the
    /// evaluation did not estimate ([`confirm_estimates`]): per pattern, before its files are
    /// written. Nothing with `--no-dem`.
    pub fn estimates(&self, pr: &mut PatternResult) -> Result<()> {
        if self.params.no_dem {
            return Ok(());
        }
        confirm_estimates(pr, (self.params, self.env.limit), self.env.store)
    }

    /// The DEM runs of the top designs of `patterns` (module docs). Empty with `--no-dem`.
    pub fn run(&self, patterns: &[PatternResult]) -> Result<Vec<DemEntry>> {
        let StageEnv { store, obs, .. } = self.env;
        let cp = self.params;
        if cp.no_dem {
            return Ok(Vec::new());
        }
        let (jobs, mut entries) = confirm_jobs(patterns, cp, self.env.limit);
        if jobs.is_empty() {
            obs.event(&Event::DemNothing);
            return Ok(Vec::new());
        }
        let dir = store.path("dem");
        obs.event(&Event::DemRuns {
            runs: jobs.len(),
            side_by_side: cp.jobs.min(jobs.len()),
            dir: &dir,
        });
        let mut outcomes = self.runner.run(&jobs, cp.jobs, &dir, obs.progress())?;
        let mut dem = to_entries(&entries, &outcomes);
        if cp.protocol_check && !cp.dem_is_study_protocol {
            let rule = self.env.limit.answer_rule(cp.designs);
            let answers: Vec<Answer> = patterns
                .iter()
                .map(|pr| answer(pr, &dem, true, &rule))
                .collect();
            if let Some(check) = protocol_check_design(patterns, &answers, &cp.loads) {
                let (entry, o) = self.protocol_check(check, &dir)?;
                entries.push(entry);
                outcomes.extend(o);
                dem = to_entries(&entries, &outcomes);
            }
        }
        let reused = outcomes.iter().filter(|o| o.reused).count();
        if reused > 0 {
            obs.event(&Event::DemReused {
                reused,
                runs: outcomes.len(),
            });
        }
        Ok(dem)
    }

    /// The study protocol's run of the design the report recommends (`check`), alone on every
    /// thread, in `dir`: its entry and its outcome.
    fn protocol_check(
        &self,
        check: ProtocolCheck,
        dir: &Path,
    ) -> Result<(ConfirmEntry, Vec<SlideOutcome>)> {
        let ProtocolCheck {
            pattern: pr,
            index: i,
            load: w,
        } = check;
        let c = &pr.ranking[i];
        let job = SlideJob {
            name: run_name(
                &pr.scene.name,
                c.theta_deg,
                c.alpha_deg,
                w,
                DemProtocol::Study,
            ),
            scene: pr.scene.scene.with_theta(deg_to_rad(c.theta_deg)),
            params: design_dem_params(
                (pr, c),
                (self.params, self.env.limit.line),
                (c.alpha_deg, w),
                DemProtocol::Study,
            ),
        };
        self.env.obs.event(&Event::ProtocolCheck {
            pattern: &pr.scene.name,
            theta_deg: c.theta_deg,
            alpha_deg: c.alpha_deg,
            load: w,
        });
        let o = self
            .runner
            .run(std::slice::from_ref(&job), 1, dir, self.env.obs.progress())?;
        let entry = ConfirmEntry {
            pattern: pr.scene.name.clone(),
            rank: i + 1,
            theta_deg: c.theta_deg,
            alpha_deg: c.alpha_deg,
            load: w,
            protocol: DemProtocol::Study,
            theta_offset_deg: 0.0,
            direction_offset_deg: 0.0,
        };
        Ok((entry, o))
    }

    /// A shard of the DEM stage (`params.dem_shard` a part): its share of the runs of
    /// `patterns` into `dem/`, no report. Cost: its runs.
    pub fn shard(&self, patterns: &[PatternResult]) -> Result<()> {
        let StageEnv { store, obs, .. } = self.env;
        let cp = self.params;
        let (jobs, _) = confirm_jobs(patterns, cp, self.env.limit);
        let part = cp.dem_shard.range(jobs.len());
        let dir = store.path("dem");
        obs.event(&Event::DemShard {
            index: cp.dem_shard.index,
            count: cp.dem_shard.count,
            start: part.start,
            end: part.end,
            runs: jobs.len(),
            dir: &dir,
        });
        let dem: Vec<SlideOutcome> = if part.is_empty() {
            Vec::new()
        } else {
            self.runner
                .run(&jobs[part], cp.jobs, &dir, obs.progress())?
        };
        let failed = dem.iter().filter(|o| o.error.is_some()).count();
        if failed > 0 {
            obs.event(&Event::DemShardFailed { failed });
        }
        Ok(())
    }
}
