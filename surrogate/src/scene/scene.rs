//! [`Scene`]: the full description of one slider–substrate pair (SI units). Its checks are in
//! `validate.rs`, its per-site sphere sizes in `sizes.rs`.

use super::pattern::{self, Geometry};
use super::{BodyMaterials, Coating, Lattice, Material, Mount};
use crate::contact::Hertz;
use crate::error::SceneError;
use rand::{Rng, SeedableRng};
use serde::{Deserialize, Serialize};

/// Names of the built-in pattern pairs (`slider-substrate`).
pub const PATTERNS: &[&str] = &["tri-tri", "square-tri", "square-square", "tri-square"];

/// The slider: a rigid disc of lattice sites, one sphere per site.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SliderSpec {
    /// Slider lattice before rotation (m).
    pub lattice: Lattice,
    /// Disc radius (m): sites with |p| ≤ radius (a site sits at the disc centre).
    pub radius: f64,
    /// Rotation θ of the slider lattice about the vertical axis through its centre (rad).
    pub theta: f64,
    /// In-plane position of the disc centre relative to the substrate sphere at the origin (m).
    pub offset: [f64; 2],
    /// How the control layer may tilt (both tiers obey it). Default: the study's anti-tilt
    /// springs K1 = 10⁶ N/m.
    pub mount: Mount,
}

/// The substrate: a rectangle of lattice sites centred on a site at the origin.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SubstrateSpec {
    /// Substrate lattice (m). `a1` along x: one lattice row along x.
    pub lattice: Lattice,
    /// Rectangle size `[Lx, Ly]` (m), centred on the origin.
    pub size: [f64; 2],
    /// Amplitude of the random sphere-height perturbation (m): heights uniform in `[-σ_h, σ_h]`.
    pub sigma_h: f64,
    /// Seed of the height perturbation (ChaCha8; same seed → same heights).
    pub seed: u64,
}

/// One slider–substrate scene (SI units). Build with [`Scene::preset`] or
/// [`crate::SceneFile::into_scene`], then [`Scene::validate`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// Short name of the pattern pair, used in output tables (e.g. `square-tri`).
    pub pattern: String,
    /// The slider disc.
    pub slider: SliderSpec,
    /// The substrate rectangle.
    pub substrate: SubstrateSpec,
    /// Radius of every substrate sphere, and of every slider sphere unless
    /// `geometry.slider_sphere_radius` says otherwise (m). Study: 1.5 µm.
    pub sphere_radius: f64,
    /// Sphere material shared by both bodies (the shorthand `[material]`), unless
    /// `body_materials` overrides it for a body.
    pub material: Material,
    /// Per-body materials (`[slider.material]`, `[substrate.material]`); read them through
    /// [`Scene::slider_material`] and [`Scene::substrate_material`]. Not recorded when absent.
    #[serde(default, skip_serializing_if = "BodyMaterials::is_shared")]
    pub body_materials: BodyMaterials,
    /// Coating strength and friction coefficients.
    pub coating: Coating,
    /// Bases, slider outline, site files and the slider sphere size (default: the presets'
    /// disc of a Bravais lattice, one sphere size). Not recorded when plain.
    #[serde(default, skip_serializing_if = "Geometry::is_plain")]
    pub geometry: Geometry,
}

impl Scene {
    /// A built-in pattern pair with the reference study's parameters (see docs/physics.md):
    /// spheres of 3 µm diameter, 3 µm spacing, substrate 364 × 270 µm, triangular slider radius
    /// 93.5 µm, square slider radius 100 µm (both 3505 spheres), θ = 0, E = 100 GPa.
    pub fn preset(name: &str) -> Result<Scene, SceneError> {
        let s = 3e-6;
        let (sl, r, sb) = match name {
            "tri-tri" => (Lattice::triangular(s), 93.5e-6, Lattice::triangular(s)),
            "square-tri" => (Lattice::square(s), 100e-6, Lattice::triangular(s)),
            "square-square" => (Lattice::square(s), 100e-6, Lattice::square(s)),
            "tri-square" => (Lattice::triangular(s), 93.5e-6, Lattice::square(s)),
            _ => {
                return Err(SceneError::Unknown {
                    field: "pattern".into(),
                    what: "pattern".into(),
                    name: name.into(),
                    expected: PATTERNS.join(", "),
                })
            }
        };
        Ok(Scene {
            pattern: name.to_string(),
            slider: SliderSpec {
                lattice: sl,
                radius: r,
                theta: 0.0,
                offset: [0.0, 0.0],
                mount: Mount::default(),
            },
            substrate: SubstrateSpec {
                lattice: sb,
                size: [364e-6, 270e-6],
                sigma_h: 0.0,
                seed: 1,
            },
            sphere_radius: 1.5e-6,
            material: Material::default(),
            body_materials: BodyMaterials::default(),
            coating: Coating::default(),
            geometry: Geometry::default(),
        })
    }

