//! Tolerance of a design: how the superlubric limit load moves when the slider is rotated by
//! δθ and pulled δd off its nominal direction.
//!
//! A misaligned slider keeps the nominal pull direction **in the substrate frame** (the
//! tribometer's axis does not rotate with the slider): the sample (θ + δθ, d + δd) is pulled
//! along d + δd from the substrate's x axis, i.e. at α' = d + δd − line(θ + δθ) from its own
//! contact line.
//!
//! **Superlubric limit** of a sample: the highest load W_k of the list such that the friction
//! estimate is superlubric (coating intact on the path, μ_est < μ_sl) at every load W_1 … W_k
//! (the design's score, [`crate::study::design::rank`]). Pruning, exact: the screen's P_max at
//! the placement is the first sample of the path, so a load whose coating fails there cannot be
//! superlubric; only the loads below the first such load are estimated
//! ([`placement_intact`]), ascending, [`LOAD_CHUNK`] per path, stopping at the first load that
//! is not superlubric.
//!
//! Two uses: the map of `superlube tolerance` ([`map`]: every grid point to its own limit) and
//! the robust limit of `design` ([`robust`]: the lowest limit over a tolerance box, with the
//! box's interior evaluated only up to the lowest limit found so far).
//!
//! Cost: one friction path per (sample, chunk of 3 loads) — 24–73 ms each on the study scenes
//! (`cargo bench --bench friction`) — plus one multi-load screen solve per θ.

use super::corrugation::contact_line;
use super::rows::{label, FrictionRow};
use super::verdict::Verdict;
use anyhow::Result;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use surrogate::friction::{estimate_friction_loads, FrictionParams};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::units::{deg_to_rad, n_to_mn, pa_to_gpa, rad_to_deg};

/// Loads per friction path (a cost knob only: each estimate is bit-identical for any chunk).
pub const LOAD_CHUNK: usize = 3;

/// What the limit of a sample is computed against (SI inside).
#[derive(Debug, Clone)]
pub struct LimitParams {
    /// Loads W (N), strictly increasing.
    pub loads: Vec<f64>,
    /// μ below which a row is superlubric (study: 0.02).
    pub mu_superlubric: f64,
    /// Contact line (rad from x) for every θ; `None`: the moiré estimate at each θ (for α).
    pub line: Option<f64>,
    /// The friction estimate's knobs.
    pub friction: FrictionParams,
}

/// The symmetric offsets (degrees) −tol … +tol in equal steps no larger than `step`, 0
/// included: `[0]` when `tol` is 0. Example: tol 0.1, step 0.02 → −0.1, −0.08, …, 0.1.
pub fn offsets(tol: f64, step: f64) -> Vec<f64> {
    if tol <= 0.0 {
        return vec![0.0];
    }
    let n = (tol / step - 1e-9).ceil().max(1.0) as i64;
    (-n..=n)
        .map(|k| super::rows::clean(tol * k as f64 / n as f64))
        .collect()
}

/// How many of the leading `loads` keep the coating intact at the placement of orientation θ
/// (rad): the screen's P_max ≤ P_crit (a load without equilibrium ends the count).
pub fn placement_intact(solver: &Solver, theta: f64, loads: &[f64]) -> usize {
    let p_crit = solver.scene().coating.p_crit;
    let pose = Pose {
        theta,
        shift: [0.0, 0.0],
    };
    solver
        .solve_loads(pose, loads, Model::Auto)
        .iter()
        .take_while(|r| r.as_ref().is_ok_and(|e| e.p_max <= p_crit))
        .count()
}

/// Whether a row is superlubric by the estimate's thresholds (the design's rule).
pub fn superlubric(r: &FrictionRow, p_crit: f64, mu_sl: f64) -> bool {
    r.error.is_empty()
        && r.p_max_GPa.is_some_and(|p| p <= pa_to_gpa(p_crit))
        && r.mu_est.is_some_and(|m| m < mu_sl)
}

