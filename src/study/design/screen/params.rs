//! [`ScreenStageParams`]: the knobs of the design's screen ([`super::ScreenStage`]).

/// The screen's knobs: the θ list and its symmetry cut (the loads are the design's own).
#[derive(Debug, Clone, PartialEq)]
pub struct ScreenStageParams {
    /// Orientations θ (degrees) as given, before the symmetry cut.
    pub thetas_deg: Vec<f64>,
    /// `--theta` was not given: `thetas_deg` is the default `0:30:0.1`, and a pattern whose
    /// domain it does not span is screened over its whole domain
    /// ([`super::domain::default_domain`]).
    pub theta_default: bool,
    /// Cut θ to the pattern's fundamental domain ([`crate::study::design::symmetry_words`]).
    pub symmetry_cut: bool,
}