    /// The same scene with the slider rotated to `theta` (rad).
    pub fn with_theta(&self, theta: f64) -> Scene {
        let mut s = self.clone();
        s.slider.theta = theta;
        s
    }

    /// Rotational stiffness tensor (N·m/rad) of the slider mount at rotation `theta` (rad):
    /// [`Mount::tilt_stiffness`] of the slider's sites. Zero for `free` and `locked`.
    pub fn tilt_stiffness_at(&self, theta: f64) -> [[f64; 2]; 2] {
        self.slider
            .mount
            .tilt_stiffness(&self.slider_sites_local(), theta)
    }

    /// Hertz law of one slider–substrate sphere pair: `1/R_eff = 1/R_slider + 1/R_substrate`
    /// (`R/2` for equal spheres), `E*` of the two bodies' materials ([`Scene::e_star`]).
    pub fn hertz(&self) -> Hertz {
        let mut h = match self.geometry.slider_sphere_radius {
            Some(r) if r != self.sphere_radius => {
                Hertz::spheres(r, self.sphere_radius, &self.material)
            }
            _ => Hertz::equal_spheres(self.sphere_radius, &self.material),
        };
        h.e_star = self.e_star();
        h
    }

    /// Material of the slider's spheres (Pa, kg/m³): `[slider.material]`, else the shared one.
    pub fn slider_material(&self) -> Material {
        self.body_materials.slider.unwrap_or(self.material)
    }

    /// Material of the substrate's spheres: `[substrate.material]`, else the shared one.
    pub fn substrate_material(&self) -> Material {
        self.body_materials.substrate.unwrap_or(self.material)
    }

    /// Hertz effective modulus E* (Pa) of a slider–substrate pair:
    /// `1/E* = (1 − ν_sl²)/E_sl + (1 − ν_sb²)/E_sb`, `E/(2(1 − ν²))` for one material. O(1).
    pub fn e_star(&self) -> f64 {
        self.slider_material()
            .e_star_with(&self.substrate_material())
    }

    /// Radius (m) of a slider sphere (`sphere_radius` unless the geometry gives its own).
    pub fn slider_sphere_radius(&self) -> f64 {
        self.geometry
            .slider_sphere_radius
            .unwrap_or(self.sphere_radius)
    }

    /// Centre distance (m) at which a slider and a substrate sphere touch: `R_slider + R_substrate`
    /// (`2R` for equal spheres, bit for bit). With per-site sizes these are the bodies'
    /// reference radii; a pair (i, j) touches at `r_i + r_j` ([`Scene::max_contact_distance`]
    /// bounds them).
    pub fn contact_distance(&self) -> f64 {
        self.slider_sphere_radius() + self.sphere_radius
    }

    /// Slider sphere centres relative to the slider centre, unrotated (m), deterministic order:
    /// the site file's sites, or the lattice (with its basis) cut to the outline.
    pub fn slider_sites_local(&self) -> Vec<[f64; 2]> {
        match &self.geometry.slider_sites {
            Some(list) => list.sites.clone(),
            None => pattern::sites_in_outline(
                &self.slider.lattice,
                &self.geometry.slider_basis,
                &self.geometry.outline,
                self.slider.radius,
            ),
        }
    }

    /// Nominal area (m²) of the slider: its outline's area (disc π r² for a site file whose
    /// outline is not given).
    pub fn slider_area(&self) -> f64 {
        self.geometry.outline.area(self.slider.radius)
    }

    /// One-word description of the slider pattern for tables: the lattice kind with its basis
    /// size, or `sites:<file>`.
    pub fn slider_lattice_name(&self) -> String {
        match &self.geometry.slider_sites {
            Some(l) => format!("sites:{}", l.path),
            None => lattice_name(&self.slider.lattice),
        }
    }

