//! The critical load of one fabricated device as a continuous value ([`CriticalLoad`]): the
//! highest load up to which it stays superlubric, found on the design's load ladder and then
//! by bisection between two rungs to a relative resolution, with the bracket of the estimate's
//! verdict band around it.
//!
//! Three properties of a load W, each by the estimate at (θ + δθ, d + δd) on the device's
//! substrate, pulled along d + δd in the substrate frame ([`crate::study::tolerance::rows_at`]):
//! - **low** — the verdict is `superlubric` (outside the band on the good side);
//! - **critical** — the design's rule [`superlubric`]: coating intact on the path and
//!   μ_est < μ_sl (no estimate, or locked in: not);
//! - **high** — the verdict is not `not` (superlubric or borderline).
//!
//! Each is true at every load up to some W_P and false just above: W_low ≤ W_c ≤ W_high (a
//! `superlubric` verdict implies the rule, the rule implies "not `not`"). The ladder is scanned
//! upwards ([`crate::study::tolerance::placement_intact`] sizes the first path) until a row is
//! `not`; each W_P then lies between its last good rung and the next, and is bisected there to
//! `resolution` × W (the estimate assumed monotone inside one rung; probes are shared by the
//! three bisections). Reported: the highest load shown good, so the true W_P lies within the
//! resolution above it. A device good at every rung is censored at the top rung.
//!
//! Cost: one path over the rungs up to the failure, then about log2(rung / (resolution · W))
//! single-load paths per property (5 for 0.35 mN rungs at 1 % of 2 mN), shared where the
//! brackets fall between the same rungs: typically 8–15 single-load estimates per device.

use crate::study::rows::FrictionRow;
use crate::study::tolerance::{placement_intact, rows_at, LimitParams, LOAD_CHUNK};
use crate::study::verdict::{superlubric, Verdict};
use anyhow::Result;
use serde::{Deserialize, Serialize};
use surrogate::solver::Solver;
use surrogate::units::{deg_to_rad, gpa_to_pa};

/// The default resolution of a critical load: 1 % of the load (`superlube yield --resolution`,
/// and the design's yield stage).
pub const DEFAULT_RESOLUTION: f64 = 0.01;

/// What ends superlubricity just above the critical load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Limit {
    /// The coating fails on the path (P_max > P_crit).
    Path,
    /// μ_est ≥ μ_sl with the coating intact.
    Friction,
    /// No estimate (the slider locks, or the solve fails).
    Error,
    /// Superlubric at every load of the ladder (censored at its top).
    None,
}

impl Limit {
    /// Why `r` is not superlubric (`None` if it is).
    fn of(r: &FrictionRow, p_crit: f64, mu_sl: f64) -> Limit {
        if superlubric(r, p_crit, mu_sl) {
            Limit::None
        } else if !r.error.is_empty() || r.mu_est.is_none() || r.p_max_GPa.is_none() {
            Limit::Error
        } else if r.p_max_GPa.is_some_and(|p| gpa_to_pa(p) > p_crit) {
            Limit::Path
        } else {
            Limit::Friction
        }
    }

    /// The lowercase word.
    pub fn word(self) -> &'static str {
        match self {
            Limit::Path => "path",
            Limit::Friction => "friction",
            Limit::Error => "error",
            Limit::None => "none",
        }
    }
}

/// The critical load of one device and its bracket (N).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CriticalLoad {
    /// W_c: highest load shown superlubric by the design's rule (0: not even near zero load).
    pub load: f64,
    /// W_low: highest load shown with a `superlubric` verdict (where the estimate enters the
    /// band).
    pub low: f64,
    /// W_high: highest load shown without a `not` verdict (where it leaves the band).
    pub high: f64,
    /// What ends superlubricity above W_c.
    pub limited_by: Limit,
    /// Whether W_c is the ladder's top (superlubric at every rung).
    pub censored: bool,
    /// Single loads estimated (the device's cost).
    pub estimates: usize,
    /// The lowest load (N) at which an estimate of the device has failing contacts on the
    /// springs mount in its resonance band (`mount_resonance`); `None`: no such estimate.
    /// A DEM run at or above it lets the DEM choose its model ([`CriticalLoad::resonant_at`]).
    pub resonance_from: Option<f64>,
    /// Every single-load estimate made, ascending in load: the device's P_max(W) and μ_est(W)
    /// that a DEM run's margin is transferred through ([`super::margin`]).
    #[serde(default)]
    pub probes: Vec<Probe>,
}

