//! The fabrication model of a yield: what varies from one fabricated device to the next
//! ([`FabricationModel`]), and one device drawn from it ([`Sample`]).
//!
//! A sample is a θ offset and a pull-direction offset (each uniform over ± its tolerance, or
//! normal with a σ), a fresh substrate realisation at the scene's σ_h (its seed drawn from a
//! stream disjoint from the seeds the design searched), and, off by default, a scatter of the
//! slider's sphere diameters (each sphere its own, coefficient of variation `cv`) and a
//! coating-strength spread (P_crit normal). Normal draws are truncated at ±3σ (so a drawn
//! P_crit or diameter stays positive, and the caller can check that no drawn sphere overlaps
//! its neighbour before any work).
//!
//! Sample `i` draws from its own ChaCha8 stream (seed [`FabricationModel::seed`], stream `i`),
//! so a sample is the same whatever the number of samples or threads. Cost: a few random
//! numbers per sample (one per slider sphere with a diameter scatter).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use surrogate::scene::SiteList;
use surrogate::Scene;

/// The lowest substrate seed a yield draws: every drawn seed has its top bit set, so it never
/// meets the small seeds a design searches (`0`, `1`, `2` …); a seed listed in
/// [`FabricationModel::excluded_seeds`] is never drawn either.
pub const SEED_FLOOR: u64 = 1 << 63;

/// How many σ a normal draw may reach (truncated there).
pub const TRUNCATE_SIGMA: f64 = 3.0;

/// The law of one angular offset (degrees).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "lowercase")]
pub enum OffsetLaw {
    /// Uniform over [−half_width, +half_width] (degrees); 0: no offset.
    Uniform {
        /// Half-width (degrees), the tolerance.
        half_width_deg: f64,
    },
    /// Normal with mean 0 and standard deviation σ (degrees), truncated at ±3σ.
    Normal {
        /// σ (degrees).
        sigma_deg: f64,
    },
}

impl OffsetLaw {
    /// One draw (degrees).
    fn draw(&self, rng: &mut ChaCha8Rng) -> f64 {
        match *self {
            OffsetLaw::Uniform { half_width_deg: h } if h > 0.0 => h * rng.random_range(-1.0..=1.0),
            OffsetLaw::Uniform { .. } => 0.0,
            OffsetLaw::Normal { sigma_deg } => sigma_deg * normal(rng),
        }
    }

    /// Whether every draw is 0.
    pub fn is_zero(&self) -> bool {
        match *self {
            OffsetLaw::Uniform { half_width_deg } => half_width_deg == 0.0,
            OffsetLaw::Normal { sigma_deg } => sigma_deg == 0.0,
        }
    }
}

/// A standard normal draw truncated at ±[`TRUNCATE_SIGMA`] (Box–Muller, rejection beyond).
fn normal(rng: &mut ChaCha8Rng) -> f64 {
    loop {
        let u1: f64 = 1.0 - rng.random::<f64>(); // (0, 1]
        let u2: f64 = rng.random::<f64>();
        let z = (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos();
        if z.abs() <= TRUNCATE_SIGMA {
            return z;
        }
    }
}

/// What varies between fabricated devices (SI except the angles, in degrees as the user gave
/// them).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FabricationModel {
    /// θ offset from the nominal (degrees).
    pub theta: OffsetLaw,
    /// Pull-direction offset from the nominal, in the substrate frame (degrees).
    pub direction: OffsetLaw,
    /// Coefficient of variation of each slider sphere's diameter (0: every sphere the scene's).
    pub sphere_diameter_cv: f64,
    /// σ of the coating strength P_crit (Pa; 0: the scene's P_crit).
    pub p_crit_sigma: f64,
    /// Seed of the sampling streams.
    pub seed: u64,
    /// Substrate seeds never drawn: the scene's own and those the design searched.
    pub excluded_seeds: Vec<u64>,
}

