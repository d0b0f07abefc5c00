//! The robust limit of a design over its tolerance box: the lowest superlubric limit over every
//! sample (θ offset, direction offset, substrate seed) of the box ([`RobustSearch`]).
//!
//! The search keeps an upper bound U of the robust limit (start: the nominal limit and the
//! screen's placement bound of every θ offset) and lowers it from the top:
//! 1. **disproof** — each sample is estimated at the single load W_U, the sample that set the
//!    last bound first, then corners and far axis points; the first that is not superlubric
//!    proves the limit < U (U − 1 is the new bound, one cheap path);
//! 2. **verification** — once every sample is superlubric at W_U, each sample's loads below
//!    W_U are estimated on one path; if all are superlubric the robust limit is exactly U,
//!    else the lowest failing load is the new bound.
//!
//! A design whose bound falls below what the ranking needs is left there (an upper bound,
//! `exact: false`); the caller decides which design to refine next. Every decision depends
//! only on the estimates and the fixed sample order, so the result is the same for any thread
//! count. Why this order: docs/validation/tolerance-cost.md.

mod seeds;

use super::{placement_intact, rows_at, LimitParams};
use crate::study::rows::{label, FrictionRow};
use crate::study::verdict::{superlubric, Verdict};
use anyhow::Result;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use surrogate::solver::Solver;
use surrogate::units::deg_to_rad;

/// Samples estimated at once (fixed: which samples are estimated must not depend on the thread
/// count).
const BATCH: usize = 4;

/// An offset (θ offset, direction offset) in degrees from the nominal.
pub type Offset = (f64, f64);

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
    /// `direction_step` ([`super::offsets`]).
    pub fn new(theta_tol: f64, direction_tol: f64, theta_step: f64, direction_step: f64) -> Self {
        ToleranceBox {
            theta_offsets_deg: super::offsets(theta_tol, theta_step),
            direction_offsets_deg: super::offsets(direction_tol, direction_step),
        }
    }

    /// Whether the box is the nominal point alone.
    pub fn is_point(&self) -> bool {
        self.theta_offsets_deg.len() == 1 && self.direction_offsets_deg.len() == 1
    }

    /// The corners of the box (θ offset, direction offset), distinct, direction outer and θ
    /// inner from the negative side: four, two where one tolerance is 0, none for a point.
    /// Exactly the extreme offsets of [`ToleranceBox::samples`] (−0 read as 0).
    pub fn corners(&self) -> Vec<Offset> {
        if self.is_point() {
            return Vec::new();
        }
        let ends = |o: &[f64]| {
            let mut e = vec![o[0] + 0.0, o[o.len() - 1] + 0.0];
            e.dedup();
            e
        };
        let th = ends(&self.theta_offsets_deg);
        ends(&self.direction_offsets_deg)
            .into_iter()
            .flat_map(|d| th.iter().map(move |&t| (t, d)))
            .collect()
    }

    /// Every sample (θ offset, direction offset) except the nominal, in the order in which a
    /// failure is most likely found early: corners first, then the rest of the box by its
    /// distance from the nominal (farthest first; the box scaled to a square), the two axes
    /// among them.
    pub fn samples(&self) -> Vec<Offset> {
        let th: Vec<f64> = self.theta_offsets_deg.clone();
        let di: Vec<f64> = self.direction_offsets_deg.clone();
        let tmax = th.iter().fold(0.0f64, |m, t| m.max(t.abs())).max(1e-12);
        let dmax = di.iter().fold(0.0f64, |m, d| m.max(d.abs())).max(1e-12);
        let mut all: Vec<Offset> = th
            .iter()
            .flat_map(|&t| di.iter().map(move |&d| (t, d)))
            .filter(|&o| o != (0.0, 0.0))
            .collect();
        let r = |p: &Offset| {
            let (x, y) = ((p.0 / tmax).abs(), (p.1 / dmax).abs());
            x.max(y) * 2.0 + x + y
        };
        all.sort_by(|a, b| {
            r(b).total_cmp(&r(a))
                .then(a.0.total_cmp(&b.0))
                .then(a.1.total_cmp(&b.1))
        });
        all
    }
}

