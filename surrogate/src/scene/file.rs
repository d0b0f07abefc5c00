//! [`SceneFile`]: the TOML / command-line form of a scene, in user units (µm, GPa, g/cm³,
//! degrees). Every field is optional and overrides the preset named by `pattern`
//! (default `square-tri`). Unknown fields are rejected with their name.
//!
//! ```toml
//! pattern = "square-tri"          # base preset: tri-tri | square-tri | square-square | tri-square
//! sphere_diameter_um = 3.0
//! [slider]
//! radius_um = 100.0
//! theta_deg = 0.0
//! offset_um = [0.0, 0.0]
//! tilt = "springs"                # locked | free | springs (study: springs, K1 = 1e6 N/m)
//! tilt_k1_N_m = 1e6
//! lattice = { kind = "square", spacing_um = 3.0 }
//! [substrate]
//! size_um = [364.0, 270.0]
//! sigma_h_um = 0.0
//! seed = 1
//! lattice = { kind = "oblique", a1_um = [3.0, 0.0], a2_um = [1.0, 2.8] }
//! # pattern geometry (see docs/scenes-patterns.md):
//! # [slider] lattice = { kind = "triangular", spacing_um = 3.0, basis_um = [[0, 0], [1.5, 0.866]] }
//! #          kind = "honeycomb" | "kagome" are lattices with their basis built in
//! # [slider] outline = { kind = "rectangle", size_um = [120, 80] } (disc, rectangle, polygon)
//! # [slider] sites = "slider.csv"   (x_um,y_um[,diameter_um] relative to the slider centre)
//! # [slider] sphere_diameter_um = 2.0 (the slider's own sphere size; same for [substrate])
//! # [slider.material] youngs_GPa = 50 (the slider's own material; same for [substrate.material]:
//! #                   each field given overrides [material] for that body; Hertz E* from both)
//! [material]
//! youngs_GPa = 100.0
//! poisson = 0.3
//! density_g_cm3 = 2.2
//! [coating]
//! p_crit_GPa = 4.0
//! mu1 = 0.01
//! mu2 = 0.5
//! ```

pub use super::material_file::MaterialFile;
use super::material_file::{materials, overlay_bodies};
use super::{CoatingFile, Mount, Scene, SiteList, SliderFile, SubstrateFile};
use crate::error::SceneError;
use crate::units::{deg_to_rad, gpa_to_pa, um_text, um_to_m};
use serde::{Deserialize, Serialize};

/// A scene in user units, as read from TOML or assembled from command-line flags.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Base preset (default `square-tri`).
    pub pattern: Option<String>,
    /// Diameter of every sphere (µm).
    pub sphere_diameter_um: Option<f64>,
    /// Slider overrides.
    #[serde(default)]
    pub slider: SliderFile,
    /// Substrate overrides.
    #[serde(default)]
    pub substrate: SubstrateFile,
    /// Material overrides.
    #[serde(default)]
    pub material: MaterialFile,
    /// Coating overrides.
    #[serde(default)]
    pub coating: CoatingFile,
}

impl SceneFile {
    /// Parses TOML text; `path` is only used in error messages.
    pub fn from_toml(text: &str, path: &str) -> Result<SceneFile, SceneError> {
        toml::from_str(text).map_err(|e| SceneError::File {
            path: path.to_string(),
            msg: e.to_string(),
        })
    }