/// The friction rows of (θ, direction) (degrees; direction from the substrate's x axis) at the
/// first `cap` loads, ascending, stopping after the first row that is not superlubric.
pub fn rows_upto(
    solver: &Solver,
    theta_deg: f64,
    direction_deg: f64,
    cap: usize,
    p: &LimitParams,
) -> Result<Vec<FrictionRow>> {
    let scene = solver.scene();
    let theta = deg_to_rad(theta_deg);
    let line = contact_line(&scene.with_theta(theta), p.line).angle;
    let dir = deg_to_rad(direction_deg);
    let p_crit = scene.coating.p_crit;
    let mut rows = Vec::new();
    // the lowest load alone (most samples end there), then LOAD_CHUNK loads per path
    let todo = &p.loads[..cap.min(p.loads.len())];
    let first = todo.len().min(1);
    let chunks = std::iter::once(&todo[..first]).chain(todo[first..].chunks(LOAD_CHUNK));
    for chunk in chunks.filter(|c| !c.is_empty()) {
        let r = estimate_friction_loads(solver, theta, dir, chunk, &p.friction)?;
        for (&w, r) in chunk.iter().zip(&r) {
            let mut row = FrictionRow::new(&scene.pattern, theta, dir - line, line, w, r);
            row.theta_deg = label(theta_deg);
            row.direction_deg = label(direction_deg);
            let ok = superlubric(&row, p_crit, p.mu_superlubric);
            rows.push(row);
            if !ok {
                return Ok(rows);
            }
        }
    }
    Ok(rows)
}

/// Number of leading superlubric rows.
pub fn superlubric_count(rows: &[FrictionRow], p_crit: f64, mu_sl: f64) -> usize {
    rows.iter()
        .take_while(|r| superlubric(r, p_crit, mu_sl))
        .count()
}

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
    /// Friction paths solved for this point (its cost).
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
        alpha_deg: super::rows::clean(point.1 - line_deg),
        placement_intact_to_mN: load(cap),
        superlubric_to_mN: load(n),
        confident_to_mN: load(sure),
        mu_est_at_limit: at.and_then(|r| r.mu_est),
        p_max_at_limit_GPa: at.and_then(|r| r.p_max_GPa),
        limited_by: limited_by.to_string(),
        loads_estimated: rows.len(),
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
/// x). Each point is independent (computed in parallel, results in grid order: the same for
/// any thread count). `tick` is called once per point.
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
    let points: Vec<(usize, f64)> = p
        .direction_offsets_deg
        .iter()
        .flat_map(|&dd| (0..per_theta.len()).map(move |i| (i, dd)))
        .collect();
    points
        .par_iter()
        .map(|&(i, dd)| {
            let (t, cap, line) = per_theta[i];
            let d = label(p.direction_deg + dd);
            let rows = rows_upto(solver, t, d, cap, &p.limit)?;
            tick();
            Ok(map_row(
                &scene.pattern,
                (p.theta_deg, p.direction_deg),
                (t, d),
                line,
                cap,
                &rows,
                &p.limit,
                p_crit,
            ))
        })
        .collect()
}

/// An offset (θ offset, direction offset) in degrees from the nominal.
pub type Offset = (f64, f64);

/// An axis sample: θ offset, direction offset (degrees), leading superlubric loads.
type AxisCount = (f64, f64, usize);

/// The tolerance box of a design.
#[derive(Debug, Clone, PartialEq)]
pub struct ToleranceBox {
    /// θ offsets (degrees, symmetric, 0 included; `[0]`: no θ tolerance).
    pub theta_offsets_deg: Vec<f64>,
    /// Direction offsets (degrees, symmetric, 0 included).
    pub direction_offsets_deg: Vec<f64>,
}

