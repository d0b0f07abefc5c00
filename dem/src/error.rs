//! [`DemError`]: why a DEM run could not be set up or did not finish.

use thiserror::Error;

/// Errors of the DEM engine. Messages name the field or knob to change.
#[derive(Debug, Error)]
pub enum DemError {
    /// The scene or a parameter is invalid (field named in user units).
    #[error(transparent)]
    Scene(#[from] surrogate::SceneError),
    /// A parameter is out of range.
    #[error("invalid value for `{field}`: {value} ({why})")]
    Invalid {
        /// User-facing name, e.g. `dt_us`.
        field: String,
        /// Value as given.
        value: String,
        /// Rule broken.
        why: String,
    },
    /// The integration blew up (non-finite state or an overlap beyond the bound): the time step
    /// is too large. Reports the step used and the estimated stable step (µs).
    #[error("unstable integration at t = {t_us:.4} µs: {what}; dt = {dt_us:e} µs exceeds the safe step (estimated critical step {dt_crit_us:e} µs) — use a smaller --dt-us")]
    Unstable {
        /// Simulated time (µs) when detected.
        t_us: f64,
        /// What was detected.
        what: String,
        /// Time step used (µs).
        dt_us: f64,
        /// Estimated critical time step (µs).
        dt_crit_us: f64,
    },
    /// The slider left the substrate during the run (the disc plus one sphere radius reaches
    /// beyond the substrate rectangle, further than at the start). Not a time-step problem.
    #[error("the slider left the substrate at t = {t_us:.4} µs: the slider disc plus one sphere radius reaches {over_um:.3} µm beyond the substrate edge (the control layer has moved by [{:.3}, {:.3}] µm); this is not a time-step problem — shorten the path (--slide-us, --speed-m-s), change --alpha-deg or --offset-um, or enlarge the substrate (--substrate-um)", moved_um[0], moved_um[1])]
    OffSubstrate {
        /// Simulated time (µs) when detected.
        t_us: f64,
        /// Overhang beyond the substrate edge (µm).
        over_um: f64,
        /// Control-layer displacement since the start (µm).
        moved_um: [f64; 2],
    },
    /// The slide path, checked before the run, takes the slider off the substrate.
    #[error("the slide path leaves the substrate: {0}")]
    Path(String),
    /// Checkpoint I/O or format problem.
    #[error("checkpoint {path}: {why}")]
    Checkpoint {
        /// File.
        path: String,
        /// What went wrong.
        why: String,
    },
}

impl DemError {
    /// Shorthand for [`DemError::Invalid`].
    pub fn invalid(field: &str, value: impl ToString, why: &str) -> Self {
        DemError::Invalid {
            field: field.into(),
            value: value.to_string(),
            why: why.into(),
        }
    }
}