/// One fabricated device drawn from a [`FabricationModel`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    /// Index of the sample (its stream).
    pub index: usize,
    /// θ offset (degrees).
    pub theta_offset_deg: f64,
    /// Pull-direction offset (degrees, substrate frame).
    pub direction_offset_deg: f64,
    /// Substrate seed (≥ [`SEED_FLOOR`], never an excluded one).
    pub substrate_seed: u64,
    /// Coating strength P_crit (Pa).
    pub p_crit: f64,
    /// Each slider sphere's radius (m), in [`Scene::slider_sites_local`] order, when the
    /// diameters scatter.
    pub slider_radii: Option<Vec<f64>>,
}

impl FabricationModel {
    /// Sample `index` for `scene` (its P_crit, sphere radius and slider sites). Cost: a few
    /// random numbers, one per slider sphere with a diameter scatter.
    pub fn sample(&self, scene: &Scene, index: usize) -> Sample {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        rng.set_stream(index as u64);
        let theta_offset_deg = crate::study::rows::clean(self.theta.draw(&mut rng));
        let direction_offset_deg = crate::study::rows::clean(self.direction.draw(&mut rng));
        let substrate_seed = loop {
            let s = SEED_FLOOR | rng.random::<u64>();
            if !self.excluded_seeds.contains(&s) {
                break s;
            }
        };
        let p_crit = if self.p_crit_sigma > 0.0 {
            scene.coating.p_crit + self.p_crit_sigma * normal(&mut rng)
        } else {
            scene.coating.p_crit
        };
        let slider_radii = (self.sphere_diameter_cv > 0.0).then(|| {
            let r = scene.slider_sphere_radius();
            (0..scene.slider_sites_local().len())
                .map(|_| r * (1.0 + self.sphere_diameter_cv * normal(&mut rng)))
                .collect()
        });
        Sample {
            index,
            theta_offset_deg,
            direction_offset_deg,
            substrate_seed,
            p_crit,
            slider_radii,
        }
    }

    /// Whether every sample is the nominal device on the scene's substrate shape (no offset, no
    /// scatter; the substrate seed still changes, which matters only where σ_h > 0).
    pub fn is_nominal(&self) -> bool {
        self.theta.is_zero()
            && self.direction.is_zero()
            && self.sphere_diameter_cv == 0.0
            && self.p_crit_sigma == 0.0
    }
}

/// A [`FabricationModel`] in user units, as `summary.json` and the sidecars record it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct FabricationRecord {
    /// θ offset law (degrees).
    pub theta_offset: OffsetLaw,
    /// Pull-direction offset law (degrees, substrate frame).
    pub direction_offset: OffsetLaw,
    /// σ_h of every drawn substrate (µm, the scene's).
    pub sigma_h_um: f64,
    /// Coefficient of variation of each slider sphere's diameter.
    pub sphere_diameter_cv: f64,
    /// σ of P_crit (GPa) around the scene's.
    pub p_crit_sigma_GPa: f64,
    /// Seed of the sampling streams.
    pub sample_seed: u64,
    /// Substrate seeds never drawn (the scene's own and the design's searched ones).
    pub excluded_seeds: Vec<u64>,
    /// Normal draws are truncated at ± this many σ.
    pub truncate_sigma: f64,
}

impl FabricationModel {
    /// The record of this model for `scene` (user units).
    pub fn record(&self, scene: &Scene) -> FabricationRecord {
        use surrogate::units::{m_to_um, pa_to_gpa};
        FabricationRecord {
            theta_offset: self.theta,
            direction_offset: self.direction,
            sigma_h_um: crate::study::rows::label(m_to_um(scene.substrate.sigma_h)),
            sphere_diameter_cv: self.sphere_diameter_cv,
            p_crit_sigma_GPa: crate::study::rows::label(pa_to_gpa(self.p_crit_sigma)),
            sample_seed: self.seed,
            excluded_seeds: self.excluded_seeds.clone(),
            truncate_sigma: TRUNCATE_SIGMA,
        }
    }
}