impl ToleranceBox {
    /// The box ±`theta_tol` × ±`direction_tol` (degrees) sampled every ≤ `theta_step` and ≤
    /// `direction_step` ([`offsets`]).
    pub fn new(theta_tol: f64, direction_tol: f64, theta_step: f64, direction_step: f64) -> Self {
        ToleranceBox {
            theta_offsets_deg: offsets(theta_tol, theta_step),
            direction_offsets_deg: offsets(direction_tol, direction_step),
        }
    }

    /// Whether the box is the nominal point alone.
    pub fn is_point(&self) -> bool {
        self.theta_offsets_deg.len() == 1 && self.direction_offsets_deg.len() == 1
    }

    /// Every sample (θ offset, direction offset) except the nominal: the two axes first
    /// (farthest first), then the interior and corners (corners first, then by distance,
    /// farthest first): the order in which a limit is most likely found early.
    pub fn samples(&self) -> (Vec<Offset>, Vec<Offset>) {
        let far = |v: &[f64]| {
            let mut v: Vec<f64> = v.iter().copied().filter(|&x| x != 0.0).collect();
            v.sort_by(|a, b| b.abs().total_cmp(&a.abs()).then(a.total_cmp(b)));
            v
        };
        let th = far(&self.theta_offsets_deg);
        let di = far(&self.direction_offsets_deg);
        let mut axes: Vec<(f64, f64)> = th.iter().map(|&t| (t, 0.0)).collect();
        axes.extend(di.iter().map(|&d| (0.0, d)));
        let tmax = th.first().map_or(1.0, |t| t.abs()).max(1e-12);
        let dmax = di.first().map_or(1.0, |d| d.abs()).max(1e-12);
        let mut inner: Vec<(f64, f64)> = th
            .iter()
            .flat_map(|&t| di.iter().map(move |&d| (t, d)))
            .collect();
        inner.sort_by(|a, b| {
            let r = |p: &(f64, f64)| {
                (p.0 / tmax).abs().max((p.1 / dmax).abs()) * 2.0
                    + (p.0 / tmax).abs()
                    + (p.1 / dmax).abs()
            };
            r(b).total_cmp(&r(a))
        });
        (axes, inner)
    }
}

/// The robust limit and window of one design (indices count loads of [`LimitParams::loads`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Robust {
    /// Loads up to which every sample of the box (and every seed) is superlubric (0: none).
    pub superlubric_to: usize,
    /// The sample (θ offset, direction offset, seed index) that set the limit (the nominal when
    /// the box does not lower it).
    pub worst: (f64, f64, usize),
    /// Half-width (degrees) of θ around the nominal inside which every θ-axis sample is
    /// superlubric, per load (index k: at the k+1-th load), up to the nominal limit.
    pub theta_window_deg: Vec<f64>,
    /// The same along the direction axis.
    pub direction_window_deg: Vec<f64>,
    /// The worst verdict over the box's samples at the robust limit load (`Not` when 0).
    pub verdict: Verdict,
    /// Friction paths solved (cost).
    pub paths: usize,
    /// Whether `superlubric_to` is exact; `false`: the evaluation stopped once it fell below
    /// the floor asked for, and it is an upper bound.
    pub exact: bool,
}

/// The window (degrees) of each of the first `upto` loads from axis samples (offset, count of
/// leading superlubric loads): the largest |offset| h such that every sample with |offset| ≤ h
/// is superlubric at that load.
fn windows(samples: &[(f64, usize)], upto: usize) -> Vec<f64> {
    let mut dist: Vec<f64> = samples.iter().map(|s| s.0.abs()).collect();
    dist.sort_by(f64::total_cmp);
    dist.dedup();
    (0..upto)
        .map(|k| {
            let mut h = 0.0;
            for &d in &dist {
                if samples.iter().all(|s| s.0.abs() != d || s.1 > k) {
                    h = d;
                } else {
                    break;
                }
            }
            h
        })
        .collect()
}

