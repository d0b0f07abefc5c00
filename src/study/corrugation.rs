//! The corrugation workflow: peak-to-peak height and static-friction barrier along straight
//! pulling paths at angles α from the slider's contact line, one [`CorrugationRow`] per α,
//! streamed in the order of the α list. Also the contact-line choice shared with the DEM runs
//! (α is measured from it there too).

use super::rows::CorrugationRow;
use crate::runs::budget::Estimate;
use crate::runs::progress::Progress;
use crate::runs::sink::RowSink;
use anyhow::{bail, Result};
use surrogate::map::{
    check_path_stays_on_substrate, compute_landscape, contact_line_direction, corrugation_direct,
    corrugation_from_landscape, ContactLine, MapParams,
};
use surrogate::solver::Solver;
use surrogate::Scene;

/// How the heights along a path are obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// A solver call at every sample along the path (exact up to the sampling step).
    Direct,
    /// Bicubic interpolation of one periodic landscape (fast; flat substrates only; the lateral
    /// force is the rigid-limit W·dz/ds).
    Landscape,
}

/// Parameters of a corrugation sweep (SI). θ is the scene's `slider.theta`.
#[derive(Debug, Clone, PartialEq)]
pub struct CorrugationParams {
    /// Normal load W (N).
    pub load: f64,
    /// Pulling angles α (rad) from the contact line, |α| ≤ π, in output order.
    pub alphas: Vec<f64>,
    /// Contact-line angle (rad from the substrate x axis); `None`: the moiré estimate.
    pub line: Option<f64>,
    /// Path length (m).
    pub distance: f64,
    /// Sampling step along the path (m).
    pub step: f64,
    /// Heights by direct solves or from an interpolated landscape.
    pub method: Method,
    /// Landscape grid points per side (method `landscape`).
    pub grid: usize,
}

impl CorrugationParams {
    /// The map knobs of these parameters.
    pub fn map_params(&self) -> MapParams {
        MapParams {
            grid: self.grid,
            distance: self.distance,
            step: self.step,
            ..MapParams::default()
        }
    }

    /// Samples per path (L/step rounded up, plus the start).
    pub fn samples_per_path(&self) -> u64 {
        (self.distance / self.step - 1e-9).ceil().max(1.0) as u64 + 1
    }
}

/// The contact line that α is measured from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineChoice {
    /// The angle used (rad from the substrate x axis).
    pub angle: f64,
    /// Whether the user gave it (otherwise the moiré estimate).
    pub given: bool,
    /// The moiré estimate (computed whether or not a line is given, for the log); `None` when a
    /// body comes from a site file ([`site_file_body`]): there is no lattice for it, and without
    /// a given line the line is the substrate x axis (0°).
    pub estimate: Option<ContactLine>,
}

/// Which body of `scene` comes from a site file, in words (`the slider comes from the site
/// file `s.csv``), the slider first; `None` when both are lattices. Such a body has no lattice
/// for the moiré contact-line estimate (its scene keeps the base preset's lattice, which the
/// file replaced).
pub fn site_file_body(scene: &Scene) -> Option<String> {
    let g = &scene.geometry;
    g.slider_sites
        .as_ref()
        .map(|l| format!("the slider comes from the site file `{}`", l.path))
        .or_else(|| {
            g.substrate_sites
                .as_ref()
                .map(|l| format!("the substrate comes from the site file `{}`", l.path))
        })
}

impl LineChoice {
    /// One log line describing the choice.
    pub fn describe(&self) -> String {
        let given = format!("given by {}", crate::study::input::Input::LineDeg);
        let Some(estimate) = &self.estimate else {
            return format!(
                "contact line: {:.3}° from x ({}: a site file has no lattice for the moiré estimate{})",
                self.angle.to_degrees(),
                if self.given {
                    given.as_str()
                } else {
                    "the substrate x axis"
                },
                if self.given {
                    String::new()
                } else {
                    format!("; {} sets the line", crate::study::input::Input::LineDeg)
                }
            );
        };
        format!(
            "contact line: {:.3}° from x ({}; moiré estimate {:.3}°{}, line spacing {:.2} µm)",
            self.angle.to_degrees(),
            if self.given {
                given.as_str()
            } else {
                "moiré estimate"
            },
            estimate.angle.to_degrees(),
            if estimate.degenerate {
                ", degenerate: commensurate first shells, substrate row used"
            } else {
                ""
            },
            surrogate::units::m_to_um(estimate.spacing)
        )
    }
}