impl Sample {
    /// The scene of this device (θ = 0: the solver's frame): `scene` with the drawn substrate
    /// seed, P_crit and slider sphere sizes. Cost: a copy of the slider sites with a diameter
    /// scatter, else of the scene.
    pub fn scene(&self, scene: &Scene) -> Scene {
        let mut s = scene.clone();
        s.slider.theta = 0.0;
        s.substrate.seed = self.substrate_seed;
        s.coating.p_crit = self.p_crit;
        if let Some(radii) = &self.slider_radii {
            s.geometry.slider_sites = Some(SiteList {
                path: format!("fabrication sample {}", self.index),
                sites: scene.slider_sites_local(),
                diameter: None,
                radii: Some(radii.clone()),
                cells: Vec::new(),
                lines: Vec::new(),
            });
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn model() -> FabricationModel {
        FabricationModel {
            theta: OffsetLaw::Uniform {
                half_width_deg: 0.1,
            },
            direction: OffsetLaw::Normal { sigma_deg: 0.2 },
            sphere_diameter_cv: 0.0,
            p_crit_sigma: 0.2e9,
            seed: 7,
            excluded_seeds: vec![1],
        }
    }

    /// A sample depends on its index only (not on which others were drawn), offsets stay in
    /// their laws' ranges, and P_crit within ±3σ.
    #[test]
    fn samples_are_streams_within_their_laws() {
        let scene = Scene::preset("square-tri").unwrap();
        let m = model();
        let all: Vec<Sample> = (0..200).map(|i| m.sample(&scene, i)).collect();
        assert_eq!(m.sample(&scene, 57), all[57]);
        for s in &all {
            assert!(s.theta_offset_deg.abs() <= 0.1);
            assert!(s.direction_offset_deg.abs() <= 0.6 + 1e-12);
            assert!((s.p_crit - 4e9).abs() <= 0.6e9 + 1.0);
        }
        assert!(all.iter().any(|s| s.theta_offset_deg < -0.05));
        assert!(all.iter().any(|s| s.theta_offset_deg > 0.05));
        let mean = all.iter().map(|s| s.direction_offset_deg).sum::<f64>() / 200.0;
        assert!(mean.abs() < 0.05, "{mean}");
    }

    /// The drawn substrate seeds never coincide with the design's searched seeds: they lie
    /// above every small seed, and a seed listed as searched is never drawn even where the
    /// stream would give it.
    #[test]
    fn drawn_seeds_never_meet_the_searched_seeds() {
        let scene = Scene::preset("square-tri").unwrap();
        let mut m = model();
        m.excluded_seeds = vec![1, 2, 3, 4, 5];
        let seeds: Vec<u64> = (0..1000)
            .map(|i| m.sample(&scene, i).substrate_seed)
            .collect();
        for s in &seeds {
            assert!(*s >= SEED_FLOOR && !m.excluded_seeds.contains(s));
        }
        let mut u = seeds.clone();
        u.sort_unstable();
        u.dedup();
        assert_eq!(u.len(), seeds.len(), "distinct substrates");
        // a design that searched sample 3's seed: the yield draws another one there
        m.excluded_seeds.push(seeds[3]);
        let again = m.sample(&scene, 3).substrate_seed;
        assert_ne!(again, seeds[3]);
        assert!(again >= SEED_FLOOR);
        assert_eq!(m.sample(&scene, 4).substrate_seed, seeds[4]);
    }

    #[test]
    fn a_diameter_scatter_gives_each_sphere_its_own_size() {
        let mut scene = Scene::preset("square-tri").unwrap();
        scene.slider.radius = 15e-6;
        let mut m = model();
        m.sphere_diameter_cv = 0.01;
        let s = m.sample(&scene, 0);
        let r = s.slider_radii.as_ref().unwrap();
        assert_eq!(r.len(), scene.slider_sites_local().len());
        assert!(r.iter().all(|&x| (x / 1.5e-6 - 1.0).abs() <= 0.03 + 1e-12));
        assert!(r.windows(2).any(|w| w[0] != w[1]));
        let sc = s.scene(&scene);
        assert_eq!(sc.slider_radii().unwrap(), &r[..]);
        assert_eq!(sc.substrate.seed, s.substrate_seed);
    }
}