    /// Slider sphere centres in the substrate frame (m) for the slider rotated by `theta` (rad)
    /// and its centre at `offset + shift`.
    /// Each site comes from [`place`], the one placement formula (the solver's too).
    pub fn slider_sites_at(&self, theta: f64, shift: [f64; 2]) -> Vec<[f64; 2]> {
        let sc = theta.sin_cos();
        let centre = [
            self.slider.offset[0] + shift[0],
            self.slider.offset[1] + shift[1],
        ];
        self.slider_sites_local()
            .into_iter()
            .map(|p| place(centre, sc, p))
            .collect()
    }

    /// Slider sphere centres in the substrate frame (m) at the scene's own θ and offset.
    pub fn slider_sites(&self) -> Vec<[f64; 2]> {
        self.slider_sites_at(self.slider.theta, [0.0, 0.0])
    }

    /// Substrate sphere centres `[x, y, h]` (m): lattice sites in the rectangle, with heights
    /// `h` uniform in `[-σ_h, σ_h]` from a ChaCha8 stream seeded by `substrate.seed` (all zero
    /// when `σ_h = 0`). With per-site sizes a sphere of radius r_j sits with its bottom on the
    /// substrate plane: its centre is `r_j − R` higher (R = `sphere_radius`).
    pub fn substrate_spheres(&self) -> Vec<[f64; 3]> {
        let sites = match &self.geometry.substrate_sites {
            Some(l) => l.sites.clone(),
            None => pattern::sites_in_rect(
                &self.substrate.lattice,
                &self.geometry.substrate_basis,
                self.substrate.size[0],
                self.substrate.size[1],
            ),
        };
        let sh = self.substrate.sigma_h;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(self.substrate.seed);
        let mut out: Vec<[f64; 3]> = sites
            .into_iter()
            .map(|p| {
                let h = if sh > 0.0 {
                    sh * rng.random_range(-1.0..=1.0)
                } else {
                    0.0
                };
                [p[0], p[1], h]
            })
            .collect();
        if let Some(radii) = self.substrate_radii() {
            for (p, r) in out.iter_mut().zip(radii) {
                p[2] += r - self.sphere_radius;
            }
        }
        out
    }
}

/// `triangular`, `square`, `rectangular` or `oblique` for a Bravais lattice.
pub fn lattice_name(l: &Lattice) -> String {
    let s = l.a1[0].hypot(l.a1[1]);
    if *l == Lattice::triangular(s) {
        "triangular".into()
    } else if *l == Lattice::square(s) {
        "square".into()
    } else if *l == Lattice::rectangular(l.a1[0], l.a2[1]) {
        "rectangular".into()
    } else {
        "oblique".into()
    }
}

/// A slider site at `local` (m, the slider's own frame) placed at the disc centre `centre` (m)
/// rotated by θ with `sin_cos = θ.sin_cos()`: the one formula every slider position comes from,
/// so a position computed alone equals its entry in a full list bit for bit. O(1).
#[inline]
pub fn place(centre: [f64; 2], sin_cos: (f64, f64), local: [f64; 2]) -> [f64; 2] {
    let (s, c) = sin_cos;
    [
        centre[0] + c * local[0] - s * local[1],
        centre[1] + s * local[0] + c * local[1],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_have_study_sizes() {
        for p in ["tri-tri", "square-tri"] {
            let s = Scene::preset(p).unwrap();
            s.validate().unwrap();
            assert_eq!(s.slider_sites().len(), 3505, "{p}");
        }
        assert_eq!(
            Scene::preset("square-tri")
                .unwrap()
                .substrate_spheres()
                .len(),
            12515
        );
    }

    #[test]
    fn heights_are_seeded_and_bounded() {
        let mut s = Scene::preset("tri-tri").unwrap();
        s.substrate.sigma_h = 0.01e-6;
        let a = s.substrate_spheres();
        assert_eq!(a, s.substrate_spheres());
        assert!(a.iter().all(|p| p[2].abs() <= 0.01e-6));
        assert!(a.iter().any(|p| p[2] != 0.0));
        s.substrate.seed = 2;
        assert_ne!(a, s.substrate_spheres());
    }
}