    /// Reads and parses a TOML file. A scene file is a few hundred bytes: anything larger than
    /// [`SceneFile::MAX_BYTES`] (e.g. `/dev/zero`, a data file given by mistake) is refused after
    /// reading at most that many bytes, so memory stays bounded whatever the path names.
    pub fn read(path: &std::path::Path) -> Result<SceneFile, SceneError> {
        use std::io::Read;
        let err = |msg: String| SceneError::File {
            path: path.display().to_string(),
            msg,
        };
        let f = std::fs::File::open(path).map_err(|e| err(crate::io_error::plain(&e)))?;
        if f.metadata().map(|m| m.is_dir()).unwrap_or(false) {
            return Err(err("is a directory, not a TOML scene file".into()));
        }
        let mut bytes = Vec::new();
        f.take(Self::MAX_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| err(crate::io_error::plain(&e)))?;
        if bytes.len() as u64 > Self::MAX_BYTES {
            return Err(err(format!(
                "larger than {} kB: not a scene file (a scene file is a short TOML text)",
                Self::MAX_BYTES / 1000
            )));
        }
        let text = String::from_utf8(bytes)
            .map_err(|_| err("is not UTF-8 text: not a TOML scene file".into()))?;
        let mut f = Self::from_toml(&text, &path.display().to_string())?;
        // site files are named relative to the scene file
        let dir = path.parent().unwrap_or(std::path::Path::new(""));
        for s in [&mut f.slider.sites, &mut f.substrate.sites]
            .into_iter()
            .flatten()
        {
            let p = std::path::Path::new(s.as_str());
            if p.is_relative() {
                let j = dir.join(p);
                *s = j.canonicalize().unwrap_or(j).display().to_string();
            }
        }
        Ok(f)
    }

    /// Largest scene file accepted by [`SceneFile::read`] (bytes).
    pub const MAX_BYTES: u64 = 1_000_000;

    /// Overlays every field set in `other` on `self` (`other` wins).
    pub fn merge(mut self, other: &SceneFile) -> SceneFile {
        macro_rules! take {
            ($($f:ident).+) => { if other.$($f).+.is_some() { self.$($f).+ = other.$($f).+.clone(); } };
        }
        take!(pattern);
        take!(sphere_diameter_um);
        take!(slider.lattice);
        take!(slider.radius_um);
        take!(slider.theta_deg);
        take!(slider.offset_um);
        take!(slider.tilt);
        take!(slider.tilt_k1_n_m);
        take!(slider.outline);
        take!(slider.sites);
        take!(slider.sphere_diameter_um);
        take!(substrate.sites);
        take!(substrate.sphere_diameter_um);
        take!(substrate.lattice);
        take!(substrate.size_um);
        take!(substrate.sigma_h_um);
        take!(substrate.seed);
        take!(material.youngs_gpa);
        take!(material.poisson);
        take!(material.density_g_cm3);
        overlay_bodies(
            [&mut self.slider.material, &mut self.substrate.material],
            [&other.slider.material, &other.substrate.material],
            &other.material,
        );
        take!(coating.p_crit_gpa);
        take!(coating.mu1);
        take!(coating.mu2);
        self
    }

    /// Builds and validates the SI [`Scene`]: the preset named by `pattern` (default
    /// `square-tri`) with every given field overriding it. Errors name the bad field.
    pub fn into_scene(&self) -> Result<Scene, SceneError> {
        let mut s = Scene::preset(self.pattern.as_deref().unwrap_or("square-tri"))?;
        if let Some(d) = self.sphere_diameter_um {
            s.sphere_radius = um_to_m(d) / 2.0;
        }
        if let Some(l) = &self.slider.lattice {
            s.slider.lattice = l.to_lattice("slider.lattice")?;
            s.geometry.slider_basis = l.to_basis("slider.lattice")?;
        }
        if let Some(v) = self.slider.radius_um {
            s.slider.radius = um_to_m(v);
        }
        self.apply_geometry(&mut s)?;
        if let Some(v) = self.slider.theta_deg {
            s.slider.theta = deg_to_rad(v);
        }
        if let Some(v) = self.slider.offset_um {
            s.slider.offset = v.map(um_to_m);
        }
        if self.slider.tilt.is_some() || self.slider.tilt_k1_n_m.is_some() {
            s.slider.mount = Mount::parse(
                self.slider.tilt.as_deref().unwrap_or("springs"),
                self.slider.tilt_k1_n_m,
                "slider.tilt",
            )?;
        }
        if let Some(l) = &self.substrate.lattice {
            s.substrate.lattice = l.to_lattice("substrate.lattice")?;
            s.geometry.substrate_basis = l.to_basis("substrate.lattice")?;
        }
        if let Some(v) = self.substrate.size_um {
            s.substrate.size = v.map(um_to_m);
        }
        if let Some(v) = self.substrate.sigma_h_um {
            s.substrate.sigma_h = um_to_m(v);
        }
        if let Some(v) = self.substrate.seed {
            s.substrate.seed = v;
        }
        (s.material, s.body_materials) = materials(
            s.material,
            &self.material,
            &self.slider.material,
            &self.substrate.material,
        )?;
        if let Some(v) = self.coating.p_crit_gpa {
            s.coating.p_crit = gpa_to_pa(v);
        }
        if let Some(v) = self.coating.mu1 {
            s.coating.mu1 = v;
        }
        if let Some(v) = self.coating.mu2 {
            s.coating.mu2 = v;
        }
        if self.slider.lattice.is_some()
            || self.substrate.lattice.is_some()
            || !s.geometry.is_plain()
        {
            if self.pattern.is_none() {
                s.pattern = "custom".into();
            } else {
                s.pattern = format!("{}*", s.pattern);
            }
        }
        s.validate()?;
        s.check_lattice_spacing()?;
        Ok(s)
    }

