//! The superlubric limit as the design's stages share it ([`LimitKnobs`]): the load ladder,
//! the threshold μ_sl, the contact line, the friction estimate's knobs and the fabrication
//! tolerance; their record in the stored stages' inputs ([`LimitKnobs::record`]), the
//! tolerance box ([`LimitKnobs::tolerance_box`]), one solver per substrate realisation
//! ([`seed_solvers`]) and the pattern's own solver built on first use ([`solver_of`]). Every
//! stage that estimates a limit (the evaluation, the robust search, the ranking, the DEM's
//! estimates and corners, the report data, the yield) reads them from here.

mod tolerance_params;

pub use tolerance_params::ToleranceParams;

use super::model::{AnswerRule, DesignScene};
use crate::study::load::Loads;
use crate::study::record;
use crate::study::tolerance::{LimitParams, ToleranceBox};
use anyhow::Result;
use serde_json::{json, Value};
use surrogate::friction::FrictionParams;
use surrogate::solver::Solver;
use surrogate::units::rad_to_deg;

/// The knobs every stage shares (SI): built once per design from its parameters
/// (`DesignParams::limit_knobs`), borrowed by each stage. Cost: a copy of the load list.
#[derive(Debug, Clone)]
pub struct LimitKnobs {
    /// Normal loads W (N), strictly increasing: the load ladder of every stage.
    pub loads: Loads,
    /// Friction coefficient below which a design counts as superlubric (study: 0.02).
    pub mu_superlubric: f64,
    /// Contact-line angle (rad from x) for every θ; `None`: the moiré estimate.
    pub line: Option<f64>,
    /// The friction estimate's knobs.
    pub friction: FrictionParams,
    /// The fabrication tolerance the robust limit holds over.
    pub tolerance: ToleranceParams,
}

impl LimitKnobs {
    /// The knobs of a superlubric limit: the loads (N), the threshold μ_sl, the contact line
    /// and the friction estimate's knobs. Cost: a copy of the load list.
    pub fn limit(&self) -> LimitParams {
        LimitParams {
            loads: self.loads.to_vec(),
            mu_superlubric: self.mu_superlubric,
            line: self.line,
            friction: self.friction,
        }
    }

    /// The loads as their mN labels, as every stored stage records them.
    pub fn load_labels_mn(&self) -> Vec<f64> {
        self.loads.labels_mn()
    }

    /// The tolerance box of `theta_tol_deg` × `direction_tol_deg` (degrees, ±), sampled at
    /// most `theta_tol_step_deg` / `direction_tol_step_deg` apart.
    pub fn tolerance_box(&self) -> ToleranceBox {
        let t = &self.tolerance;
        ToleranceBox::new(
            t.theta_tol_deg,
            t.direction_tol_deg,
            t.theta_tol_step_deg,
            t.direction_tol_step_deg,
        )
    }

    /// The rule each pattern's answer is decided by, the DEM confirming the top `designs`:
    /// μ_sl, and whether the tolerance box has corners whose runs must confirm too.
    pub fn answer_rule(&self, designs: usize) -> AnswerRule {
        AnswerRule {
            designs,
            mu_superlubric: self.mu_superlubric,
            corners: !self.tolerance_box().is_point(),
        }
    }

    /// The recorded inputs of a superlubric limit (loads in mN, threshold, contact line in
    /// degrees, estimate knobs).
    pub fn record(&self) -> Value {
        json!({
            "load_mN": self.load_labels_mn(),
            "mu_superlubric": self.mu_superlubric,
            "line_deg": self.line.map(rad_to_deg),
            "friction": record::friction_knobs(&self.friction),
        })
    }
}

/// One solver per substrate realisation: the scene's own (reusing `own` when built), then one
/// per extra seed of `seeds`. Cost: one solver set-up (pair search) per realisation.
pub fn seed_solvers(ds: &DesignScene, seeds: &[u64], own: Option<Solver>) -> Result<Vec<Solver>> {
    let mut sc = ds.scene.clone();
    sc.slider.theta = 0.0;
    let mut v = vec![match own {
        Some(s) => s,
        None => Solver::new(&sc)?,
    }];
    for &seed in seeds {
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
pub fn solver_of<'a>(slot: &'a mut Option<Solver>, ds: &DesignScene) -> Result<&'a Solver> {
    if slot.is_none() {
        let mut sc = ds.scene.clone();
        sc.slider.theta = 0.0;
        *slot = Some(Solver::new(&sc)?);
    }
    slot.as_ref().ok_or_else(|| anyhow::anyhow!("no solver"))
}
