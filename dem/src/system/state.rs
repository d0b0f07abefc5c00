//! [`State`]: everything that evolves during a run (positions, velocities, forces, contact
//! history, the active set, phase flags). Checkpointed bit-exactly by [`crate::checkpoint`].

use crate::model::PairOut;

/// Tangential history of one listed pair.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairHist {
    /// Elastic tangential displacement ξ (m).
    pub xi: [f64; 3],
    /// Whether this pair's coating has failed at any time since it was listed.
    pub ever_failed: bool,
}

/// Slider–substrate candidate pairs (within `2R + skin` at the last build), sorted by
/// (slider, substrate), with their history. While a pair is in the active set its current
/// history lives in [`Active::hist`]; it is written back here at each re-evaluation.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PairList {
    /// Slider sphere index.
    pub i: Vec<u32>,
    /// Substrate sphere index.
    pub j: Vec<u32>,
    /// History per pair.
    pub hist: Vec<PairHist>,
}

/// The particles integrated step by step, packed densely (all of them when the active set is
/// off). Between re-evaluations these arrays are the truth for their particles; the global
/// arrays of [`State`] hold them as of the last re-evaluation.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Active {
    /// Global indices of the active slider spheres (ascending).
    pub sl: Vec<u32>,
    /// Their positions (m), velocities (m/s), forces (N) and positions at the last evaluation.
    pub sl_x: Vec<[f64; 3]>,
    /// Velocities (m/s).
    pub sl_v: Vec<[f64; 3]>,
    /// Forces (N) (z: the contact force only with `rigid_z`).
    pub sl_f: Vec<[f64; 3]>,
    /// Positions at the last evaluation (m).
    pub sl_x0: Vec<[f64; 3]>,
    /// Global indices of the active substrate spheres (ascending).
    pub sub: Vec<u32>,
    /// Their positions (x, y) (m).
    pub sub_x: Vec<[f64; 2]>,
    /// Velocities (m/s).
    pub sub_v: Vec<[f64; 2]>,
    /// Forces (N).
    pub sub_f: Vec<[f64; 2]>,
    /// Positions at the last evaluation (m).
    pub sub_x0: Vec<[f64; 2]>,
    /// Candidate-pair indices of the active pairs (ascending, so grouped by slider sphere).
    pub pairs: Vec<u32>,
    /// Current history of each active pair.
    pub hist: Vec<PairHist>,
    /// Result of each active pair at the last force evaluation.
    pub out: Vec<PairOut>,
}

/// Relative state shared by every inactive slider sphere (exact: they all obey the same linear
/// equation driven by the control layer). Lateral: displacement `u` from the site and absolute
/// velocity `v`. Vertical (full model only): displacement from the anchor `w_i = g_i·w` and
/// absolute velocity `v_z,i = g_i·s`, with `g_i = (1, y_i, −x_i)` (tilt convention).
///
/// An inactive sphere that still rings after a contact deviates from this state by `δ_i`, which
/// obeys a homogeneous linear equation (spring and damping only, the same for every sphere);
/// the control layer feels only their sum, integrated here as `d` (lateral, `Σ δ_i`) and `dz`
/// (vertical, `Σ δz_i g_i`). Each sphere's own deviation is kept in [`Ringing`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CommonMode {
    /// Lateral displacement from the site (m).
    pub u: [f64; 2],
    /// Lateral velocity (m/s).
    pub v: [f64; 2],
    /// Lateral force per sphere (N).
    pub fu: [f64; 2],
    /// Vertical displacement coefficients (m, rad, rad).
    pub w: [f64; 3],
    /// Vertical velocity coefficients.
    pub s: [f64; 3],
    /// Vertical force coefficients (per sphere: `g_i·fw`).
    pub fw: [f64; 3],
    /// Σ of the lateral deviations of the ringing inactive spheres (m).
    pub d: [f64; 2],
    /// Σ of their relative velocities (m/s).
    pub dv: [f64; 2],
    /// Σ of their deviation forces (N).
    pub fd: [f64; 2],
    /// Σ δz_i g_i of their vertical deviations (full model).
    pub dz: [f64; 3],
    /// Σ δż_i g_i.
    pub dzv: [f64; 3],
    /// Σ of their vertical deviation forces times g_i.
    pub fdz: [f64; 3],
}

