//! [`DesignParams`]: every knob of `superlube design`, as the composition of each stage's own
//! params (each defined in its stage's folder) and the knobs the stages share. No stage
//! imports it: the pipeline's plan ([`super::pipeline::Plan`]) hands each stage its own part
//! and the shared [`LimitKnobs`].

pub use super::confirm::ConfirmParams;
pub use super::evaluate::AlphaScanParams;
use super::limit::LimitKnobs;
pub use super::limit::ToleranceParams;
use super::model::AnswerRule;
pub use super::model::DesignScene;
pub use super::screen::ScreenStageParams;
pub use super::shortlist::ShortlistParams;
use super::yield_stage::YieldStageParams;
use crate::study::load::Loads;
use crate::study::tolerance::ToleranceBox;
use surrogate::friction::FrictionParams;

/// Every knob of a design (SI inside; angles as the degree decimals the user meant, so that
/// every reproduction command prints them exactly): each stage's own params, and the knobs the
/// stages share (the load ladder, the superlubric threshold, the friction estimate's knobs).
#[derive(Debug, Clone)]
pub struct DesignParams {
    /// Normal loads W (N), strictly increasing: the load ladder of every stage.
    pub loads: Loads,
    /// Friction coefficient below which a design counts as superlubric (study: 0.02).
    pub mu_superlubric: f64,
    /// The screen's: the θ list and its symmetry cut ([`super::screen`]).
    pub screen: ScreenStageParams,
    /// The shortlist's ([`super::shortlist`]).
    pub shortlist: ShortlistParams,
    /// The α scan's, the contact line included ([`super::evaluate::alpha_scan`]).
    pub alpha_scan: AlphaScanParams,
    /// The friction estimate's knobs ([`super::evaluate::estimate`]), shared by every stage
    /// that estimates a limit (the robust search, the DEM's comparisons, the tolerance maps).
    pub friction: FrictionParams,
    /// The fabrication tolerance the robust limit holds over ([`LimitKnobs::tolerance_box`];
    /// the robust search, the tolerance maps, the DEM's corners and the yield use it).
    pub tolerance: ToleranceParams,
    /// The DEM confirmation's ([`super::confirm`]).
    pub confirm: ConfirmParams,
    /// The yield of each answer over fabrication ([`super::yield_stage`]); `None`: the stage
    /// does not run.
    pub fab_yield: Option<YieldStageParams>,
}

impl DesignParams {
    /// The knobs the stages share ([`LimitKnobs`]): the loads, μ_sl, the contact line, the
    /// estimate's knobs and the tolerance. Cost: a copy of the load list and the seeds.
    pub fn limit_knobs(&self) -> LimitKnobs {
        LimitKnobs {
            loads: self.loads.clone(),
            mu_superlubric: self.mu_superlubric,
            line: self.alpha_scan.line,
            friction: self.friction,
            tolerance: self.tolerance.clone(),
        }
    }

    /// The rule each pattern's answer is decided by ([`LimitKnobs::answer_rule`], the top
    /// `confirm.designs`). Cost: a copy of the loads.
    pub fn answer_rule(&self) -> AnswerRule {
        self.limit_knobs().answer_rule(self.confirm.designs)
    }
}

/// The tolerance box of the design's `theta_tol_deg` × `direction_tol_deg` (degrees, ±),
/// sampled at most `theta_tol_step_deg` / `direction_tol_step_deg` apart.
pub fn tolerance_box(p: &DesignParams) -> ToleranceBox {
    let t = &p.tolerance;
    ToleranceBox::new(
        t.theta_tol_deg,
        t.direction_tol_deg,
        t.theta_tol_step_deg,
        t.direction_tol_step_deg,
    )
}