/// The contact line of `scene` at its θ: `given` (rad) or the moiré estimate; with a site file
/// ([`site_file_body`]) and none given, the substrate x axis (no `estimate`). The commands
/// whose α the user gives refuse that case first (`--line-deg`); `design` and `tolerance`
/// measure α from it and say so.
pub fn contact_line(scene: &Scene, given: Option<f64>) -> LineChoice {
    let estimate = site_file_body(scene)
        .is_none()
        .then(|| contact_line_direction(scene, scene.slider.theta, &MapParams::default()));
    LineChoice {
        angle: given.or(estimate.map(|e| e.angle)).unwrap_or(0.0),
        given: given.is_some(),
        estimate,
    }
}

/// Cost estimate.
pub fn estimate(scene: &Scene, p: &CorrugationParams) -> Estimate {
    use crate::study::input::Input;
    let (inputs, solves) = match p.method {
        Method::Direct => (
            format!(
                "{} × ({} / {})",
                Input::Alpha,
                Input::DistanceUm,
                Input::StepUm
            ),
            (p.alphas.len() as u64).saturating_mul(p.samples_per_path()),
        ),
        Method::Landscape => (
            Input::Grid.to_string(),
            (p.grid as u64).saturating_mul(p.grid as u64),
        ),
    };
    Estimate::solves(
        &inputs,
        solves,
        scene.slider_sites_local().len(),
        scene.substrate_spheres().len(),
        // a path's profile (direct) or the landscape (interpolated) is held in memory
        40.0 * (p.samples_per_path() as f64 + (p.grid * p.grid) as f64),
        0.0,
    )
}

/// Checks that the slider stays over the substrate along the path of every α of `p` from the
/// contact line `line` (field `distance_um` named otherwise). No solve.
pub fn check_paths(scene: &Scene, p: &CorrugationParams, line: &LineChoice) -> Result<()> {
    for &alpha in &p.alphas {
        check_path_stays_on_substrate(scene, line.angle + alpha, p.distance)?;
    }
    Ok(())
}

/// Runs the corrugation sweep of `scene` at its θ, pushing one [`CorrugationRow`] per α in
/// order; returns the contact line used.
pub fn corrugation(
    scene: &Scene,
    p: &CorrugationParams,
    rows: &mut dyn RowSink<CorrugationRow>,
    progress: &dyn Progress,
) -> Result<LineChoice> {
    let theta = scene.slider.theta;
    let params = p.map_params();
    let solver = Solver::new(scene)?;
    let line = contact_line(scene, p.line);
    progress.note(&line.describe());
    // Every path must stay over the substrate: checked for all α before the first solve.
    check_paths(scene, p, &line)?;
    match p.method {
        Method::Direct => {
            progress.stage(
                "corrugation",
                p.alphas.len() as u64 * p.samples_per_path(),
                "solves",
            );
            for &alpha in &p.alphas {
                let pts = corrugation_direct(
                    &solver,
                    theta,
                    p.load,
                    line.angle,
                    &[alpha],
                    &params,
                    &|| progress.advance(1),
                )?;
                rows.push(&CorrugationRow::new(theta, p.load, line.angle, &pts[0]))?;
            }
            progress.finish();
        }
        Method::Landscape => {
            if scene.substrate.sigma_h > 0.0 {
                bail!("the landscape method needs a flat substrate (σ_h = 0): the landscape of a perturbed substrate is not periodic; use the direct method");
            }
            if scene.geometry.substrate_sites.is_some() {
                bail!("the landscape method needs a substrate lattice (its repeat cell): a substrate from a site file (`substrate.sites`) has none; use the direct method");
            }
            progress.stage("landscape", (p.grid * p.grid) as u64, "grid points");
            let l = compute_landscape(&solver, theta, p.load, &params, &|| progress.advance(1))?;
            progress.finish();
            for pt in corrugation_from_landscape(&l, line.angle, &p.alphas, &params)? {
                rows.push(&CorrugationRow::new(theta, p.load, line.angle, &pt))?;
            }
        }
    }
    Ok(line)
}