/// What is known of one sample of the box.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SampleState {
    /// Substrate realisation (index into the solvers; 0: the design's own scene).
    pub seed: usize,
    /// θ offset (degrees).
    pub theta_offset_deg: f64,
    /// Direction offset (degrees).
    pub direction_offset_deg: f64,
    /// Leading loads intact at the placement (the screen's bound of its limit).
    pub cap: usize,
    /// Estimated rows by load index (`None`: not estimated).
    pub rows: Vec<Option<FrictionRow>>,
}

/// The state of a robust search: every estimate made so far and what follows from it. Stored
/// between levels of a design, so that an interrupted design resumes with the same result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RobustState {
    /// The samples: `[0]` is the nominal on the design's own scene.
    pub samples: Vec<SampleState>,
    /// The nominal limit (loads).
    pub nominal_to: usize,
    /// Upper bound of the robust limit (loads); exact when `exact`.
    pub bound: usize,
    /// The sample that set `bound`.
    pub worst: usize,
    /// Whether `bound` is the robust limit.
    pub exact: bool,
    /// θ window at the nominal limit load (degrees), once computed.
    pub theta_window_deg: Option<f64>,
    /// Direction window at the nominal limit load (degrees), once computed.
    pub direction_window_deg: Option<f64>,
    /// Friction paths solved.
    pub paths: usize,
    /// (sample, load) estimates made.
    pub loads_estimated: usize,
}

/// The robust limit and window of one design (load counts index [`LimitParams::loads`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Robust {
    /// Loads up to which every sample of the box (and every seed) is superlubric (0: none); an
    /// upper bound when not `exact`.
    pub superlubric_to: usize,
    /// The sample (θ offset, direction offset, seed index) that set the limit (the nominal when
    /// the box does not lower it).
    pub worst: (f64, f64, usize),
    /// Half-width (degrees) of θ around the nominal inside which every θ-axis sample is
    /// superlubric at every load up to the nominal limit (`None`: not computed).
    pub theta_window_deg: Option<f64>,
    /// The same along the direction axis.
    pub direction_window_deg: Option<f64>,
    /// The worst verdict over every load up to the limit and every sample of the box estimated
    /// there (`Not` when 0; `worst_verdict`).
    pub verdict: Verdict,
    /// Friction paths solved (cost).
    pub paths: usize,
    /// Whether `superlubric_to` is exact.
    pub exact: bool,
}

/// The worst verdict over every load up to `b` (a load count) of every sample, counting the
/// rows estimated (with an exact limit: all of them); `Not` when `b` is 0. So a sample
/// borderline at a load below the limit makes the limit borderline.
pub fn worst_verdict(samples: &[SampleState], b: usize, mu_sl: f64, p_crit: f64) -> Verdict {
    if b == 0 {
        return Verdict::Not;
    }
    Verdict::worst(
        samples
            .iter()
            .flat_map(|s| s.rows.iter().take(b).filter_map(Option::as_ref)),
        mu_sl,
        p_crit,
    )
}

/// A robust search on one design (see the module docs).
pub struct RobustSearch<'a> {
    solvers: &'a [Solver],
    theta_deg: f64,
    direction_deg: f64,
    p: &'a LimitParams,
    p_crit: f64,
    /// Everything known.
    pub state: RobustState,
}

