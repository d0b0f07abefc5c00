//! The study scenes every tier of the diagrams runs on ([`scenes`]).

use crate::study::corrugation::contact_line;
use anyhow::Result;
use surrogate::units::{deg_to_rad, mn_to_n, um_to_m};
use surrogate::Scene;

/// One study scene of the diagrams: the scene at its θ, the pulling direction and the load.
#[derive(Debug, Clone)]
pub struct StudyScene {
    /// `superlubric`, `coating-failure`, `stick-slip` (prefixed `small-` on a small slider).
    pub name: String,
    /// The scene, slider at θ.
    pub scene: Scene,
    /// Pulling direction (rad from the substrate x axis).
    pub direction: f64,
    /// Normal load W (N), scaled to the study's load per slider sphere on a small slider.
    pub load: f64,
}

/// The three study scenes: square-tri θ = 0°, α = 90° at 1.4 mN (superlubric); tri-tri 30°
/// pulled along the substrate x axis at 2.45 mN (coating failure); square-tri 0°, α = 0° at
/// 1.4 mN (stick-slip). α is measured from the contact line (as `friction` does). With
/// `small = Some((radius_um, substrate_um))` the slider is a disc of that radius over a square
/// substrate of that side, loaded per sphere as the study's (W × N_small / N_study).
pub fn scenes(small: Option<(f64, f64)>) -> Result<Vec<StudyScene>> {
    let specs: [(&str, &str, f64, Option<f64>, f64); 3] = [
        ("superlubric", "square-tri", 0.0, Some(90.0), 1.4),
        ("coating-failure", "tri-tri", 30.0, None, 2.45),
        ("stick-slip", "square-tri", 0.0, Some(0.0), 1.4),
    ];
    specs
        .iter()
        .map(|&(name, pattern, theta_deg, alpha_deg, load_mn)| {
            let mut scene = Scene::preset(pattern)?;
            scene.slider.theta = deg_to_rad(theta_deg);
            let n_study = scene.slider_sites_local().len() as f64;
            let mut load = mn_to_n(load_mn);
            let mut name = name.to_string();
            if let Some((r, side)) = small {
                scene.slider.radius = um_to_m(r);
                scene.substrate.size = [um_to_m(side), um_to_m(side)];
                load *= scene.slider_sites_local().len() as f64 / n_study;
                name = format!("small-{name}");
            }
            scene.validate()?;
            let direction = match alpha_deg {
                Some(a) => contact_line(&scene, None).angle + deg_to_rad(a),
                None => 0.0,
            };
            Ok(StudyScene {
                name,
                scene,
                direction,
                load,
            })
        })
        .collect()
}
