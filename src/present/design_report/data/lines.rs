//! The row and section types of [`super::ReportData`]: strings ready for the template.

use serde::Serialize;

/// The DEM comparison: protocol, its measured difference from the study's, one row per run.
#[derive(Debug, Clone, Serialize)]
pub struct DemSection {
    /// The confirmation protocol in words.
    pub protocol: String,
    /// The confirmation protocol is the study's.
    pub study_protocol: bool,
    /// The DEM model and reductions in words.
    pub model: String,
    /// The study-protocol checks.
    pub checks: Vec<StudyCheck>,
    /// No check and a protocol shorter than the study's (`--no-protocol-check`).
    pub unmeasured: bool,
    /// One row per DEM run.
    pub rows: Vec<DemLine>,
    /// Runs whose DEM and estimate verdicts agree.
    pub agree: usize,
    /// Runs with both verdicts.
    pub judged: usize,
    /// Friction path length (µm).
    pub path_um: String,
    /// The study DEM's slide length (µm).
    pub slid_um: String,
    /// Largest measured μ_est/μ_DEM of a mount in resonance
    /// ([`surrogate::friction::RESONANCE_DROP_MAX`]).
    pub resonance_drop: String,
}

/// One study-protocol run against the same run with the design's shorter protocol.
#[derive(Debug, Clone, Serialize)]
pub struct StudyCheck {
    /// Which design, in words.
    pub what: String,
    pub pattern: String,
    pub theta_deg: String,
    pub alpha_deg: String,
    pub load_mn: String,
    /// Both runs have a μ.
    pub measured: bool,
    /// μ of the short and the study protocol.
    pub mu_short: String,
    pub mu_study: String,
    /// (μ_short/μ_study − 1) in %, signed, one decimal.
    pub difference_pct: String,
    /// Both DEM verdicts are the same.
    pub same: bool,
    /// The verdicts in words (short, study).
    pub short_verdict: String,
    pub study_verdict: String,
    /// Why the study-protocol run did not complete.
    pub error: String,
}

/// One row of the DEM table (cells as printed).
#[derive(Debug, Clone, Serialize)]
pub struct DemLine {
    pub pattern: String,
    pub rank: usize,
    pub theta_deg: String,
    pub alpha_deg: String,
    /// `δθ, δdir` of a tolerance-corner run, `–` for the design itself.
    pub corner: String,
    pub load_mn: String,
    pub protocol: String,
    pub mu_est: String,
    pub mu_dem: String,
    pub ratio: String,
    pub verdict_est: String,
    pub verdict_dem: String,
    pub max_p_max_gpa: String,
    pub contacts: String,
    /// Status, with the error after a colon.
    pub status: String,
    pub wall_s: String,
}

/// One row of the ranking table (cells as printed).
#[derive(Debug, Clone, Serialize)]
pub struct RankingLine {
    pub pattern: String,
    pub rank: usize,
    pub theta_deg: String,
    pub alpha_deg: String,
    pub pull_deg: String,
    /// The robust limit (mN), `≤ x` where it is an upper bound (`robust_exact = false`).
    pub superlubric_to_mn: String,
    /// The limit at the nominal (θ, α) alone (mN).
    pub nominal_mn: String,
    /// The θ and direction windows (±degrees), `–` where not computed.
    pub theta_window_deg: String,
    pub direction_window_deg: String,
    /// The worst verdict up to the robust limit.
    pub verdict: String,
    pub mu_worst: String,
    pub contacts: String,
    pub intact_to_mn: String,
    pub screen_intact_to_mn: String,
    pub corrugation_nm: String,
    pub reason: String,
}

/// Candidates of a pattern with failed contacts on a mount in resonance.
#[derive(Debug, Clone, Serialize)]
pub struct ResonanceLine {
    pub pattern: String,
    pub flagged: usize,
    pub candidates: usize,
    /// The resonance in words.
    pub note: String,
}

/// The screen and the shortlist levels of one pattern.
#[derive(Debug, Clone, Serialize)]
pub struct ScreenLine {
    pub pattern: String,
    /// The symmetry cut in words.
    pub symmetry: String,
    pub thetas: usize,
    /// First and last θ screened (empty when none).
    pub theta_first: String,
    pub theta_last: String,
    pub loads: usize,
    /// The levels, highest first.
    pub levels: Vec<LevelLine>,
    /// Why the evaluation stopped.
    pub stop: String,
}

/// One shortlist level.
#[derive(Debug, Clone, Serialize)]
pub struct LevelLine {
    pub load_mn: String,
    pub size: usize,
    pub kept: usize,
    pub evaluated: bool,
}

/// Wall times of the screen and the evaluation of one pattern.
#[derive(Debug, Clone, Serialize)]
pub struct WallLine {
    pub pattern: String,
    pub thetas: usize,
    pub loads: usize,
    pub screen_s: String,
    pub evaluated: usize,
    pub scan_paths: usize,
    pub friction_paths: usize,
    pub estimates: usize,
    pub evaluation_s: String,
}

/// Wall time of the DEM tier.
#[derive(Debug, Clone, Serialize)]
pub struct DemWall {
    pub runs: usize,
    pub jobs: usize,
    pub sum_s: String,
    pub elapsed_s: String,
}

/// The reproduction commands of one pattern's surrogate stages.
#[derive(Debug, Clone, Serialize)]
pub struct Reproduce {
    pub pattern: String,
    pub screen: String,
    pub evaluated: Vec<ReproduceTheta>,
}

/// The commands of one evaluated θ.
#[derive(Debug, Clone, Serialize)]
pub struct ReproduceTheta {
    pub theta_deg: String,
    pub corrugation: String,
    pub friction: String,
}
