//! [`tidy`]: a degree or µm value without binary noise.

/// A degree or µm value without binary noise.
pub fn tidy(v: f64) -> f64 {
    (v * 1e9).round() / 1e9 + 0.0
}
