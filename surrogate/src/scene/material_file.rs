//! [`MaterialFile`]: the materials of a scene file, in user units (GPa, g/cm³): the shared
//! `[material]` and each body's own `[slider.material]` / `[substrate.material]`, whose fields
//! override the shared ones for that body (Hertz E* and Mindlin G* from both bodies,
//! [`super::BodyMaterials`]). How an overlay of scene files combines them
//! ([`overlay_bodies`]) and how they resolve to SI ([`materials`]).

use super::{BodyMaterials, Material};
use crate::error::SceneError;
use crate::units::{gcm3_to_kgm3, gpa_to_pa};
use serde::{Deserialize, Serialize};

/// Material overrides (user units).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialFile {
    /// Young's modulus (GPa).
    #[serde(rename = "youngs_GPa")]
    pub youngs_gpa: Option<f64>,
    /// Poisson ratio.
    pub poisson: Option<f64>,
    /// Density (g/cm³).
    pub density_g_cm3: Option<f64>,
}

impl MaterialFile {
    /// `base` (SI) with every field given here overriding it.
    pub fn apply(&self, mut base: Material) -> Material {
        if let Some(v) = self.youngs_gpa {
            base.youngs = gpa_to_pa(v);
        }
        if let Some(v) = self.poisson {
            base.poisson = v;
        }
        if let Some(v) = self.density_g_cm3 {
            base.density = gcm3_to_kgm3(v);
        }
        base
    }

    /// Overlays the fields set in `other` (`other` wins).
    pub(super) fn merged(&self, other: &MaterialFile) -> MaterialFile {
        MaterialFile {
            youngs_gpa: other.youngs_gpa.or(self.youngs_gpa),
            poisson: other.poisson.or(self.poisson),
            density_g_cm3: other.density_g_cm3.or(self.density_g_cm3),
        }
    }

    /// This body override less the fields that `shared` sets: a shared value given later (a
    /// flag such as `--youngs-gpa`) is the shorthand for both bodies. `None` when nothing is
    /// left.
    pub(super) fn without(&self, shared: &MaterialFile) -> Option<MaterialFile> {
        let f = MaterialFile {
            youngs_gpa: self.youngs_gpa.filter(|_| shared.youngs_gpa.is_none()),
            poisson: self.poisson.filter(|_| shared.poisson.is_none()),
            density_g_cm3: self
                .density_g_cm3
                .filter(|_| shared.density_g_cm3.is_none()),
        };
        (f != MaterialFile::default()).then_some(f)
    }
}

/// Overlays the bodies' own materials `theirs` (slider, substrate) of a later scene file on
/// `mine`: a shared material value given in the later file (`shared`, its `[material]`) is the
/// shorthand for both bodies, so it replaces the bodies' own values of that field; a body's
/// own table in the later file wins over both.
pub(super) fn overlay_bodies(
    mine: [&mut Option<MaterialFile>; 2],
    theirs: [&Option<MaterialFile>; 2],
    shared: &MaterialFile,
) {
    for (mine, theirs) in mine.into_iter().zip(theirs) {
        let kept = mine.as_ref().and_then(|m| m.without(shared));
        *mine = match (kept, theirs) {
            (Some(m), Some(t)) => Some(m.merged(t)),
            (None, Some(t)) => Some(t.clone()),
            (m, None) => m,
        };
    }
}

/// The SI materials of a scene: the preset's `base` with the shared `[material]` applied, and
/// each body's own table on top of that (validated, errors naming the table's fields), then
/// normalised ([`BodyMaterials::normalized`]): returns the shared material and the bodies'.
pub(super) fn materials(
    base: Material,
    shared: &MaterialFile,
    slider: &Option<MaterialFile>,
    substrate: &Option<MaterialFile>,
) -> Result<(Material, BodyMaterials), SceneError> {
    let shared = shared.apply(base);
    shared.validate()?;
    let body = |f: &Option<MaterialFile>, table: &str| -> Result<Option<Material>, SceneError> {
        f.as_ref()
            .map(|f| {
                let m = f.apply(shared);
                m.validate_in(table).map(|_| m)
            })
            .transpose()
    };
    let bodies = BodyMaterials {
        slider: body(slider, "slider.material")?,
        substrate: body(substrate, "substrate.material")?,
    };
    Ok(bodies.normalized(shared))
}

#[cfg(test)]
mod tests {
    use super::super::SceneFile;

    /// A body's own table overrides the shared material for that body only; a shared value
    /// given later is the shorthand for both bodies; bad values name the table's field.
    #[test]
    fn body_tables_override_the_shared_material() {
        let f = SceneFile::from_toml(
            "[material]\nyoungs_GPa = 120\n[slider.material]\nyoungs_GPa = 50\n",
            "m.toml",
        )
        .unwrap();
        let s = f.into_scene().unwrap();
        assert_eq!(s.slider_material().youngs, 50e9);
        assert_eq!(s.substrate_material().youngs, 120e9);
        let later = SceneFile::from_toml("[material]\nyoungs_GPa = 80\n", "l.toml").unwrap();
        let s = f.merge(&later).into_scene().unwrap();
        assert_eq!(s.slider_material().youngs, 80e9);
        assert_eq!(s.substrate_material().youngs, 80e9);
        let e = SceneFile::from_toml("[substrate.material]\npoisson = 0.7\n", "b.toml")
            .unwrap()
            .into_scene()
            .unwrap_err();
        assert!(e.to_string().contains("substrate.material.poisson"), "{e}");
    }
}