    /// Applies the outline, site files and per-body sphere sizes to `s` (SI), after the
    /// slider lattice and radius. Reads the site files; errors name the field and line.
    fn apply_geometry(&self, s: &mut Scene) -> Result<(), SceneError> {
        let pos = |field: &str, v: Option<f64>| -> Result<Option<f64>, SceneError> {
            match v {
                Some(d) if !(d.is_finite() && d > 0.0) => {
                    Err(SceneError::invalid(field, d, "must be a positive number"))
                }
                _ => Ok(v.map(|d| um_to_m(d) / 2.0)),
            }
        };
        let mut r_sl = pos("slider.sphere_diameter_um", self.slider.sphere_diameter_um)?;
        let mut r_sb = pos(
            "substrate.sphere_diameter_um",
            self.substrate.sphere_diameter_um,
        )?;
        self.apply_outline(s)?;
        self.apply_slider_sites(s, &mut r_sl)?;
        if let Some(p) = &self.substrate.sites {
            if self.substrate.lattice.is_some() {
                return Err(SceneError::invalid(
                    "substrate.sites",
                    p,
                    "give either substrate.lattice or substrate.sites, not both",
                ));
            }
            s.geometry.substrate_sites = Some(read_sites("substrate.sites", p, &mut r_sb)?);
        }
        let base = s.sphere_radius;
        let sb = r_sb.unwrap_or(base);
        let sl = r_sl.unwrap_or(base);
        s.sphere_radius = sb;
        s.geometry.slider_sphere_radius = (sl != sb).then_some(sl);
        // per-site sizes: empty diameter_um cells take the body's size
        if let Some(l) = &mut s.geometry.slider_sites {
            l.resolve_sizes(sl, "slider.sites")?;
        }
        if let Some(l) = &mut s.geometry.substrate_sites {
            l.resolve_sizes(sb, "substrate.sites")?;
        }
        Ok(())
    }

    /// Applies the slider's outline (and a disc outline's radius) to `s`.
    fn apply_outline(&self, s: &mut Scene) -> Result<(), SceneError> {
        if let Some(o) = &self.slider.outline {
            if self.slider.sites.is_some() {
                return Err(SceneError::invalid(
                    "slider.outline",
                    &o.kind,
                    "the slider site file (slider.sites) gives the slider's spheres; drop the outline",
                ));
            }
            let (outline, disc_r) = o.to_outline("slider.outline")?;
            match disc_r {
                Some(r) => {
                    if self.slider.radius_um.is_some_and(|v| um_to_m(v) != r) {
                        return Err(SceneError::invalid(
                            "slider.outline.radius_um",
                            um_text(r),
                            "differs from slider.radius_um: give the disc radius once",
                        ));
                    }
                    s.slider.radius = r;
                }
                None => s.slider.radius = outline.circumradius(s.slider.radius),
            }
            s.geometry.outline = outline;
        }
        Ok(())
    }