impl<'a> RobustSearch<'a> {
    /// A search on (θ, direction) (degrees) over `bx` × every solver (one per substrate seed;
    /// the first is the design's own scene, whose nominal rows are `nominal`, loads ascending
    /// from the first). Cost: one multi-load screen solve per θ offset and seed.
    pub fn new(
        solvers: &'a [Solver],
        theta_deg: f64,
        direction_deg: f64,
        nominal: &[FrictionRow],
        bx: &ToleranceBox,
        p: &'a LimitParams,
    ) -> Self {
        let p_crit = solvers[0].scene().coating.p_crit;
        let n = p.loads.len();
        let mut offsets: Vec<(usize, Offset)> = vec![(0, (0.0, 0.0))];
        for si in 0..solvers.len() {
            if si > 0 {
                offsets.push((si, (0.0, 0.0)));
            }
            offsets.extend(bx.samples().into_iter().map(|o| (si, o)));
        }
        let caps: Vec<Vec<usize>> = solvers
            .iter()
            .map(|s| {
                bx.theta_offsets_deg
                    .par_iter()
                    .map(|&dt| placement_intact(s, deg_to_rad(label(theta_deg + dt)), &p.loads))
                    .collect()
            })
            .collect();
        let cap_of = |si: usize, dt: f64| {
            let i = bx.theta_offsets_deg.iter().position(|&t| t == dt);
            i.map_or(n, |i| caps[si][i])
        };
        let samples: Vec<SampleState> = offsets
            .iter()
            .map(|&(si, (dt, dd))| SampleState {
                seed: si,
                theta_offset_deg: dt,
                direction_offset_deg: dd,
                cap: cap_of(si, dt),
                rows: vec![None; n],
            })
            .collect();
        let mut state = RobustState {
            samples,
            nominal_to: 0,
            bound: n,
            worst: 0,
            exact: false,
            theta_window_deg: None,
            direction_window_deg: None,
            paths: 0,
            loads_estimated: 0,
        };
        for r in nominal {
            if let Some(k) = crate::study::load::Load::position(&p.loads, r.load_mN) {
                state.samples[0].rows[k] = Some(r.clone());
            }
        }
        let mut s = RobustSearch {
            solvers,
            theta_deg,
            direction_deg,
            p,
            p_crit,
            state,
        };
        s.state.nominal_to = super::superlubric_count(nominal, p_crit, p.mu_superlubric);
        s.tighten();
        s
    }

    /// Resumes a stored search (its samples must be those of the same design and box).
    pub fn resume(
        solvers: &'a [Solver],
        theta_deg: f64,
        direction_deg: f64,
        p: &'a LimitParams,
        state: RobustState,
    ) -> Self {
        RobustSearch {
            solvers,
            theta_deg,
            direction_deg,
            p_crit: solvers[0].scene().coating.p_crit,
            p,
            state,
        }
    }

    /// Whether the search is over: exact, or no load is left.
    pub fn settled(&self) -> bool {
        self.state.exact || self.state.bound == 0
    }

    fn ok(&self, r: &FrictionRow) -> bool {
        superlubric(r, self.p_crit, self.p.mu_superlubric)
    }

    /// What is known of sample `i`: its limit is at most this (its placement bound, or the
    /// first estimated load that is not superlubric).
    fn limit_bound(&self, i: usize) -> usize {
        let s = &self.state.samples[i];
        let failed = s
            .rows
            .iter()
            .position(|r| r.as_ref().is_some_and(|r| !self.ok(r)));
        failed.map_or(s.cap, |k| k.min(s.cap))
    }

    /// Lowers the bound to what the estimates so far prove (the first sample in order that
    /// attains it becomes the worst).
    fn tighten(&mut self) {
        let st = &self.state;
        let mut bound = st.bound.min(st.nominal_to);
        let mut worst = st.worst;
        for i in 0..st.samples.len() {
            let b = self.limit_bound(i);
            if b < bound {
                bound = b;
                worst = i;
            }
        }
        self.state.bound = bound;
        self.state.worst = worst;
        if bound == 0 {
            self.state.exact = true;
        }
    }

    /// Estimates the loads `which` of the samples `todo` (one path each, in parallel) and
    /// records the rows.
    fn estimate(&mut self, todo: &[(usize, Vec<usize>)]) -> Result<()> {
        let st = &self.state;
        let done: Vec<Result<Vec<FrictionRow>>> = todo
            .par_iter()
            .map(|(i, which)| {
                let s = &st.samples[*i];
                rows_at(
                    &self.solvers[s.seed],
                    label(self.theta_deg + s.theta_offset_deg),
                    label(self.direction_deg + s.direction_offset_deg),
                    which,
                    self.p,
                )
            })
            .collect();
        for ((i, which), rows) in todo.iter().zip(done) {
            let rows = rows?;
            self.state.paths += 1;
            self.state.loads_estimated += rows.len();
            for (&k, r) in which.iter().zip(rows) {
                self.state.samples[*i].rows[k] = Some(r);
            }
        }
        Ok(())
    }

