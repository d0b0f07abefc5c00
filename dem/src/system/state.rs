//! [`State`]: everything that evolves during a run (positions, velocities, forces, contact
//! history, phase flags). Checkpointed bit-exactly by [`crate::checkpoint`].

/// Tangential history of one listed pair.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairHist {
    /// Elastic tangential displacement ξ (m).
    pub xi: [f64; 3],
    /// Whether this pair's coating has failed at any time since it was listed.
    pub ever_failed: bool,
}

/// Slider–substrate candidate pairs, sorted by (slider, substrate), with their history.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PairList {
    /// Slider sphere index.
    pub i: Vec<u32>,
    /// Substrate sphere index.
    pub j: Vec<u32>,
    /// History per pair.
    pub hist: Vec<PairHist>,
}

/// Dynamic state (SI). Arrays are indexed like the [`super::SystemSpec`] lists.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct State {
    /// Steps taken.
    pub step: u64,
    /// Simulated time (s).
    pub t: f64,
    /// Substrate positions (x, y) (m).
    pub sub_x: Vec<[f64; 2]>,
    /// Substrate velocities (m/s).
    pub sub_v: Vec<[f64; 2]>,
    /// Substrate forces (N).
    pub sub_f: Vec<[f64; 2]>,
    /// Slider sphere positions (m).
    pub sl_x: Vec<[f64; 3]>,
    /// Slider sphere velocities (m/s).
    pub sl_v: Vec<[f64; 3]>,
    /// Slider sphere forces (N) (z: contact only when rigid-z).
    pub sl_f: Vec<[f64; 3]>,
    /// Control-layer centre of mass (x, y) and reference height Z (m).
    pub cl_x: [f64; 3],
    /// Control-layer velocity (m/s).
    pub cl_v: [f64; 3],
    /// Control-layer force (N).
    pub cl_f: [f64; 3],
    /// Support position (m).
    pub support: [f64; 2],
    /// Support position when the spring was attached (m).
    pub support0: [f64; 2],
    /// Support velocity (m/s).
    pub support_v: [f64; 2],
    /// Whether the pulling spring is attached.
    pub spring_on: bool,
    /// Whether the control layer is held laterally (equilibration).
    pub held_xy: bool,
    /// Listed pairs with history.
    pub pairs: PairList,
    /// Substrate positions at the last neighbour-list build (m).
    pub ref_sub: Vec<[f64; 2]>,
    /// Slider positions at the last neighbour-list build (m).
    pub ref_sl: Vec<[f64; 3]>,
    /// Neighbour-list builds so far.
    pub builds: u64,
}