    /// Reads the slider's site file into `s` with the slider's bounding radius; its diameter
    /// column sets `r_sl` (m).
    fn apply_slider_sites(&self, s: &mut Scene, r_sl: &mut Option<f64>) -> Result<(), SceneError> {
        if let Some(p) = &self.slider.sites {
            if self.slider.lattice.is_some() {
                return Err(SceneError::invalid(
                    "slider.sites",
                    p,
                    "give either slider.lattice or slider.sites, not both",
                ));
            }
            let l = read_sites("slider.sites", p, r_sl)?;
            // the slider's bounding radius: the farthest site, or `radius_um` when given
            let far = l.sites.iter().map(|q| q[0].hypot(q[1])).fold(0.0, f64::max);
            s.slider.radius = match self.slider.radius_um {
                Some(v) if um_to_m(v) < far * (1.0 - 1e-9) => {
                    return Err(SceneError::invalid(
                        "slider.radius_um",
                        v,
                        &format!(
                            "with slider.sites it bounds the slider: the farthest site of {p} is {} µm from the centre",
                            um_text(far)
                        ),
                    ))
                }
                Some(v) => um_to_m(v),
                None => far,
            };
            s.geometry.slider_sites = Some(l);
        }
        Ok(())
    }
}

/// The site file `path` of `field` (`slider.sites`, `substrate.sites`); its diameter column,
/// if any, sets the body's sphere radius `r` (m), which must agree with a given one.
fn read_sites(field: &str, path: &str, r: &mut Option<f64>) -> Result<SiteList, SceneError> {
    let l = SiteList::read(std::path::Path::new(path), field)?;
    if let Some(d) = l.diameter {
        if r.is_some_and(|v| v != d / 2.0) {
            return Err(SceneError::invalid(
                field,
                path,
                &format!(
                    "its diameter_um column ({} µm) differs from the body's sphere_diameter_um ({} µm); give one",
                    um_text(d),
                    um_text(2.0 * r.unwrap_or_default())
                ),
            ));
        }
        *r = Some(d / 2.0);
    }
    Ok(l)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Lattice;

    #[test]
    fn toml_round_trip_and_overrides() {
        let f = SceneFile::from_toml(
            "pattern = 'tri-tri'\n[slider]\nradius_um = 30\ntheta_deg = 10\n[substrate]\nsigma_h_um = 0.01\nlattice = { kind = 'square' }\n",
            "x.toml",
        )
        .unwrap();
        let s = f.into_scene().unwrap();
        assert!((s.slider.radius - 30e-6).abs() < 1e-18);
        assert!((s.slider.theta - 10f64.to_radians()).abs() < 1e-15);
        assert_eq!(s.substrate.lattice, Lattice::square(3e-6));
        assert_eq!(s.pattern, "tri-tri*");
        assert_eq!(s.slider.mount, Mount::Springs { k1: 1e6 });
        let f = SceneFile::from_toml("[slider]\ntilt = 'free'\n", "x.toml").unwrap();
        assert_eq!(f.into_scene().unwrap().slider.mount, Mount::Free);
        let f = SceneFile::from_toml("[slider]\ntilt_k1_N_m = 2e5\n", "x.toml").unwrap();
        assert_eq!(
            f.into_scene().unwrap().slider.mount,
            Mount::Springs { k1: 2e5 }
        );
        let e = SceneFile::from_toml("[slider]\ntilt = 'loose'\n", "x.toml")
            .unwrap()
            .into_scene()
            .unwrap_err();
        assert!(e.to_string().contains("slider.tilt"), "{e}");
    }

    #[test]
    fn dev_zero_and_directories_are_refused() {
        let e = SceneFile::read(std::path::Path::new("/dev/zero")).unwrap_err();
        assert!(e.to_string().contains("not a scene file"), "{e}");
        let e = SceneFile::read(std::path::Path::new("/")).unwrap_err();
        assert!(e.to_string().contains("directory"), "{e}");
    }

    #[test]
    fn errors_name_the_field() {
        let e = SceneFile::from_toml("[slider]\nradius = 3\n", "bad.toml").unwrap_err();
        assert!(
            e.to_string().contains("radius") && e.to_string().contains("bad.toml"),
            "{e}"
        );
        let e = SceneFile::from_toml("[substrate]\nlattice = { kind = 'hex' }\n", "b.toml")
            .unwrap()
            .into_scene()
            .unwrap_err();
        assert!(e.to_string().contains("substrate.lattice.kind"), "{e}");
        let e = SceneFile::from_toml("[material]\nyoungs_GPa = -1\n", "b.toml")
            .unwrap()
            .into_scene()
            .unwrap_err();
        assert!(e.to_string().contains("material.youngs_GPa"), "{e}");
    }
}
