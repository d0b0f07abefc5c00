//! The superlubric limit as the design's stages share it: its knobs ([`DesignParams::limit`]),
//! their record in the stored stages' inputs ([`limit_record`]), the tolerance box
//! ([`tolerance_box`]), one solver per substrate realisation ([`seed_solvers`]) and the
//! pattern's own solver built on first use ([`solver_of`]). The robust
//! search, the tolerance map and the P_crit sweep all build on these, each from here.

use super::params::{DesignParams, DesignScene};
use crate::study::record;
use crate::study::tolerance::{LimitParams, ToleranceBox};
use anyhow::Result;
use serde_json::{json, Value};
use surrogate::solver::Solver;
use surrogate::units::rad_to_deg;

impl DesignParams {
    /// The knobs of a superlubric limit: the loads (N), the threshold μ_sl, the contact line
    /// and the friction estimate's knobs. Cost: a copy of the load list.
    pub fn limit(&self) -> LimitParams {
        LimitParams {
            loads: self.loads.to_vec(),
            mu_superlubric: self.mu_superlubric,
            line: self.alpha_scan.line,
            friction: self.friction,
        }
    }

    /// The loads as their mN labels, as every stored stage records them.
    pub(super) fn load_labels_mn(&self) -> Vec<f64> {
        self.loads.labels_mn()
    }
}

/// The tolerance box of the design's `theta_tol_deg` × `direction_tol_deg` (degrees, ±), sampled
/// at most `theta_tol_step_deg` / `direction_tol_step_deg` apart.
pub fn tolerance_box(p: &DesignParams) -> ToleranceBox {
    ToleranceBox::new(
        p.tolerance.theta_tol_deg,
        p.tolerance.direction_tol_deg,
        p.tolerance.theta_tol_step_deg,
        p.tolerance.direction_tol_step_deg,
    )
}

/// The recorded inputs of a superlubric limit (loads in mN, threshold, contact line in
/// degrees, estimate knobs).
pub(super) fn limit_record(p: &DesignParams) -> Value {
    json!({
        "load_mN": p.load_labels_mn(),
        "mu_superlubric": p.mu_superlubric,
        "line_deg": p.alpha_scan.line.map(rad_to_deg),
        "friction": record::friction_knobs(&p.friction),
    })
}

/// One solver per substrate realisation: the scene's own (reusing `own` when built), then one
/// per extra seed of `p.tolerance.seeds`. Cost: one solver set-up (pair search) per realisation.
pub(super) fn seed_solvers(
    ds: &DesignScene,
    p: &DesignParams,
    own: Option<Solver>,
) -> Result<Vec<Solver>> {
    let mut sc = ds.scene.clone();
    sc.slider.theta = 0.0;
    let mut v = vec![match own {
        Some(s) => s,
        None => Solver::new(&sc)?,
    }];
    for &seed in &p.tolerance.seeds {
        if seed != sc.substrate.seed {
            let mut o = sc.clone();
            o.substrate.seed = seed;
            v.push(Solver::new(&o)?);
        }
    }
    Ok(v)
}

/// The pattern's solver (slider at θ = 0, each query rotates it), built on first use in `slot`.
/// Cost: one scene build and pair-search setup, once.
pub(super) fn solver_of<'a>(slot: &'a mut Option<Solver>, ds: &DesignScene) -> Result<&'a Solver> {
    if slot.is_none() {
        let mut sc = ds.scene.clone();
        sc.slider.theta = 0.0;
        *slot = Some(Solver::new(&sc)?);
    }
    slot.as_ref().ok_or_else(|| anyhow::anyhow!("no solver"))
}
