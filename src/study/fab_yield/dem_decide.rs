//! The DEM runs of a yield ([`DemDecider`]): one DEM `slide` run of one device at one load,
//! with the design's protocol and model choice (the design's `--dem-model`; `auto` where the
//! device's estimate lies in the springs mount's resonance band, as the design does for a
//! recipe outside the validated range; judged at the run's load,
//! [`super::CriticalLoad::resonant_at`]), on its own substrate, θ and pull direction. Its
//! verdict is [`dem_superlubric`]; its P_max and μ are kept beside it ([`DemRun`]) for the
//! design's band ([`super::calibration`]). Which devices run at which loads is
//! [`super::rounds`]'s choice.
//!
//! The runs go through the batch runner ([`crate::study::batch`]): side by side, one thread
//! each, reused by their input hash (a re-run costs nothing), each in `dir/<name>/`.

use super::device::DemRun;
use super::fabrication::Sample;
use crate::runs::progress::Progress;
use crate::study::batch::{self, run_batch_with, BatchOptions, SlideJob};
use crate::study::corrugation::contact_line;
use crate::study::dem_run::DemParams;
use crate::study::rows::label;
use crate::study::verdict::dem_superlubric;
use anyhow::Result;
use std::path::PathBuf;
use surrogate::units::{deg_to_rad, n_to_mn, rad_to_deg};
use surrogate::Scene;

/// The DEM of a yield.
#[derive(Debug, Clone)]
pub struct YieldDem {
    /// The protocol and model of every run (load, α and line are set per run).
    pub params: DemParams,
    /// Fresh devices run with the DEM for the check (0: no check).
    pub check: usize,
    /// Load (N) of the check; `None`: the estimate's quote.
    pub check_load: Option<f64>,
    /// Runs side by side (one thread each).
    pub jobs: usize,
    /// Folder of the runs.
    pub dir: PathBuf,
    /// Most DEM runs for one yield, the check's included ([`DEFAULT_MAX_RUNS`]).
    pub max_runs: usize,
}

/// The default most DEM runs of one yield, the check's included.
pub const DEFAULT_MAX_RUNS: usize = 40;

impl YieldDem {
    /// The DEM of a yield: runs with `params` (load, α and line set per run), `check` fresh
    /// devices at `check_load` (N; `None`: the estimate's quote), at most `max_runs` runs (the
    /// check's included; see [`YieldDem::runs_hold_check`]), `jobs` side by side in `dir`.
    /// The one constructor of `superlube yield` and the design's yield stage.
    pub fn new(
        params: DemParams,
        (check, check_load): (usize, Option<f64>),
        max_runs: usize,
        jobs: usize,
        dir: PathBuf,
    ) -> YieldDem {
        YieldDem {
            params,
            check,
            check_load,
            jobs,
            dir,
            max_runs,
        }
    }

    /// Whether `max_runs` DEM runs can hold a check of `check` devices (and at least one run):
    /// the one rule behind `yield --dem-max-runs` and `design --yield-dem-max-runs`.
    pub fn runs_hold_check(max_runs: usize, check: usize) -> bool {
        max_runs >= check.max(1)
    }
}

/// One DEM run's record and, when it was not superlubric, why.
#[derive(Debug, Clone)]
pub struct Decision {
    /// The run.
    pub run: DemRun,
    /// Why not superlubric (empty when it was).
    pub why: String,
}

/// One DEM run asked for: a device at a load (N).
pub struct Ask<'a> {
    /// The device.
    pub sample: &'a Sample,
    /// Load (N).
    pub load: f64,
    /// Whether its estimate at `load` has failing contacts on the mount's resonance (the DEM
    /// then chooses its model itself).
    pub mount_resonance: bool,
}

/// Runs DEM decisions for one design (scene, nominal θ and direction, degrees).
pub struct DemDecider<'a> {
    /// The design's scene (SI).
    pub scene: &'a Scene,
    /// Nominal θ (degrees).
    pub theta_deg: f64,
    /// Nominal pull direction from the substrate's x axis (degrees).
    pub direction_deg: f64,
    /// μ_sl of the verdict.
    pub mu_superlubric: f64,
    /// The DEM's settings.
    pub dem: &'a YieldDem,
}

impl DemDecider<'_> {
    /// The slide job of `ask`: the device's scene at θ + δθ, pulled along d + δd from the
    /// substrate's x axis (α measured from the device's own contact line).
    pub fn job(&self, ask: &Ask) -> SlideJob {
        let s = ask.sample;
        let theta = label(self.theta_deg + s.theta_offset_deg);
        let direction = label(self.direction_deg + s.direction_offset_deg);
        let scene = s.scene(self.scene).with_theta(deg_to_rad(theta));
        let line = contact_line(&scene, self.dem.params.line);
        let alpha = label(direction - rad_to_deg(line.angle));
        let mut d = self.dem.params.clone();
        d.sim.protocol.load = ask.load;
        d.alpha = deg_to_rad(alpha);
        if ask.mount_resonance && d.model.request == dem::ModelRequest::Reduced {
            d.model.request = dem::ModelRequest::Auto;
        }
        SlideJob {
            name: format!("s{}_{}", s.index, batch::run_name(&scene, &d)),
            scene,
            params: d,
        }
    }

    /// Runs `asks` side by side under the stage `stage` and returns each one's decision, in
    /// order. Cost: one DEM run each (1–3 s with the design's protocol), none where reused.
    pub fn run(&self, asks: &[Ask], stage: &str, progress: &dyn Progress) -> Result<Vec<Decision>> {
        if asks.is_empty() {
            return Ok(Vec::new());
        }
        let jobs: Vec<SlideJob> = asks.iter().map(|a| self.job(a)).collect();
        let out = run_batch_with(
            &jobs,
            &BatchOptions {
                side_by_side: self.dem.jobs.max(1),
                stage: stage.into(),
                run_notes: false,
            },
            &self.dem.dir,
            progress,
        )?;
        Ok(asks
            .iter()
            .zip(&out)
            .map(|(a, o)| {
                let v = dem_superlubric(
                    o.result.as_ref(),
                    o.error.as_deref(),
                    label(n_to_mn(a.load)),
                    a.sample.p_crit,
                    self.mu_superlubric,
                );
                let r = o.result.as_ref();
                Decision {
                    run: DemRun {
                        load: a.load,
                        superlubric: v.is_ok(),
                        p_max_GPa: r.map(|r| r.max_p_max_GPa).filter(|p| p.is_finite()),
                        mu: r
                            .filter(|r| !r.locked_in)
                            .map(|r| r.mu)
                            .filter(|m| m.is_finite()),
                    },
                    why: v.err().unwrap_or_default(),
                }
            })
            .collect())
    }
}
