//! What the shortlist ([`super::super::shortlist`]) finds of a pattern's screen: each
//! orientation's coating-intact load ([`Orientation`]) and the levels they group into ([`Level`]).

/// What the screen says about one orientation.
#[derive(Debug, Clone, PartialEq)]
pub struct Orientation {
    /// θ (degrees, as screened).
    pub theta_deg: f64,
    /// Highest load (N) up to which the coating is intact at every load of the list; 0: none.
    pub w_intact: f64,
    /// P_max (Pa) at `w_intact` (at the lowest load when `w_intact` is 0).
    pub p_max: f64,
    /// Contacts at that load.
    pub contacts: usize,
}

/// One level of the shortlist: the orientations whose coating survives up to `load`.
#[derive(Debug, Clone, PartialEq)]
pub struct Level {
    /// The level's load `W_c` (N).
    pub load: f64,
    /// Orientations at this level.
    pub size: usize,
    /// The kept ones, best first.
    pub picks: Vec<Orientation>,
    /// Whether this is the top level of the loads asked (its load is the highest load).
    pub top: bool,
}
