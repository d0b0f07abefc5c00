//! The friction workflow: the surrogate friction estimate μ_est (`surrogate::friction`) for
//! every orientation θ × pulling angle α × load W of one scene, one [`FrictionRow`] per
//! (θ, α, W), streamed in a fixed order (θ outer, α, W inner).
//!
//! The sweep's item is one (θ, α) pair, giving one row per load: the loads of an item share
//! one path, its candidate searches and its per-sample pair lists
//! ([`surrogate::friction::estimate_friction_loads`], bit-identical to one estimate per load).
//! Items run one after the other, each parallel over its path segments (rayon), so the output is
//! the same whatever the thread count. α is measured from the slider's contact line at each θ
//! (the moiré estimate, or the `line` given), as in `corrugation` and `slide`. Every row carries
//! its verdict at its own (θ, α, W) by the rule `design` applies at each sample
//! ([`crate::study::verdict::Verdict::of_row`]).

use super::corrugation::{contact_line, LineChoice};
use super::rows::FrictionRow;
use crate::runs::budget::Estimate;
use crate::runs::progress::Progress;
use crate::runs::sink::RowSink;
use anyhow::{bail, Result};
use std::ops::Range;
use surrogate::friction::{
    estimate_friction_loads, lattice_period, FrictionParams, TiltResonance, DETUNING_SIGMA_H,
    RESONANCE_DROP_MAX,
};
use surrogate::map::check_slider_stays_on_substrate;
use surrogate::solver::Solver;
use surrogate::units::m_to_nm;
use surrogate::Scene;

/// Parameters of a friction sweep (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionSweepParams {
    /// Slider orientations θ (rad), in output order.
    pub thetas: Vec<f64>,
    /// Pulling angles α (rad) from the contact line, |α| ≤ π, in output order within a θ.
    pub alphas: Vec<f64>,
    /// Normal loads W (N), each > 0, in output order within an α.
    pub loads: Vec<f64>,
    /// Contact-line angle (rad from the substrate x axis) for every θ; `None`: the moiré
    /// estimate at each θ.
    pub line: Option<f64>,
    /// The estimate's knobs (path, step, stiffnesses).
    pub knobs: FrictionParams,
    /// μ below which a row can be superlubric (study: 0.02): the threshold of each row's
    /// `verdict` ([`crate::study::verdict::Verdict::of_row`], with the scene's P_crit).
    pub mu_superlubric: f64,
}

impl FrictionSweepParams {
    /// Items of the sweep: (θ, α) pairs.
    pub fn items(&self) -> usize {
        self.thetas.len() * self.alphas.len()
    }

    /// (θ, α) of item `i` (θ outer).
    pub fn item(&self, i: usize) -> (f64, f64) {
        let na = self.alphas.len().max(1);
        (self.thetas[i / na], self.alphas[i % na])
    }

    /// Largest number of samples a path can have (the longer of the fixed length and the longest
    /// period, over the step).
    pub fn max_samples(&self) -> u64 {
        let l = self.knobs.length.max(self.knobs.max_period);
        (l / self.knobs.step - 1e-9).ceil().max(1.0) as u64 + 1
    }
}

/// What a finished friction sweep reports besides its rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FrictionStats {
    /// Rows written.
    pub rows: u64,
    /// Rows without an estimate (their `error` column says why).
    pub failures: u64,
    /// Rows whose `mount_resonance` column is true (the resonance note applies to them).
    pub resonant: u64,
}

/// Cost estimate (for the size guard): at most `max_samples` solves per (θ, α, W).
pub fn estimate(scene: &Scene, p: &FrictionSweepParams) -> Estimate {
    Estimate::solves(
        &format!(
            "{} × {} × {} × path samples",
            crate::study::input::Input::Theta,
            crate::study::input::Input::Alpha,
            crate::study::input::Input::LoadMn
        ),
        (p.items() as u64)
            .saturating_mul(p.loads.len() as u64)
            .saturating_mul(p.max_samples()),
        scene.slider_sites_local().len(),
        scene.substrate_spheres().len(),
        // one path's samples per load are held at once
        100.0 * p.max_samples() as f64 * p.loads.len() as f64,
        300.0 / p.max_samples() as f64,
    )
}

/// The contact line at orientation `theta` (rad) of `scene`: `line` or the moiré estimate.
pub fn line_at(scene: &Scene, theta: f64, line: Option<f64>) -> LineChoice {
    contact_line(&scene.with_theta(theta), line)
}