/// The robust limit of the design (θ, direction) (degrees) over `bx` and every solver in
/// `solvers` (one per substrate seed; the first is the design's own scene, whose nominal rows
/// are `nominal`: the design's estimate, loads ascending). Axis samples are estimated up to
/// the nominal limit (for the windows), the interior only up to the lowest limit found so far,
/// a few samples at a time in parallel (the result does not depend on the batching). Once the
/// limit falls below `floor` loads the evaluation stops: the result is then an upper bound
/// (`exact: false`; a design that cannot reach the floor needs no exact value to be ranked
/// below those that do).
pub fn robust(
    solvers: &[Solver],
    theta_deg: f64,
    direction_deg: f64,
    nominal: &[FrictionRow],
    bx: &ToleranceBox,
    p: &LimitParams,
    floor: usize,
) -> Result<Robust> {
    let p_crit = solvers[0].scene().coating.p_crit;
    let mu_sl = p.mu_superlubric;
    let nominal_to = superlubric_count(nominal, p_crit, mu_sl);
    let mut lowest = nominal_to;
    let mut worst = (0.0, 0.0, 0usize);
    let mut paths = 0usize;
    let mut seen: Vec<FrictionRow> = nominal.to_vec();
    if nominal_to == 0 {
        return Ok(Robust {
            superlubric_to: 0,
            worst,
            theta_window_deg: Vec::new(),
            direction_window_deg: Vec::new(),
            verdict: Verdict::Not,
            paths,
            exact: true,
        });
    }
    let (axes, inner) = bx.samples();
    let mut all: Vec<(f64, f64)> = vec![(0.0, 0.0)];
    all.extend(axes.iter().copied());
    // placement bounds per θ offset and solver
    let caps: Vec<Vec<(f64, usize)>> = solvers
        .iter()
        .map(|s| {
            bx.theta_offsets_deg
                .par_iter()
                .map(|&dt| {
                    let t = label(theta_deg + dt);
                    (dt, placement_intact(s, deg_to_rad(t), &p.loads))
                })
                .collect()
        })
        .collect();
    let cap_of = |si: usize, dt: f64| -> usize {
        caps[si]
            .iter()
            .find(|c| c.0 == dt)
            .map_or(p.loads.len(), |c| c.1)
    };
    // axis samples (and the nominal of the other seeds), each to the nominal limit
    let mut axis_counts: Vec<AxisCount> = Vec::new();
    for (si, s) in solvers.iter().enumerate() {
        let todo: Vec<(f64, f64)> = all
            .iter()
            .copied()
            .filter(|&(dt, dd)| si > 0 || (dt, dd) != (0.0, 0.0))
            .collect();
        let done: Vec<Result<Vec<FrictionRow>>> = todo
            .par_iter()
            .map(|&(dt, dd)| {
                let cap = cap_of(si, dt).min(nominal_to);
                rows_upto(s, label(theta_deg + dt), label(direction_deg + dd), cap, p)
            })
            .collect();
        for (&(dt, dd), rows) in todo.iter().zip(done) {
            let rows = rows?;
            paths += rows.len().div_ceil(LOAD_CHUNK);
            let n = superlubric_count(&rows, p_crit, mu_sl);
            axis_counts.push((dt, dd, n));
            if n < lowest {
                lowest = n;
                worst = (dt, dd, si);
            }
            seen.extend(rows);
        }
    }
    // (below the floor after the axes: the interior cannot raise it back)
    // the interior, each only up to the lowest limit so far, BATCH samples at a time
    const BATCH: usize = 4;
    let mut exact = true;
    let jobs: Vec<(usize, f64, f64)> = (0..solvers.len())
        .flat_map(|si| inner.iter().map(move |&(dt, dd)| (si, dt, dd)))
        .collect();
    for batch in jobs.chunks(BATCH) {
        if lowest == 0 {
            break;
        }
        if lowest < floor {
            exact = false;
            break;
        }
        let cap_now = lowest;
        let done: Vec<Result<Vec<FrictionRow>>> = batch
            .par_iter()
            .map(|&(si, dt, dd)| {
                rows_upto(
                    &solvers[si],
                    label(theta_deg + dt),
                    label(direction_deg + dd),
                    cap_of(si, dt).min(cap_now),
                    p,
                )
            })
            .collect();
        for (&(si, dt, dd), rows) in batch.iter().zip(done) {
            let rows = rows?;
            paths += rows.len().div_ceil(LOAD_CHUNK);
            let n = superlubric_count(&rows, p_crit, mu_sl);
            if n < lowest {
                lowest = n;
                worst = (dt, dd, si);
            }
            seen.extend(rows);
        }
    }
    let min_over = |pick: &dyn Fn(&AxisCount) -> Option<f64>| -> Vec<(f64, usize)> {
        let mut m: Vec<(f64, usize)> = Vec::new();
        for c in &axis_counts {
            if let Some(o) = pick(c) {
                match m.iter_mut().find(|x| x.0 == o) {
                    Some(x) => x.1 = x.1.min(c.2),
                    None => m.push((o, c.2)),
                }
            }
        }
        m
    };
    let th = min_over(&|c| (c.1 == 0.0).then_some(c.0));
    let di = min_over(&|c| (c.0 == 0.0).then_some(c.1));
    let mut th_all = vec![(0.0, nominal_to)];
    th_all.extend(th);
    let mut di_all = vec![(0.0, nominal_to)];
    di_all.extend(di);
    // rows at the robust limit load: keep those of exactly that load
    let verdict = if lowest == 0 {
        Verdict::Not
    } else {
        let w = label(n_to_mn(p.loads[lowest - 1]));
        seen.iter()
            .filter(|r| r.load_mN == w)
            .map(|r| Verdict::of_row(r, mu_sl, p_crit))
            .max()
            .unwrap_or(Verdict::Not)
    };
    Ok(Robust {
        superlubric_to: lowest,
        worst,
        theta_window_deg: windows(&th_all, nominal_to),
        direction_window_deg: windows(&di_all, nominal_to),
        verdict,
        paths,
        exact: exact || lowest == 0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_are_symmetric_and_fine_enough() {
        assert_eq!(offsets(0.0, 0.02), vec![0.0]);
        let o = offsets(0.1, 0.02);
        assert_eq!(o.len(), 11);
        assert_eq!(o[0], -0.1);
        assert_eq!(o[5], 0.0);
        assert_eq!(o[10], 0.1);
        let o = offsets(0.5, 0.3);
        assert_eq!(o, vec![-0.5, -0.25, 0.0, 0.25, 0.5]);
    }

    #[test]
    fn windows_stop_at_the_first_failing_offset() {
        // offsets ±0.02 … ±0.1; superlubric at 3 loads out to 0.04, 1 load beyond
        let s: Vec<(f64, usize)> = [0.0, 0.02, -0.02, 0.04, -0.04, 0.06, -0.06, 0.08, 0.1]
            .iter()
            .map(|&o: &f64| (o, if o.abs() <= 0.041 { 3 } else { 1 }))
            .collect();
        let w = windows(&s, 3);
        assert_eq!(w, vec![0.1, 0.04, 0.04]);
        // the first offset fails: window 0 (narrower than the sampling)
        let s = vec![(0.0, 2), (0.02, 0), (-0.02, 2)];
        assert_eq!(windows(&s, 2), vec![0.0, 0.0]);
    }

    #[test]
    fn box_samples_cover_the_box_once() {
        let bx = ToleranceBox::new(0.1, 0.5, 0.05, 0.25);
        let (axes, inner) = bx.samples();
        assert_eq!(axes.len(), 4 + 4);
        assert_eq!(inner.len(), 4 * 4);
        // corners first
        assert_eq!(inner[0].0.abs(), 0.1);
        assert_eq!(inner[0].1.abs(), 0.5);
        assert!(ToleranceBox::new(0.0, 0.0, 0.02, 0.25).is_point());
    }
}