    /// The samples in search order: the worst first, then the list order.
    fn order(&self) -> Vec<usize> {
        let w = self.state.worst;
        std::iter::once(w)
            .chain((0..self.state.samples.len()).filter(|&i| i != w))
            .collect()
    }

    /// One step: runs until the bound falls or the limit is proven exact (see the module docs).
    pub fn step(&mut self) -> Result<()> {
        if self.settled() {
            return Ok(());
        }
        let u = self.state.bound;
        let k = u - 1;
        // 1. disproof at the single load W_U
        let todo: Vec<usize> = self
            .order()
            .into_iter()
            .filter(|&i| self.state.samples[i].rows[k].is_none())
            .collect();
        for batch in todo.chunks(BATCH) {
            let jobs: Vec<(usize, Vec<usize>)> = batch.iter().map(|&i| (i, vec![k])).collect();
            self.estimate(&jobs)?;
            // a sample that fails at W_U: its own limit (the loads below, one path) is the
            // new bound, often many loads lower (knife-edge designs)
            let below: Vec<(usize, Vec<usize>)> = batch
                .iter()
                .filter(|&&i| self.limit_bound(i) < u)
                .map(|&i| {
                    let rows = &self.state.samples[i].rows;
                    (i, (0..k).filter(|&j| rows[j].is_none()).collect::<Vec<_>>())
                })
                .filter(|(_, w)| !w.is_empty())
                .collect();
            self.estimate(&below)?;
            self.tighten();
            if self.state.bound < u {
                return Ok(());
            }
        }
        // 2. verification of the loads below W_U, one path per sample
        let todo: Vec<(usize, Vec<usize>)> = self
            .order()
            .into_iter()
            .map(|i| {
                let rows = &self.state.samples[i].rows;
                (i, (0..k).filter(|&j| rows[j].is_none()).collect::<Vec<_>>())
            })
            .filter(|(_, w)| !w.is_empty())
            .collect();
        for batch in todo.chunks(BATCH) {
            self.estimate(batch)?;
            self.tighten();
            if self.state.bound < u {
                return Ok(());
            }
        }
        self.state.exact = true;
        Ok(())
    }

    /// Steps until settled or the bound falls to `floor` or below.
    pub fn run_above(&mut self, floor: usize) -> Result<()> {
        while !self.settled() && self.state.bound > floor {
            self.step()?;
        }
        Ok(())
    }

    /// Whether sample `i` is superlubric at every load up to the nominal limit, estimating
    /// what is missing: first the load at the limit (one path), then the loads below it.
    fn holds_to_nominal(&mut self, group: &[usize]) -> Result<bool> {
        let n = self.state.nominal_to;
        if n == 0 {
            return Ok(true);
        }
        let fails = |s: &Self| group.iter().any(|&i| s.limit_bound(i) < n);
        if fails(self) {
            return Ok(false);
        }
        let top: Vec<(usize, Vec<usize>)> = group
            .iter()
            .filter(|&&i| self.state.samples[i].rows[n - 1].is_none())
            .map(|&i| (i, vec![n - 1]))
            .collect();
        self.estimate(&top)?;
        if fails(self) {
            return Ok(false);
        }
        let below: Vec<(usize, Vec<usize>)> = group
            .iter()
            .map(|&i| {
                let rows = &self.state.samples[i].rows;
                (i, (0..n - 1).filter(|&j| rows[j].is_none()).collect())
            })
            .filter(|(_, w): &(usize, Vec<usize>)| !w.is_empty())
            .collect();
        self.estimate(&below)?;
        Ok(!fails(self))
    }