/// The warning for a scene whose springs mount's tilt mode lies in the measured resonance band
/// on a substrate too smooth to detune it ([`surrogate::friction::TiltResonance::expected`]),
/// where μ_est of failed-coating rows (column `mount_resonance`) may be an upper bound; `None`
/// outside the band, on a rough enough substrate or without springs.
pub fn resonance_note(scene: &Scene, knobs: &FrictionParams) -> Option<String> {
    let t = TiltResonance::of(scene, knobs).filter(|t| t.expected())?;
    Some(format!(
        "{t}: where contacts fail (column mount_resonance) the DEM's friction can be up to {}× \
         below mu_est (measured against the DEM; substrate roughness σ_h ≥ {} nm detunes it; \
         docs/validation/friction.md, \"The mount's resonance\")",
        RESONANCE_DROP_MAX,
        m_to_nm(DETUNING_SIGMA_H)
    ))
}

/// Length (m) of the estimate's path along the unit direction `e`: one substrate period along
/// lattice directions, the fixed length otherwise.
pub fn path_length(scene: &Scene, e: [f64; 2], knobs: &FrictionParams) -> f64 {
    lattice_period(
        &scene.substrate.lattice,
        e,
        knobs.max_period,
        knobs.direction_tol,
    )
    .unwrap_or(knobs.length)
}

/// Checks the knobs and that the slider stays over the substrate along the path of every
/// (θ, α) (field `friction.length_um` named otherwise). No solve.
pub fn check(scene: &Scene, p: &FrictionSweepParams) -> Result<()> {
    p.knobs.validate()?;
    for &theta in &p.thetas {
        let line = line_at(scene, theta, p.line).angle;
        for &alpha in &p.alphas {
            check_path(scene, line + alpha, &p.knobs)?;
        }
    }
    Ok(())
}

/// Checks that the slider stays over the substrate along the estimate's path in every direction
/// (every 0.5° of the full circle, each at its own [`path_length`]): a superset of any α scan
/// and tolerance box, for workflows that choose the directions as they go (`design`). Field
/// `friction.length_um` named otherwise. No solve; O(720).
pub fn check_every_direction(scene: &Scene, knobs: &FrictionParams) -> Result<()> {
    knobs.validate()?;
    for k in 0..720 {
        check_path(scene, surrogate::units::deg_to_rad(0.5 * k as f64), knobs)?;
    }
    Ok(())
}

/// Whether the slider stays over the substrate along the estimate's path in direction `d`
/// (rad from the substrate x axis), of its [`path_length`]; field `friction.length_um`.
fn check_path(scene: &Scene, d: f64, knobs: &FrictionParams) -> Result<()> {
    let e = [d.cos(), d.sin()];
    let l = path_length(scene, e, knobs);
    let end = [l * e[0], l * e[1]];
    check_slider_stays_on_substrate(
        scene,
        [
            [end[0].min(0.0), end[1].min(0.0)],
            [end[0].max(0.0), end[1].max(0.0)],
        ],
        "friction.length_um",
    )?;
    Ok(())
}

/// Runs the items `items` (a sub-range of `0..p.items()`: a shard, or what a resumed run has
/// left) of the friction sweep of `scene`, pushing `p.loads.len()` [`FrictionRow`]s per item in
/// order. Errors: bad knobs, a path off the substrate, a failing sink, or (when every row of
/// the whole sweep was computed) no configuration with an estimate.
pub fn friction(
    scene: &Scene,
    p: &FrictionSweepParams,
    items: Range<usize>,
    rows: &mut dyn RowSink<FrictionRow>,
    progress: &dyn Progress,
) -> Result<FrictionStats> {
    if p.loads.is_empty() || p.items() == 0 {
        bail!("a friction sweep needs at least one θ, one α and one load");
    }
    check(scene, p)?;
    let solver = Solver::new(scene)?;
    let mut stats = FrictionStats::default();
    progress.stage(
        "friction",
        (items.len() * p.loads.len()) as u64,
        "estimates",
    );
    for i in items {
        let (theta, alpha) = p.item(i);
        let line = line_at(scene, theta, p.line).angle;
        let est = estimate_friction_loads(&solver, theta, line + alpha, &p.loads, &p.knobs)?;
        for (&w, r) in p.loads.iter().zip(&est) {
            let row = FrictionRow::new(&scene.pattern, theta, alpha, line, w, r)
                .judged(p.mu_superlubric, scene.coating.p_crit);
            stats.rows += 1;
            stats.failures += !row.error.is_empty() as u64;
            stats.resonant += (row.mount_resonance == Some(true)) as u64;
            rows.push(&row)?;
        }
        progress.advance(p.loads.len() as u64);
    }
    progress.finish();
    if stats.failures > 0 {
        progress.note(&format!(
            "warning: {} of {} configurations have no estimate (see the `error` column)",
            stats.failures, stats.rows
        ));
    }
    Ok(stats)
}