/// One single-load estimate of a device: the load (N) and what the estimate found there.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct Probe {
    /// Load (N).
    pub load: f64,
    /// The path's largest P_max (GPa; `None`: no estimate).
    pub p_max_GPa: Option<f64>,
    /// μ_est (`None`: no estimate, or locked in).
    pub mu_est: Option<f64>,
}

impl Probe {
    /// The probe of row `r` at load `w` (N); a row with an error has no estimate.
    fn of(w: f64, r: &FrictionRow) -> Probe {
        let ok = r.error.is_empty();
        Probe {
            load: w,
            p_max_GPa: r.p_max_GPa.filter(|_| ok),
            mu_est: r.mu_est.filter(|_| ok),
        }
    }
}

impl CriticalLoad {
    /// Whether the estimate puts the device on the mount's resonance at load `w` (N): some
    /// estimate at or below `w` has failing contacts there (contacts that fail at a load fail
    /// above it). Below that load the contacts the estimate sees are intact, and the DEM's
    /// model is the one asked for.
    pub fn resonant_at(&self, w: f64) -> bool {
        self.resonance_from.is_some_and(|r| r <= w)
    }
}

/// The three properties of a load (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Property {
    Low,
    Critical,
    High,
}

/// The probes of one device: every estimated row by load.
struct Probes<'a> {
    solver: &'a Solver,
    theta_deg: f64,
    direction_deg: f64,
    p: &'a LimitParams,
    p_crit: f64,
    rows: Vec<(f64, FrictionRow)>,
}

impl Probes<'_> {
    fn holds(&self, r: &FrictionRow, prop: Property) -> bool {
        let mu = self.p.mu_superlubric;
        match prop {
            Property::Low => Verdict::of_row(r, mu, self.p_crit) == Verdict::Superlubric,
            Property::Critical => superlubric(r, self.p_crit, mu),
            Property::High => Verdict::of_row(r, mu, self.p_crit) != Verdict::Not,
        }
    }

    /// Estimates `loads` (N, ascending) on one path and records the rows.
    fn estimate(&mut self, loads: &[f64]) -> Result<()> {
        let mut lp = self.p.clone();
        lp.loads = loads.to_vec();
        let which: Vec<usize> = (0..loads.len()).collect();
        let rows = rows_at(self.solver, self.theta_deg, self.direction_deg, &which, &lp)?;
        self.rows.extend(loads.iter().copied().zip(rows));
        Ok(())
    }

    /// The bracket (a, b) of `prop` inside (lo, hi) from the probes there (ascending; `prop`
    /// true at `lo`, false at `hi`; monotone inside).
    fn bracket(&self, prop: Property, lo: f64, hi: f64) -> (f64, f64) {
        let mut inside: Vec<&(f64, FrictionRow)> = self
            .rows
            .iter()
            .filter(|(w, _)| *w > lo && *w < hi)
            .collect();
        inside.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (mut a, mut b) = (lo, hi);
        for (w, r) in inside {
            if self.holds(r, prop) {
                a = *w;
            } else {
                b = *w;
                break;
            }
        }
        (a, b)
    }
}

