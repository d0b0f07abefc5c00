//! The tolerance map of one design: every grid point (θ, direction) to its own superlubric
//! limit ([`map`]).

use super::{placement_intact, rows_upto, superlubric_count, LimitParams};
use crate::study::corrugation::contact_line;
use crate::study::rows::{label, FrictionRow};
use crate::study::verdict::Verdict;
use anyhow::Result;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use surrogate::solver::Solver;
use surrogate::units::{deg_to_rad, n_to_mn, pa_to_gpa, rad_to_deg};

/// One point of a tolerance map (user units; `map.csv`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ToleranceRow {
    /// Pattern pair name.
    pub pattern: String,
    /// Slider orientation θ of the point (degrees).
    pub theta_deg: f64,
    /// Pulling direction of the point from the substrate's x axis (degrees).
    pub direction_deg: f64,
    /// θ − nominal θ (degrees).
    pub theta_offset_deg: f64,
    /// Direction − nominal direction (degrees).
    pub direction_offset_deg: f64,
    /// Pulling angle from the slider's own contact line at θ (degrees).
    pub alpha_deg: f64,
    /// Highest load up to which the coating is intact at the placement (mN; 0: none): the
    /// screen's bound, no load above it is estimated.
    pub placement_intact_to_mN: f64,
    /// Highest load W_k such that the estimate is superlubric at every load up to it (mN; 0:
    /// none).
    pub superlubric_to_mN: f64,
    /// Highest load up to which every row's verdict is `superlubric` (outside the estimate's
    /// uncertainty band; mN; 0: none).
    pub confident_to_mN: f64,
    /// μ_est at `superlubric_to_mN` (empty when 0).
    pub mu_est_at_limit: Option<f64>,
    /// Path P_max at `superlubric_to_mN` (GPa; empty when 0).
    pub p_max_at_limit_GPa: Option<f64>,
    /// What ends superlubricity above the limit: `placement` (coating fails where the slider is
    /// placed), `path` (fails along the sliding path), `friction` (μ_est ≥ μ_sl), `error` (no
    /// estimate), `none` (superlubric at the highest load).
    pub limited_by: String,
    /// Loads estimated for this point (its cost; paths may run one guess past the limit).
    pub loads_estimated: usize,
}

/// The map's row of a sample from its rows (those [`rows_upto`] returned with cap `cap`).
#[allow(clippy::too_many_arguments)]
fn map_row(
    pattern: &str,
    nominal: (f64, f64),
    point: (f64, f64),
    line_deg: f64,
    cap: usize,
    rows: &[FrictionRow],
    estimated: usize,
    p: &LimitParams,
    p_crit: f64,
) -> ToleranceRow {
    let mu_sl = p.mu_superlubric;
    let n = superlubric_count(rows, p_crit, mu_sl);
    let sure = rows
        .iter()
        .take_while(|r| Verdict::of_row(r, mu_sl, p_crit) == Verdict::Superlubric)
        .count();
    let load = |k: usize| {
        if k == 0 {
            0.0
        } else {
            label(n_to_mn(p.loads[k - 1]))
        }
    };
    let limited_by = if n == p.loads.len() {
        "none"
    } else if n == cap && rows.len() == n {
        "placement"
    } else {
        let r = &rows[n];
        if !r.error.is_empty() || r.mu_est.is_none() {
            "error"
        } else if r.p_max_GPa.is_some_and(|x| x > pa_to_gpa(p_crit)) {
            "path"
        } else {
            "friction"
        }
    };
    let at = n.checked_sub(1).map(|k| &rows[k]);
    ToleranceRow {
        pattern: pattern.to_string(),
        theta_deg: label(point.0),
        direction_deg: label(point.1),
        theta_offset_deg: label(point.0 - nominal.0),
        direction_offset_deg: label(point.1 - nominal.1),
        alpha_deg: crate::study::rows::clean(point.1 - line_deg),
        placement_intact_to_mN: load(cap),
        superlubric_to_mN: load(n),
        confident_to_mN: load(sure),
        mu_est_at_limit: at.and_then(|r| r.mu_est),
        p_max_at_limit_GPa: at.and_then(|r| r.p_max_GPa),
        limited_by: limited_by.to_string(),
        loads_estimated: estimated,
    }
}

/// A tolerance map: the grid and what to draw.
#[derive(Debug, Clone)]
pub struct MapParams {
    /// Nominal θ (degrees).
    pub theta_deg: f64,
    /// Nominal pulling direction from the substrate's x axis (degrees).
    pub direction_deg: f64,
    /// θ offsets of the grid (degrees, ascending).
    pub theta_offsets_deg: Vec<f64>,
    /// Direction offsets of the grid (degrees, ascending).
    pub direction_offsets_deg: Vec<f64>,
    /// The limit's loads, threshold and estimate knobs.
    pub limit: LimitParams,
}

/// Every point of the map, direction outer, θ inner (row-major for a heat map with θ along
/// x). The directions are computed in parallel; along θ each point's first path runs the loads
/// up to its left neighbour's limit + 1 (one path where the limit does not change: the values
/// are the same for any grouping of loads, so the map is the same for any thread count).
/// `tick` is called once per point.
pub fn map(solver: &Solver, p: &MapParams, tick: &(dyn Fn() + Sync)) -> Result<Vec<ToleranceRow>> {
    let scene = solver.scene();
    let p_crit = scene.coating.p_crit;
    // the placement bound and the contact line per θ (shared by every direction)
    let per_theta: Vec<(f64, usize, f64)> = p
        .theta_offsets_deg
        .par_iter()
        .map(|&dt| {
            let t = label(p.theta_deg + dt);
            let th = deg_to_rad(t);
            let cap = placement_intact(solver, th, &p.limit.loads);
            let line = rad_to_deg(contact_line(&scene.with_theta(th), p.limit.line).angle);
            (t, cap, line)
        })
        .collect();
    let lines: Vec<Result<Vec<ToleranceRow>>> = p
        .direction_offsets_deg
        .par_iter()
        .map(|&dd| {
            let d = label(p.direction_deg + dd);
            let mut out = Vec::with_capacity(per_theta.len());
            let mut guess = 0;
            for &(t, cap, line) in &per_theta {
                let (rows, estimated) = rows_upto(solver, t, d, cap, guess, &p.limit)?;
                tick();
                let row = map_row(
                    &scene.pattern,
                    (p.theta_deg, p.direction_deg),
                    (t, d),
                    line,
                    cap,
                    &rows,
                    estimated,
                    &p.limit,
                    p_crit,
                );
                guess = superlubric_count(&rows, p_crit, p.limit.mu_superlubric);
                out.push(row);
            }
            Ok(out)
        })
        .collect();
    let mut all = Vec::with_capacity(per_theta.len() * p.direction_offsets_deg.len());
    for l in lines {
        all.extend(l?);
    }
    Ok(all)
}
