//! Elastic material of the spheres and the superlubric coating on them.

use crate::error::SceneError;
use crate::units::{kgm3_to_gcm3, pa_to_gpa};
use serde::{Deserialize, Serialize};

/// Isotropic elastic material of every sphere (SI).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Material {
    /// Young's modulus E (Pa). Study: 100 GPa (also 50 GPa).
    pub youngs: f64,
    /// Poisson ratio ν (–). Study: 0.3.
    pub poisson: f64,
    /// Density ρ (kg/m³). Study: 2200 kg/m³ (2.2 g/cm³).
    pub density: f64,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            youngs: 100e9,
            poisson: 0.3,
            density: 2200.0,
        }
    }
}

impl Material {
    /// Effective modulus of two spheres of this material, `E* = E / (2(1 − ν²))` (Pa).
    pub fn e_star(&self) -> f64 {
        self.youngs / (2.0 * (1.0 - self.poisson * self.poisson))
    }
    /// Hertz effective modulus (Pa) of a sphere of this material against one of `other`:
    /// `1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2`; [`Material::e_star`] itself, bit for bit, when the
    /// two materials are equal. O(1).
    pub fn e_star_with(&self, other: &Material) -> f64 {
        if self == other {
            return self.e_star();
        }
        let c = |m: &Material| (1.0 - m.poisson * m.poisson) / m.youngs;
        1.0 / (c(self) + c(other))
    }
    /// Mindlin effective shear modulus (Pa) of a sphere of this material against one of
    /// `other`: `1/G* = (2 − ν1)/G1 + (2 − ν2)/G2` with `G = E/(2(1 + ν))`;
    /// `E / (4(2 − ν)(1 + ν))`, bit for bit, when the two materials are equal. O(1).
    pub fn g_star_with(&self, other: &Material) -> f64 {
        if self == other {
            return self.youngs / (4.0 * (2.0 - self.poisson) * (1.0 + self.poisson));
        }
        let c = |m: &Material| (2.0 - m.poisson) * 2.0 * (1.0 + m.poisson) / m.youngs;
        1.0 / (c(self) + c(other))
    }
    /// Mass of a sphere of radius `r` (m): `ρ·4/3·π·r³` (kg).
    pub fn sphere_mass(&self, r: f64) -> f64 {
        self.density * 4.0 / 3.0 * std::f64::consts::PI * r * r * r
    }
    /// Checks ranges; errors name the user-facing field (`material.youngs_GPa` …).
    pub fn validate(&self) -> Result<(), SceneError> {
        self.validate_in("material")
    }
    /// Checks ranges; errors name the field in the table `table` (`slider.material` gives
    /// `slider.material.youngs_GPa` …).
    pub fn validate_in(&self, table: &str) -> Result<(), SceneError> {
        if !(self.youngs.is_finite() && self.youngs > 0.0) {
            return Err(SceneError::invalid(
                &format!("{table}.youngs_GPa"),
                pa_to_gpa(self.youngs),
                "must be a positive number",
            ));
        }
        super::plausible::plausible_field(
            &format!("{table}.youngs_GPa"),
            &super::plausible::YOUNGS_GPA,
            pa_to_gpa(self.youngs),
        )?;
        if !(self.poisson.is_finite() && self.poisson > -1.0 && self.poisson < 0.5) {
            return Err(SceneError::invalid(
                &format!("{table}.poisson"),
                self.poisson,
                "must lie in (-1, 0.5)",
            ));
        }
        if !(self.density.is_finite() && self.density > 0.0) {
            return Err(SceneError::invalid(
                &format!("{table}.density_g_cm3"),
                kgm3_to_gcm3(self.density),
                "must be a positive number",
            ));
        }
        super::plausible::plausible_field(
            &format!("{table}.density_g_cm3"),
            &super::plausible::DENSITY_G_CM3,
            kgm3_to_gcm3(self.density),
        )
    }
}

/// Per-body materials: each body's spheres take its own [`Material`] when set, the scene's
/// shared `material` otherwise. Resolved scenes keep an override only where it differs from the
/// shared material ([`BodyMaterials::normalized`]), so a scene whose overrides equal its
/// `[material]` is the scene of the shorthand, bit for bit.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct BodyMaterials {
    /// Material of the slider's spheres (and its control layer's masses); `None`: the shared one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub slider: Option<Material>,
    /// Material of the substrate's spheres; `None`: the shared one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub substrate: Option<Material>,
}

impl BodyMaterials {
    /// Whether both bodies take the shared material (nothing recorded).
    pub fn is_shared(&self) -> bool {
        self.slider.is_none() && self.substrate.is_none()
    }
    /// The overrides against the shared material `shared`, and the shared material itself:
    /// both bodies of one material make it the shared one (no override); an override equal to
    /// the shared material is dropped. O(1).
    pub fn normalized(self, shared: Material) -> (Material, BodyMaterials) {
        let sl = self.slider.unwrap_or(shared);
        let sb = self.substrate.unwrap_or(shared);
        if sl == sb {
            return (sl, BodyMaterials::default());
        }
        (
            shared,
            BodyMaterials {
                slider: (sl != shared).then_some(sl),
                substrate: (sb != shared).then_some(sb),
            },
        )
    }
}

/// The superlubric coating: its strength and the two friction coefficients it switches between.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Coating {
    /// Critical contact pressure P_crit (Pa) above which the coating fails. Study: 4 GPa.
    pub p_crit: f64,
    /// Friction coefficient μ1 of an intact contact (p0 ≤ P_crit). Study: 0.01.
    pub mu1: f64,
    /// Friction coefficient μ2 of a failed contact (p0 > P_crit). Study: 0.5.
    pub mu2: f64,
}

impl Default for Coating {
    fn default() -> Self {
        Coating {
            p_crit: 4e9,
            mu1: 0.01,
            mu2: 0.5,
        }
    }
}

impl Coating {
    /// Friction coefficient of a contact whose maximum Hertz pressure is `p0` (Pa).
    pub fn mu(&self, p0: f64) -> f64 {
        crate::contact::coating_mu(p0, self.p_crit, self.mu1, self.mu2)
    }
    /// Whether a contact with maximum Hertz pressure `p0` (Pa) has failed (`p0 > P_crit`).
    pub fn failed(&self, p0: f64) -> bool {
        crate::contact::coating_failed(p0, self.p_crit)
    }
    /// Checks ranges; errors name the user-facing field.
    pub fn validate(&self) -> Result<(), SceneError> {
        if !(self.p_crit.is_finite() && self.p_crit > 0.0) {
            return Err(SceneError::invalid(
                "coating.p_crit_GPa",
                pa_to_gpa(self.p_crit),
                "must be a positive number",
            ));
        }
        super::plausible::plausible_field(
            "coating.p_crit_GPa",
            &super::plausible::P_CRIT_GPA,
            pa_to_gpa(self.p_crit),
        )?;
        for (f, v) in [("coating.mu1", self.mu1), ("coating.mu2", self.mu2)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(SceneError::invalid(f, v, "must be a non-negative number"));
            }
        }
        Ok(())
    }
}