/// The critical load of the device `solver` (its scene at θ = 0, the device's substrate and
/// P_crit) at (θ, direction) (degrees, direction in the substrate frame), on the ladder
/// `p.loads` (N, ascending), bisected to `resolution` (fraction of the load, > 0). See the
/// module docs for the rule and the cost.
pub fn critical_load(
    solver: &Solver,
    theta_deg: f64,
    direction_deg: f64,
    p: &LimitParams,
    resolution: f64,
) -> Result<CriticalLoad> {
    let p_crit = solver.scene().coating.p_crit;
    let ladder = &p.loads;
    let mut probes = Probes {
        solver,
        theta_deg,
        direction_deg,
        p,
        p_crit,
        rows: Vec::new(),
    };
    // the ladder, upwards until a row is `not`: the first path up to one rung past the
    // placement's intact load
    let cap = placement_intact(solver, deg_to_rad(theta_deg), ladder);
    let mut from = 0;
    let mut width = (cap + 1).max(1);
    while from < ladder.len() {
        let to = (from + width).min(ladder.len());
        probes.estimate(&ladder[from..to])?;
        if probes.rows[from..to]
            .iter()
            .any(|(_, r)| !probes.holds(r, Property::High))
        {
            break;
        }
        from = to;
        width = LOAD_CHUNK;
    }
    let scanned = probes.rows.len();
    let mut out = [0.0f64; 3];
    let mut censored = false;
    for (slot, prop) in [Property::Low, Property::Critical, Property::High]
        .into_iter()
        .enumerate()
    {
        let good = probes.rows[..scanned]
            .iter()
            .take_while(|(_, r)| probes.holds(r, prop))
            .count();
        if good == ladder.len() {
            out[slot] = ladder[ladder.len() - 1];
            censored |= prop == Property::Critical;
            continue;
        }
        let lo = if good == 0 { 0.0 } else { ladder[good - 1] };
        let hi = ladder[good];
        let floor = resolution * ladder[0];
        let (mut a, mut b) = probes.bracket(prop, lo, hi);
        while b - a > resolution * b && b > floor {
            let m = 0.5 * (a + b);
            probes.estimate(&[m])?;
            let r = &probes.rows[probes.rows.len() - 1].1;
            if probes.holds(r, prop) {
                a = m;
            } else {
                b = m;
            }
        }
        out[slot] = a;
    }
    // what ends it: the lowest probe above W_c that fails the rule
    let limited_by = if censored {
        Limit::None
    } else {
        probes
            .rows
            .iter()
            .filter(|(w, _)| *w > out[1])
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map_or(Limit::Error, |(_, r)| {
                Limit::of(r, p_crit, p.mu_superlubric)
            })
    };
    Ok(CriticalLoad {
        load: out[1],
        low: out[0].min(out[1]),
        high: out[2].max(out[1]),
        limited_by,
        censored,
        estimates: probes.rows.len(),
        resonance_from: probes
            .rows
            .iter()
            .filter(|(_, r)| r.mount_resonance == Some(true))
            .map(|(w, _)| *w)
            .min_by(f64::total_cmp),
        probes: {
            let mut v: Vec<Probe> = probes.rows.iter().map(|(w, r)| Probe::of(*w, r)).collect();
            v.sort_by(|a, b| a.load.total_cmp(&b.load));
            v
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use surrogate::friction::FrictionParams;
    use surrogate::units::{mn_to_n, rad_to_deg};
    use surrogate::Scene;

    /// The small tri-tri scene of the tolerance tests (15 µm slider, ≈ 80 spheres) and its
    /// solver at θ = 0, with the direction of α = 0 at θ = 30°.
    fn small() -> (Solver, f64) {
        let mut s = Scene::preset("tri-tri").unwrap();
        s.slider.radius = 15e-6;
        s.substrate.size = [60e-6, 60e-6];
        let line = crate::study::friction::line_at(&s, deg_to_rad(30.0), None);
        (Solver::new(&s).unwrap(), label(rad_to_deg(line.angle)))
    }

    use crate::study::rows::label;

    fn params(loads_mn: &[f64]) -> LimitParams {
        LimitParams {
            loads: loads_mn.iter().map(|&w| mn_to_n(w)).collect(),
            mu_superlubric: 0.02,
            line: None,
            friction: FrictionParams::default(),
        }
    }

    /// The bisected critical load equals a fine ladder scan's (every load a step of 0.5 % of
    /// the rung above apart) to the stated 1 % resolution; the bracket holds it.
    #[test]
    fn bisection_matches_a_fine_ladder_scan() {
        let (solver, dir) = small();
        let ladder = [0.01, 0.03, 0.06, 0.09, 0.12, 0.15];
        let p = params(&ladder);
        let res = 0.01;
        let c = critical_load(&solver, 30.0, dir, &p, res).unwrap();
        assert!(c.low <= c.load && c.load <= c.high, "{c:?}");
        assert!(
            !c.censored,
            "the small scene must fail within the ladder: {c:?}"
        );
        // the fine scan: the ladder's rungs around W_c, refined to steps of res/2 of the upper
        let top = *p.loads.iter().find(|&&w| w > c.load).unwrap();
        let bottom = p
            .loads
            .iter()
            .copied()
            .filter(|&w| w < top)
            .fold(0.0, f64::max);
        let step = 0.5 * res * top;
        let n = ((top - bottom) / step).ceil() as usize;
        let fine: Vec<f64> = (1..=n).map(|k| bottom + k as f64 * step).collect();
        let mut fp = p.clone();
        fp.loads = fine.clone();
        let which: Vec<usize> = (0..fine.len()).collect();
        let rows = rows_at(&solver, 30.0, dir, &which, &fp).unwrap();
        let p_crit = solver.scene().coating.p_crit;
        let good = rows
            .iter()
            .take_while(|r| superlubric(r, p_crit, 0.02))
            .count();
        let scan = if good == 0 { bottom } else { fine[good - 1] };
        assert!(
            (c.load - scan).abs() <= res * top + step,
            "bisection {} N vs fine scan {} N (rung {} N)",
            c.load,
            scan,
            top
        );
        assert!(c.limited_by != Limit::None);
    }
}
