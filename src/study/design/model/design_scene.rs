//! [`DesignScene`]: one pattern pair as the design takes it, the input of every stage.

/// One pattern pair of a design: its name (the pattern, or a scene file's stem; used in file
/// names), the validated scene (SI, θ = 0), the scene flags that reproduce it on another
/// command's command line, and the warnings to report.
#[derive(Debug, Clone)]
pub struct DesignScene {
    /// Name used in the report and the file names (`square-tri`, `my_scene`).
    pub name: String,
    /// The scene (SI); its `slider.theta` is ignored (θ is swept).
    pub scene: surrogate::Scene,
    /// Scene flags reproducing it (`--pattern square-tri --sigma-h-um 0.01`).
    pub flags: Vec<String>,
    /// Warnings about the scene (edge overhang…).
    pub warnings: Vec<String>,
    /// What `superlube patterns` recorded of it, when it comes from an `index.csv`.
    pub facts: Option<crate::study::patterns::CandidateFacts>,
    /// What the design knows of it as a recipe of `design --vary` (why it lies outside the
    /// validated range; the DEM decides such a recipe, [`super::super::confirm`]); `None`: not a
    /// recipe.
    pub recipe: Option<crate::study::recipe::RecipeFacts>,
}

impl DesignScene {
    /// The scene as recorded in the stored stages' inputs: its scene file with θ left out (θ
    /// is swept). Cost: one scene-file conversion.
    pub fn record(&self) -> surrogate::scene::SceneFile {
        let mut f = crate::runs::meta::scene_file(&self.scene);
        f.slider.theta_deg = None;
        f
    }
}