    /// The θ and direction windows at the nominal limit load: the largest sampled |offset| h
    /// on each axis such that every axis sample (every seed) with |offset| ≤ h is superlubric at
    /// every load up to the nominal limit. Estimated outwards, stopping at the first failure
    /// (a knife-edge design costs two paths per axis).
    pub fn windows(&mut self) -> Result<()> {
        if self.state.theta_window_deg.is_some() {
            return Ok(());
        }
        let mut w = [0.0f64; 2];
        for (axis, slot) in w.iter_mut().enumerate() {
            let on_axis = |s: &SampleState| {
                let (a, b) = (s.theta_offset_deg, s.direction_offset_deg);
                if axis == 0 {
                    (b == 0.0 && a != 0.0).then_some(a.abs())
                } else {
                    (a == 0.0 && b != 0.0).then_some(b.abs())
                }
            };
            let mut dist: Vec<f64> = self.state.samples.iter().filter_map(on_axis).collect();
            dist.sort_by(f64::total_cmp);
            dist.dedup();
            for d in dist {
                let group: Vec<usize> = (0..self.state.samples.len())
                    .filter(|&i| on_axis(&self.state.samples[i]) == Some(d))
                    .collect();
                if !self.holds_to_nominal(&group)? {
                    break;
                }
                *slot = d;
            }
        }
        self.state.theta_window_deg = Some(w[0]);
        self.state.direction_window_deg = Some(w[1]);
        Ok(())
    }

    /// The result so far.
    pub fn result(&self) -> Robust {
        let st = &self.state;
        let b = st.bound;
        let verdict = worst_verdict(&st.samples, b, self.p.mu_superlubric, self.p_crit);
        let w = &st.samples[st.worst];
        Robust {
            superlubric_to: b,
            worst: (w.theta_offset_deg, w.direction_offset_deg, w.seed),
            theta_window_deg: st.theta_window_deg,
            direction_window_deg: st.direction_window_deg,
            verdict,
            paths: st.paths,
            exact: st.exact,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_samples_cover_the_box_once_corners_first() {
        let bx = ToleranceBox::new(0.1, 0.5, 0.05, 0.25);
        let s = bx.samples();
        assert_eq!(s.len(), 5 * 5 - 1);
        let mut u = s.clone();
        u.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        u.dedup();
        assert_eq!(u.len(), s.len());
        for c in &s[..4] {
            assert_eq!((c.0.abs(), c.1.abs()), (0.1, 0.5));
        }
        assert!(ToleranceBox::new(0.0, 0.0, 0.02, 0.25).is_point());
        assert_eq!(
            bx.corners(),
            vec![(-0.1, -0.5), (0.1, -0.5), (-0.1, 0.5), (0.1, 0.5)]
        );
        for c in bx.corners() {
            assert!(s.contains(&c));
        }
        assert_eq!(
            ToleranceBox::new(0.0, 0.5, 0.02, 0.25).corners(),
            vec![(0.0, -0.5), (0.0, 0.5)]
        );
        assert!(ToleranceBox::new(0.0, 0.0, 0.02, 0.25).corners().is_empty());
    }

    /// The verdict of a limit is the worst over every load up to it and every sample: a corner
    /// borderline at the lowest load makes a limit of two loads borderline; loads above the
    /// limit and rows not estimated do not count.
    #[test]
    fn the_verdict_is_the_worst_below_the_limit_over_every_sample() {
        let row = |mu: f64, p_gpa: f64| {
            let mut r = FrictionRow::new(
                "x",
                0.0,
                0.0,
                0.0,
                1e-3,
                &Err(surrogate::SceneError::invalid("x", 0.0, "y")),
            );
            r.error.clear();
            r.mu_est = Some(mu);
            r.p_max_GPa = Some(p_gpa);
            r
        };
        let sample = |rows: Vec<Option<FrictionRow>>| SampleState {
            seed: 0,
            theta_offset_deg: 0.0,
            direction_offset_deg: 0.0,
            cap: rows.len(),
            rows,
        };
        let clear = || Some(row(0.010, 3.0));
        let samples = vec![
            sample(vec![clear(), clear(), Some(row(0.05, 5.0))]),
            sample(vec![Some(row(0.018, 3.0)), clear(), None]),
            sample(vec![clear(), None, Some(row(0.019, 3.9))]),
        ];
        let v = |b: usize| worst_verdict(&samples, b, 0.02, 4e9);
        assert_eq!(v(0), Verdict::Not);
        assert_eq!(v(1), Verdict::Borderline);
        assert_eq!(v(2), Verdict::Borderline, "borderline at the lowest load");
        let clean = vec![samples[0].clone(), samples[0].clone()];
        assert_eq!(worst_verdict(&clean, 2, 0.02, 4e9), Verdict::Superlubric);
        assert_eq!(worst_verdict(&clean, 3, 0.02, 4e9), Verdict::Not);
    }
}
