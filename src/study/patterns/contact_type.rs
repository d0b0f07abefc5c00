//! [`ContactType`]: how a slider lattice meets the substrate.

/// How a candidate meets the substrate (Panizon et al. 2023).
#[derive(Debug, Clone, PartialEq)]
pub enum ContactType {
    /// No coincident reciprocal vector: lubric in every direction.
    Lubric,
    /// Coincident reciprocal vectors along one direction only: lubric perpendicular to it
    /// (`lubric_deg`, the free sliding direction, in [0°, 180°)).
    Directional { lubric_deg: f64 },
    /// Two non-parallel coincident reciprocal vectors: interlocked.
    Interlocked,
}

impl ContactType {
    /// `lubric`, `directional` or `interlocked`.
    pub fn name(&self) -> &'static str {
        match self {
            ContactType::Lubric => "lubric",
            ContactType::Directional { .. } => "directional",
            ContactType::Interlocked => "interlocked",
        }
    }
}
