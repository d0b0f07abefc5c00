//! Scene flags shared by every subcommand.

use anyhow::{bail, Context, Result};
use clap::Args;
use std::path::PathBuf;
use surrogate::{Scene, SceneFile};

/// Scene selection and overrides (every subcommand). Flags override the scene file, which
/// overrides the `--pattern` preset.
#[derive(Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// Pattern pair shorthand `slider-substrate`: tri-tri, square-tri, square-square, tri-square.
    /// The reference study's geometry (3 µm spheres, 3505-sphere slider, 364x270 µm substrate).
    #[arg(long)]
    pub pattern: Option<String>,
    /// Scene file (TOML, user units); see README "Scene files". Flags below override it.
    #[arg(long, value_name = "FILE.toml")]
    pub scene: Option<PathBuf>,
    /// Slider disc radius in µm (study: 93.5 triangular, 100 square).
    #[arg(long, value_name = "UM", allow_hyphen_values = true)]
    pub slider_radius_um: Option<f64>,
    /// Substrate rectangle size in µm, `LXxLY` (study: 364x270; x is the long side).
    #[arg(long, value_name = "LXxLY")]
    pub substrate_um: Option<String>,
    /// Amplitude σ_h in µm of random substrate sphere heights, uniform in [-σ_h, σ_h] (study: 0.002, 0.01).
    #[arg(long, value_name = "UM", allow_hyphen_values = true)]
    pub sigma_h_um: Option<f64>,
    /// Seed of the substrate height perturbation (same seed → same heights).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Young's modulus in GPa (study: 100, also 50).
    #[arg(long, value_name = "GPA", allow_hyphen_values = true)]
    pub youngs_gpa: Option<f64>,
    /// Critical coating pressure P_crit in GPa (study: 4).
    #[arg(long, value_name = "GPA", allow_hyphen_values = true)]
    pub p_crit_gpa: Option<f64>,
    /// In-plane offset of the slider centre from the central substrate sphere in µm, `X,Y`.
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    pub offset_um: Option<String>,
    /// Slider mount (tilt of the control layer), obeyed by every tier: `locked` (no tilt),
    /// `free` (tilts with no restoring moment) or `springs` (the study's anti-tilt springs K1
    /// between opposing halves of the control layer) [default: springs, K1 = 1e6 N/m].
    #[arg(long, value_name = "MOUNT")]
    pub tilt: Option<String>,
    /// Anti-tilt spring stiffness K1 in N/m of `--tilt springs` (study: 1e6).
    #[arg(long = "tilt-k1-n-m", value_name = "N_M", allow_hyphen_values = true)]
    pub tilt_k1_n_m: Option<f64>,
}

impl SceneArgs {
    /// The [`SceneFile`] these flags describe (file, then flags on top).
    pub fn scene_file(&self) -> Result<SceneFile> {
        let mut f = match &self.scene {
            Some(p) => SceneFile::read(p)?,
            None => SceneFile::default(),
        };
        let mut o = SceneFile {
            pattern: self.pattern.clone(),
            ..Default::default()
        };
        o.slider.radius_um = self.slider_radius_um;
        o.slider.tilt = self.tilt.clone();
        o.slider.tilt_k1_n_m = self.tilt_k1_n_m;
        o.substrate.sigma_h_um = self.sigma_h_um;
        o.substrate.seed = self.seed;
        o.material.youngs_gpa = self.youngs_gpa;
        o.coating.p_crit_gpa = self.p_crit_gpa;
        if let Some(s) = &self.substrate_um {
            let parts: Vec<&str> = s.split(['x', 'X']).collect();
            if parts.len() != 2 {
                bail!("`--substrate-um`: `{s}` must be LXxLY, e.g. 364x270");
            }
            let lx: f64 = parts[0]
                .trim()
                .parse()
                .with_context(|| format!("`--substrate-um`: `{}` is not a number", parts[0]))?;
            let ly: f64 = parts[1]
                .trim()
                .parse()
                .with_context(|| format!("`--substrate-um`: `{}` is not a number", parts[1]))?;
            o.substrate.size_um = Some([lx, ly]);
        }
        if let Some(s) = &self.offset_um {
            let v = super::parse_list_or_range(s, "--offset-um")?;
            if v.len() != 2 {
                bail!("`--offset-um`: `{s}` must be X,Y");
            }
            o.slider.offset_um = Some([v[0], v[1]]);
        }
        f = f.merge(&o);
        Ok(f)
    }

    /// The validated SI scene.
    pub fn scene(&self) -> Result<Scene> {
        Ok(self.scene_file()?.into_scene()?)
    }
}
