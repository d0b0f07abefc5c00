//! Scene flags shared by every subcommand, and the one scene resolution every command uses.

use anyhow::{bail, Context, Result};
use clap::Args;
use std::path::PathBuf;
use surrogate::{Scene, SceneFile};

/// Scene selection and overrides (every subcommand). Flags override the scene file, which
/// overrides the `--pattern` preset.
#[derive(Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// Pattern pair `slider-substrate`: tri-tri, square-tri, square-square or tri-square, with
    /// the reference study's geometry (3 µm spheres at 3 µm spacing, 3505-sphere slider,
    /// 364x270 µm substrate) [default: the scene file's pattern, else square-tri].
    #[arg(long, value_name = "PATTERN")]
    pub pattern: Option<String>,
    /// Scene file (TOML, user units; see the README section "Scenes"). The flags below
    /// override it.
    #[arg(long, value_name = "FILE.toml")]
    pub scene: Option<PathBuf>,
    /// The override flags.
    #[command(flatten)]
    pub overrides: SceneOverrides,
}

/// The scene override flags (every subcommand, `design` included: they apply to every pattern
/// and scene file it designs).
#[derive(Args, Debug, Clone, Default)]
pub struct SceneOverrides {
    /// Slider disc radius in µm (study: 93.5 triangular, 100 square).
    #[arg(long, value_name = "UM", allow_hyphen_values = true)]
    pub slider_radius_um: Option<f64>,
    /// Substrate rectangle size in µm, `LXxLY` (study: 364x270; x is the long side).
    #[arg(long, value_name = "LXxLY", allow_hyphen_values = true)]
    pub substrate_um: Option<String>,
    /// Amplitude σ_h in µm of random substrate sphere heights, uniform in [-σ_h, σ_h]
    /// (study: 0.002, 0.01).
    #[arg(long, value_name = "UM", allow_hyphen_values = true)]
    pub sigma_h_um: Option<f64>,
    /// Seed (a non-negative integer) of the substrate height perturbation: same seed → same
    /// heights.
    #[arg(long, value_name = "SEED", allow_negative_numbers = true)]
    pub seed: Option<u64>,
    /// Young's modulus E in GPa (study: 100, also 50).
    #[arg(long, value_name = "GPA", allow_hyphen_values = true)]
    pub youngs_gpa: Option<f64>,
    /// Critical coating pressure P_crit in GPa (study: 4).
    #[arg(long, value_name = "GPA", allow_hyphen_values = true)]
    pub p_crit_gpa: Option<f64>,
    /// In-plane offset in µm of the slider centre from the central substrate sphere, `X,Y`
    /// (breaks the symmetry `design`'s θ cut relies on: see its --no-symmetry-cut).
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

impl SceneOverrides {
    /// The flags as given on the command line (for the commands a report prints to reproduce
    /// a result), in declaration order.
    pub fn flags(&self) -> Vec<String> {
        let mut v = Vec::new();
        let mut push = |f: &str, x: Option<String>| {
            if let Some(x) = x {
                v.push(f.to_string());
                v.push(x);
            }
        };
        push(
            "--slider-radius-um",
            self.slider_radius_um.map(|x| x.to_string()),
        );
        push("--substrate-um", self.substrate_um.clone());
        push("--sigma-h-um", self.sigma_h_um.map(|x| x.to_string()));
        push("--seed", self.seed.map(|x| x.to_string()));
        push("--youngs-gpa", self.youngs_gpa.map(|x| x.to_string()));
        push("--p-crit-gpa", self.p_crit_gpa.map(|x| x.to_string()));
        push("--offset-um", self.offset_um.clone());
        push("--tilt", self.tilt.clone());
        push("--tilt-k1-n-m", self.tilt_k1_n_m.map(|x| x.to_string()));
        v
    }
}

/// A validated scene and what every command must report about it.
#[derive(Debug, Clone)]
pub struct Resolved {
    /// The SI scene (validated by `Scene::validate`).
    pub scene: Scene,
    /// Warnings to log and record (e.g. the slider hanging over the substrate edge).
    pub warnings: Vec<String>,
}

impl Resolved {
    /// Logs the warnings (through the command's reporter).
    pub fn log(&self, p: &dyn crate::runs::progress::Progress) {
        for w in &self.warnings {
            p.note(&format!("warning: {w}"));
        }
    }
}

impl SceneArgs {
    /// The [`SceneFile`] these flags describe (file, then flags on top).
    pub fn scene_file(&self) -> Result<SceneFile> {
        let f = match &self.scene {
            Some(p) => SceneFile::read(p)?,
            None => SceneFile::default(),
        };
        let mut o = SceneFile {
            pattern: self.pattern.clone(),
            ..Default::default()
        };
        o.slider.radius_um = self.overrides.slider_radius_um;
        o.slider.tilt = self.overrides.tilt.clone();
        o.slider.tilt_k1_n_m = self.overrides.tilt_k1_n_m;
        o.substrate.sigma_h_um = self.overrides.sigma_h_um;
        o.substrate.seed = self.overrides.seed;
        o.material.youngs_gpa = self.overrides.youngs_gpa;
        o.coating.p_crit_gpa = self.overrides.p_crit_gpa;
        if let Some(s) = &self.overrides.substrate_um {
            let parts: Vec<&str> = s.split(['x', 'X']).collect();
            if parts.len() != 2 {
                bail!("`--substrate-um`: `{s}` must be LXxLY, e.g. 364x270");
            }
            let num = |t: &str| -> Result<f64> {
                t.trim()
                    .parse()
                    .with_context(|| format!("`--substrate-um`: `{t}` is not a number"))
            };
            o.substrate.size_um = Some([num(parts[0])?, num(parts[1])?]);
        }
        if let Some(s) = &self.overrides.offset_um {
            let v = super::parse_list_or_range(s, "--offset-um")?;
            if v.len() != 2 {
                bail!("`--offset-um`: `{s}` must be X,Y");
            }
            o.slider.offset_um = Some([v[0], v[1]]);
        }
        Ok(f.merge(&o))
    }

    /// THE scene resolution of every command: preset ← scene file ← flags, with `theta_deg`
    /// (a command's `--theta` for one orientation) overriding the file's `slider.theta_deg`;
    /// validated ([`Scene::validate`]: every field, the slider must fit on the substrate), and
    /// the edge warning collected ([`Scene::edge_warning`]).
    pub fn resolve(&self, theta_deg: Option<f64>) -> Result<Resolved> {
        let mut file = self.scene_file()?;
        if let Some(t) = theta_deg {
            if !t.is_finite() {
                bail!("`--theta`: {t} is not a finite angle in degrees");
            }
            file.slider.theta_deg = Some(t);
        }
        let scene = file.into_scene()?;
        scene.validate()?;
        Ok(Resolved {
            warnings: scene.edge_warning().into_iter().collect(),
            scene,
        })
    }
}
