//! The screen workflow: contacts, P_max, height and coating failure for every orientation θ ×
//! load W of one scene, streamed row by row in a fixed order (θ outer, W inner).
//!
//! Parallel over a bounded window of θ ([`window`] θ at a time, each θ solving all loads on one
//! shared pair list); the window's rows are pushed in order before the next window starts, so the
//! output is the same whatever the thread count and memory does not grow with the sweep.

use super::rows::ScreenRow;
use crate::runs::budget::Estimate;
use crate::runs::progress::Progress;
use crate::runs::sink::RowSink;
use anyhow::{bail, Result};
use rayon::prelude::*;
use surrogate::solver::{Model, Pose, SearchKind, Solver};
use surrogate::Scene;

/// Parameters of a screen (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct ScreenParams {
    /// Slider orientations θ (rad), in output order.
    pub thetas: Vec<f64>,
    /// Normal loads W (N), each > 0, in output order within a θ.
    pub loads: Vec<f64>,
    /// Load-sharing model.
    pub model: Model,
    /// Candidate pair search.
    pub search: SearchKind,
}

/// What a finished screen reports besides its rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ScreenStats {
    /// Rows written.
    pub rows: u64,
    /// Rows without an equilibrium (their `error` column says why).
    pub failures: u64,
}

/// θ values solved in parallel before their rows are written: 8 per thread (enough to keep the
/// threads busy, small enough that a window's rows take no noticeable memory).
pub fn window() -> usize {
    8 * rayon::current_num_threads().max(1)
}

/// Cost estimate of the screen (for the size guard).
pub fn estimate(scene: &Scene, p: &ScreenParams) -> Estimate {
    Estimate::solves(
        &format!(
            "{} × {}",
            crate::study::input::Input::Theta,
            crate::study::input::Input::LoadMn
        ),
        (p.thetas.len() as u64).saturating_mul(p.loads.len() as u64),
        scene.slider_sites_local().len(),
        scene.substrate_spheres().len(),
        0.0,
        150.0,
    )
}

/// Runs the screen of `scene` (its θ is replaced by each of `p.thetas`), pushing one
/// [`ScreenRow`] per (θ, W) into `rows` in order. Errors: a scene the solver refuses, a failing
/// sink, or no configuration with an equilibrium at all.
pub fn screen(
    scene: &Scene,
    p: &ScreenParams,
    rows: &mut dyn RowSink<ScreenRow>,
    progress: &dyn Progress,
) -> Result<ScreenStats> {
    if p.loads.is_empty() || p.thetas.is_empty() {
        bail!("a screen needs at least one θ and one load");
    }
    if p.model == Model::RigidTilt && !scene.slider.mount.tilts() {
        use crate::study::input::Input;
        bail!(
            "{}: rigid-tilt solves for the slider's tilt, and the mount is locked ({} locked, or the scene file's slider.tilt = \"locked\"): use rigid-z (exact for a locked mount) or auto, or a mount that tilts ({} free or springs)",
            Input::Solver,
            Input::Tilt,
            Input::Tilt
        );
    }
    let mut solver = Solver::new(scene)?;
    solver
        .check_model(p.model)
        .map_err(|e| anyhow::anyhow!("{}: {e}", crate::study::input::Input::Solver))?;
    solver.search = p.search;
    let mut stats = ScreenStats::default();
    progress.stage("screen", p.thetas.len() as u64, "θ");
    for chunk in p.thetas.chunks(window()) {
        let done: Vec<Vec<ScreenRow>> = chunk
            .par_iter()
            .map(|&theta| {
                let pose = Pose {
                    theta,
                    shift: [0.0, 0.0],
                };
                let rs = solver.solve_loads(pose, &p.loads, p.model);
                progress.advance(1);
                p.loads
                    .iter()
                    .zip(&rs)
                    .map(|(&w, r)| ScreenRow::new(&scene.pattern, theta, w, r, p.model))
                    .collect()
            })
            .collect();
        for r in done.iter().flatten() {
            stats.rows += 1;
            stats.failures += !r.error.is_empty() as u64;
            rows.push(r)?;
        }
    }
    progress.finish();
    if stats.failures > 0 {
        progress.note(&format!(
            "warning: {} of {} configurations have no equilibrium (see the `error` column)",
            stats.failures, stats.rows
        ));
    }
    Ok(stats)
}
