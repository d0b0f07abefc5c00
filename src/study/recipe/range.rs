//! The range the surrogate's verdict band was measured at, and why a recipe lies outside it.
//!
//! The band (docs/validation/verdict-band.md) was measured on the study's scenes: 3 µm spheres
//! and E = 100 GPa for both bodies. A recipe with another sphere size or modulus, or whose
//! design has a load in the springs mount's resonance band (where μ_est can be 2.8× high,
//! `surrogate::friction::resonance`), is **outside the validated range**: `design` runs the DEM
//! on it at its centre and its tolerance-box corners before naming it, with the DEM model
//! `auto` where `reduced` was asked (rigid-z only inside its own measured limits:
//! `dem::reduction`), and without the DEM the report calls it unconfirmed.

use surrogate::units::{pa_to_gpa, um_text};
use surrogate::Scene;

/// The study's sphere diameter (m) at which the verdict band was measured
/// (docs/validation/verdict-band.md).
pub const VALIDATED_DIAMETER: f64 = 3e-6;
/// The study's Young's modulus (Pa) of both bodies at which the verdict band was measured.
pub const VALIDATED_YOUNGS: f64 = 100e9;

/// One of the two bodies of a scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Body {
    /// The slider (the pad of spheres that moves).
    Slider,
    /// The substrate.
    Substrate,
}

impl Body {
    /// `slider` or `substrate`.
    pub fn name(self) -> &'static str {
        match self {
            Body::Slider => "slider",
            Body::Substrate => "substrate",
        }
    }
}

/// Why a recipe (or one of its designs) lies outside the validated range.
#[derive(Debug, Clone, PartialEq)]
pub enum Outside {
    /// A body's spheres are not the study's 3 µm (`diameter` in m).
    SphereDiameter {
        /// The body.
        body: Body,
        /// Its sphere diameter (m).
        diameter: f64,
    },
    /// A body's Young's modulus is not the study's 100 GPa (`youngs` in Pa).
    Youngs {
        /// The body.
        body: Body,
        /// Its modulus (Pa).
        youngs: f64,
    },
    /// The design has a load in the springs mount's resonance band (column `mount_resonance`
    /// of its friction rows): μ_est may be an upper bound there.
    MountResonance,
}

impl std::fmt::Display for Outside {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Outside::SphereDiameter { body, diameter } => {
                write!(f, "{} spheres of {} µm", body.name(), um_text(*diameter))
            }
            Outside::Youngs { body, youngs } => write!(
                f,
                "{} E = {} GPa",
                body.name(),
                crate::study::rows::label(pa_to_gpa(*youngs))
            ),
            Outside::MountResonance => write!(f, "in the mount's resonance band"),
        }
    }
}

/// What a design knows of a recipe (`design --vary`): why its scene lies outside the validated
/// range (empty: inside). Its designs add [`Outside::MountResonance`] where their rows say so
/// (`crate::study::design::answer::outside_range`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RecipeFacts {
    /// The name of the pattern the recipe was made from.
    pub base: String,
    /// The scene's reasons ([`validated_range`]).
    pub outside: Vec<Outside>,
}

/// Why `s` lies outside the range the verdict band was measured at (sphere diameter and
/// modulus of each body against [`VALIDATED_DIAMETER`] and [`VALIDATED_YOUNGS`]); empty
/// inside it. O(1).
pub fn validated_range(s: &Scene) -> Vec<Outside> {
    let mut why = Vec::new();
    for (body, r) in [
        (Body::Slider, s.slider_sphere_radius()),
        (Body::Substrate, s.sphere_radius),
    ] {
        if (2.0 * r / VALIDATED_DIAMETER - 1.0).abs() > 1e-9 {
            why.push(Outside::SphereDiameter {
                body,
                diameter: 2.0 * r,
            });
        }
    }
    for (body, m) in [
        (Body::Slider, s.slider_material()),
        (Body::Substrate, s.substrate_material()),
    ] {
        if (m.youngs / VALIDATED_YOUNGS - 1.0).abs() > 1e-9 {
            why.push(Outside::Youngs {
                body,
                youngs: m.youngs,
            });
        }
    }
    why
}

/// The reasons of [`validated_range`] in one sentence for the log, or `None` inside the range.
/// O(1).
pub fn outside_validated_range(s: &Scene) -> Option<String> {
    let why = validated_range(s);
    (!why.is_empty()).then(|| {
        format!(
            "outside the validated range ({}; the verdict band was measured at 3 µm spheres and E = 100 GPa): the DEM confirmation decides",
            why.iter().map(|w| w.to_string()).collect::<Vec<_>>().join(", ")
        )
    })
}
