//! [`Fairness`]: what compared candidates share (the slider area or the sphere count), one rule
//! for the candidates of `superlube patterns` and the recipes of `superlube design`, and
//! [`MadeFair`]: which of the two made a design's candidates fair, and by which rule.

/// What the compared candidates share. Serialized as the sidecar of a candidates' index records
/// it (its `normalize` parameter): `area` or `spheres`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Fairness {
    /// Every candidate keeps the base slider's outline: equal slider area (the load per area is
    /// the same).
    #[default]
    #[serde(rename = "area")]
    Area,
    /// Every candidate's outline is scaled so that it holds the base slider's sphere count (the
    /// closest count its lattice allows): equal sphere count.
    #[serde(rename = "spheres")]
    Count,
}

impl Fairness {
    /// The command-line spelling: `area` or `count`.
    pub fn name(self) -> &'static str {
        match self {
            Fairness::Area => "area",
            Fairness::Count => "count",
        }
    }
}

/// Who made a design's candidates comparable, and by which rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MadeFair {
    /// The candidates of a `superlube patterns` index (the rule its sidecar records).
    Patterns(Fairness),
    /// The recipes of a design's grid of varied fields.
    Recipe(Fairness),
}