/// Inactive spheres still ringing after a contact: their deviation from the rest state
/// (substrate: the site, velocity 0; slider: the common mode) as of the last evaluation, in the
/// order `[δx, δy, δz, δvx, δvy, δvz]` (slider; δz, δvz only in the full model) and
/// `[δx, δy, δvx, δvy]` (substrate). Advanced exactly by the homogeneous linear step map at each
/// evaluation; dropped once below 10⁻²⁵ m (far below the round-off of a position).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Ringing {
    /// Ringing inactive slider spheres (ascending).
    pub sl: Vec<u32>,
    /// Their deviations.
    pub sl_dev: Vec<[f64; 6]>,
    /// Ringing inactive substrate spheres (ascending).
    pub sub: Vec<u32>,
    /// Their deviations.
    pub sub_dev: Vec<[f64; 4]>,
}

/// Where the frame of the inactive slider spheres (control layer + common mode) stood at some
/// moment: for the displacement bound of the inactive spheres.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FrameMark {
    /// Control layer X, Y, Z (m).
    pub cl: [f64; 3],
    /// Tilts (rad).
    pub tilt: [f64; 2],
    /// Common-mode lateral displacement (m).
    pub u: [f64; 2],
    /// Common-mode vertical coefficients.
    pub w: [f64; 3],
    /// Step of the evaluation.
    pub step: u64,
    /// Bound (m) on how far a ringing inactive slider / substrate sphere can move away from its
    /// rest-state position between two evaluations.
    pub ring: [f64; 2],
}

/// Counters of the active set (diagnostics; checkpointed).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct ActiveStats {
    /// Re-evaluations so far.
    pub evaluations: u64,
    /// Particles that entered the active set.
    pub activations: u64,
    /// Particles that left it.
    pub deactivations: u64,
    /// Pairs that entered the active set already touching (must stay 0: a contact missed).
    pub late_pairs: u64,
    /// Σ over steps of active slider + substrate spheres (for the mean).
    pub particle_steps: u64,
}

/// Dynamic state (SI). Global arrays are indexed like the [`super::SystemSpec`] lists.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct State {
    /// Steps taken.
    pub step: u64,
    /// Simulated time (s).
    pub t: f64,
    /// Substrate positions (x, y) (m) (active ones: as of the last evaluation).
    pub sub_x: Vec<[f64; 2]>,
    /// Substrate velocities (m/s).
    pub sub_v: Vec<[f64; 2]>,
    /// Slider sphere positions (m) (active ones: as of the last evaluation; inactive ones: as
    /// of the last evaluation, from the common mode).
    pub sl_x: Vec<[f64; 3]>,
    /// Slider sphere velocities (m/s).
    pub sl_v: Vec<[f64; 3]>,
    /// The particles integrated step by step.
    pub act: Active,
    /// Relative state of the inactive slider spheres.
    pub common: CommonMode,
    /// Inactive spheres still ringing after a contact.
    pub ringing: Ringing,
    /// Control-layer centre of mass (x, y) and reference height Z (m).
    pub cl_x: [f64; 3],
    /// Control-layer velocity (m/s).
    pub cl_v: [f64; 3],
    /// Control-layer force (N): lateral force and the generalized force on Z.
    pub cl_f: [f64; 3],
    /// Control-layer tilts `[t_x, t_y]` (rad) (0 with a locked mount).
    pub tilt: [f64; 2],
    /// Tilt rates (rad/s).
    pub tilt_v: [f64; 2],
    /// Generalized forces on the tilts (N·m).
    pub tilt_f: [f64; 2],
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
    /// Candidate pairs with history.
    pub pairs: PairList,
    /// Substrate positions at the last candidate-list build (m).
    pub ref_sub: Vec<[f64; 2]>,
    /// Slider positions at the last candidate-list build (m).
    pub ref_sl: Vec<[f64; 3]>,
    /// Frame of the inactive slider spheres at the last evaluation.
    pub mark: FrameMark,
    /// Candidate-list builds so far.
    pub builds: u64,
    /// Active-set counters.
    pub stats: ActiveStats,
    /// Bytes and frames of the extended-XYZ file written so far (restored on resume).
    pub xyz_bytes: u64,
    /// Frames written so far.
    pub xyz_frames: u64,
    /// Largest p0 (Pa) of any pair at any force evaluation since the last time-series sample
    /// ([`crate::integrator::Sim::observe_sample`]): pressure peaks shorter than the sampling
    /// interval (the slider's vertical ringing during fast slips) are not lost.
    pub p0_peak: f64,
}
