//! [`DesignParams`]: every knob of `superlube design`, as the composition of each stage's own
//! params (each defined beside its stage) and the knobs the stages share.

pub use super::alpha_scan_params::AlphaScanParams;
pub use super::confirm_params::ConfirmParams;
pub use super::screen_params::ScreenStageParams;
pub use super::shortlist_params::ShortlistParams;
pub use super::tolerance_params::ToleranceParams;
use crate::study::load::Loads;
use surrogate::friction::FrictionParams;

/// One pattern pair of a design: its name (the pattern, or a scene file's stem; used in file
/// names), the validated scene (SI, θ = 0), the scene flags that reproduce it on another
/// command's command line, and the warnings to report.
#[derive(Debug, Clone)]
pub struct DesignScene {
    /// Name used in the report and the file names (`square-tri`, `my_scene`).
    pub name: String,
    /// The scene (SI); its `slider.theta` is ignored (θ is swept).
    pub scene: surrogate::Scene,
    /// Scene flags reproducing it (`--pattern square-tri --sigma-h-um 0.01`).
    pub flags: Vec<String>,
    /// Warnings about the scene (edge overhang…).
    pub warnings: Vec<String>,
    /// What `superlube patterns` recorded of it, when it comes from an `index.csv`.
    pub facts: Option<crate::study::patterns::CandidateFacts>,
    /// What the design knows of it as a recipe of `design --vary` (why it lies outside the
    /// validated range; the DEM decides such a recipe, [`super::confirm`]); `None`: not a
    /// recipe.
    pub recipe: Option<crate::study::recipe::RecipeFacts>,
}

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
    /// The α scan's, the contact line included ([`super::alpha_scan`]).
    pub alpha_scan: AlphaScanParams,
    /// The friction estimate's knobs ([`super::estimate`]), shared by every stage that
    /// estimates a limit (the robust search, the DEM's comparisons, the tolerance maps).
    pub friction: FrictionParams,
    /// The fabrication tolerance the robust limit holds over ([`super::tolerance_box`]; the
    /// robust search, the tolerance maps, the DEM's corners and the yield use it).
    pub tolerance: ToleranceParams,
    /// The DEM confirmation's ([`super::confirm`]).
    pub confirm: ConfirmParams,
    /// The yield of each answer over fabrication ([`super::yield_stage`]); `None`: the stage
    /// does not run (the default: its DEM decisions take minutes per answer).
    pub fab_yield: Option<super::yield_params::YieldStageParams>,
}
