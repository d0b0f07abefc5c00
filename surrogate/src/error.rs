//! Errors of scene construction and solving. Every variant names the offending field in the
//! user's units so a CLI or TOML user can fix it without reading code.

use thiserror::Error;

/// A scene or solve request that cannot be honoured.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SceneError {
    /// A field has a value outside its valid range. `field` is the user-facing name (e.g.
    /// `slider.radius_um`), `value` the offending value as given, `why` the rule it breaks.
    #[error("invalid value for `{field}`: {value} ({why})")]
    Invalid {
        /// User-facing field name, e.g. `load_mN` or `substrate.sigma_h_um`.
        field: String,
        /// The value as given by the user (in the user's units).
        value: String,
        /// The rule that is broken.
        why: String,
    },
    /// An unknown lattice / pattern name.
    #[error("unknown {what} `{name}` for `{field}` (expected one of: {expected})")]
    Unknown {
        /// Field name.
        field: String,
        /// What kind of name (lattice, pattern, model).
        what: String,
        /// The name given.
        name: String,
        /// Comma-separated accepted names.
        expected: String,
    },
    /// A scene file could not be read or parsed.
    #[error("cannot read scene file `{path}`: {msg}")]
    File {
        /// Path of the file.
        path: String,
        /// Parser or I/O message (includes line/column for TOML errors).
        msg: String,
    },
    /// The solver found no equilibrium (e.g. no substrate sphere under the slider).
    #[error("no equilibrium: {0}")]
    NoEquilibrium(String),
}

impl SceneError {
    /// Shorthand for [`SceneError::Invalid`].
    pub fn invalid(field: &str, value: impl std::fmt::Display, why: &str) -> Self {
        SceneError::Invalid {
            field: field.to_string(),
            value: value.to_string(),
            why: why.to_string(),
        }
    }
}
