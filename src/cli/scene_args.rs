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
    #[arg(
        long,
        value_name = "SEED",
        allow_negative_numbers = true,
        value_parser = seed
    )]
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
    /// Slider lattice, `KIND:SPACING_UM`: `triangular:3`, `square:3`, `honeycomb:6`,
    /// `kagome:6` (the lattice constant s in µm; honeycomb and kagome: of their triangular
    /// lattice, with their built-in basis, nearest neighbours s/√3 and s/2 apart) or
    /// `rectangular:3x3.5` (x and y spacings in µm; each example holds 3 µm spheres); replaces
    /// a scene file's `slider.lattice` or `slider.sites`. A basis of your own or an oblique
    /// lattice: the scene file.
    #[arg(long, value_name = "KIND:SPACING_UM")]
    pub slider_lattice: Option<String>,
    /// Slider outline: `disc:R` (radius in µm), `rectangle:WxH` (sides in µm) or
    /// `polygon:N:R` (N sides, circumradius in µm, a vertex on +x); replaces the disc of
    /// `--slider-radius-um`. Arbitrary vertices: the scene file (`slider.outline`).
    #[arg(long, value_name = "SPEC")]
    pub outline: Option<String>,
    /// Slider site file (imaged pattern): CSV `x_um,y_um[,diameter_um]` relative to the slider
    /// centre, path relative to the working directory; replaces the slider lattice.
    #[arg(long, value_name = "FILE.csv")]
    pub slider_sites: Option<PathBuf>,
    /// Substrate site file: CSV `x_um,y_um[,diameter_um]` relative to the substrate centre;
    /// replaces the substrate lattice.
    #[arg(long, value_name = "FILE.csv")]
    pub substrate_sites: Option<PathBuf>,
    /// Slider sphere diameter in µm (study: 3; the substrate keeps its own).
    #[arg(long, value_name = "UM", allow_hyphen_values = true)]
    pub slider_sphere_diameter_um: Option<f64>,
    /// Substrate sphere diameter in µm (study: 3).
    #[arg(long, value_name = "UM", allow_hyphen_values = true)]
    pub substrate_sphere_diameter_um: Option<f64>,
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
        push("--slider-lattice", self.slider_lattice.clone());
        push("--outline", self.outline.clone());
        let path = |p: &Option<PathBuf>| p.as_ref().map(|p| p.display().to_string());
        push("--slider-sites", path(&self.slider_sites));
        push("--substrate-sites", path(&self.substrate_sites));
        push(
            "--slider-sphere-diameter-um",
            self.slider_sphere_diameter_um.map(|x| x.to_string()),
        );
        push(
            "--substrate-sphere-diameter-um",
            self.substrate_sphere_diameter_um.map(|x| x.to_string()),
        );
        v
    }

    /// The lattice of `--slider-lattice` (see its help). Errors name the flag.
    fn lattice(spec: &str) -> Result<surrogate::scene::LatticeFile> {
        let flag = "--slider-lattice";
        let Some((kind, spacing)) = spec.split_once(':') else {
            bail!(
                "`{flag}`: `{spec}` must be KIND:SPACING_UM, e.g. honeycomb:6 or rectangular:3x3.5"
            );
        };
        let num = |t: &str| um_number(flag, t);
        let mut l = surrogate::scene::LatticeFile {
            kind: kind.trim().to_string(),
            ..Default::default()
        };
        match l.kind.as_str() {
            "triangular" | "square" | "honeycomb" | "kagome" => {
                l.spacing_um = Some(num(spacing)?);
            }
            "rectangular" => {
                let Some((x, y)) = spacing.split_once(['x', 'X']) else {
                    bail!("`{flag}`: a rectangular lattice needs two spacings, e.g. rectangular:3x3.5");
                };
                l.spacing_um = Some(num(x)?);
                l.spacing_y_um = Some(num(y)?);
            }
            k => bail!(
                "`{flag}`: unknown lattice kind `{k}` (triangular, square, honeycomb, kagome, rectangular; a basis or an oblique lattice: the scene file's slider.lattice)"
            ),
        }
        Ok(l)
    }

    /// The outline of `--outline` (see its help). Errors name the flag.
    fn outline(spec: &str) -> Result<surrogate::scene::OutlineFile> {
        let flag = "--outline";
        let num = |t: &str| um_number(flag, t);
        let parts: Vec<&str> = spec.split(':').collect();
        let mut o = surrogate::scene::OutlineFile {
            kind: parts[0].trim().to_string(),
            ..Default::default()
        };
        match (o.kind.as_str(), &parts[1..]) {
            ("disc", [r]) => o.radius_um = Some(num(r)?),
            ("rectangle", [wh]) => {
                let Some((w, h)) = wh.split_once(['x', 'X']) else {
                    bail!("`{flag}`: `{spec}`: a rectangle is rectangle:WxH, e.g. rectangle:120x80");
                };
                o.size_um = Some([num(w)?, num(h)?]);
            }
            ("polygon", [n, r]) => {
                o.sides = Some(n.trim().parse().with_context(|| {
                    format!("`{flag}`: `{n}` is not a whole number of sides")
                })?);
                o.radius_um = Some(num(r)?);
            }
            _ => bail!(
                "`{flag}`: `{spec}` must be disc:R, rectangle:WxH or polygon:N:R (µm); arbitrary vertices: the scene file's slider.outline"
            ),
        }
        // refused here in the flag's syntax, before the scene file's rules name its fields
        let positive = |v: Option<f64>| v.is_none_or(|v| v.is_finite() && v > 0.0);
        if !positive(o.radius_um)
            || !o
                .size_um
                .is_none_or(|s| s.iter().all(|v| positive(Some(*v))))
        {
            bail!("`{flag} {spec}`: every length (µm) must be a positive number");
        }
        if o.sides.is_some_and(|n| n < 3) {
            bail!("`{flag} {spec}`: a polygon has at least 3 sides (polygon:N:R)");
        }
        Ok(o)
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
            Some(p) => SceneFile::read(p).map_err(|e| anyhow::anyhow!("`--scene`: {e}"))?,
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
            let num = |t: &str| um_number("--substrate-um", t);
            o.substrate.size_um = Some([num(parts[0])?, num(parts[1])?]);
        }
        if let Some(s) = &self.overrides.offset_um {
            let v = super::parse_list_or_range(s, "--offset-um")?;
            if v.len() != 2 {
                bail!("`--offset-um`: `{s}` must be X,Y");
            }
            o.slider.offset_um = Some([v[0], v[1]]);
        }
        let ov = &self.overrides;
        if let Some(l) = &ov.slider_lattice {
            o.slider.lattice = Some(SceneOverrides::lattice(l)?);
        }
        if let Some(x) = &ov.outline {
            o.slider.outline = Some(SceneOverrides::outline(x)?);
        }
        let path = |p: &PathBuf| p.display().to_string();
        o.slider.sites = ov.slider_sites.as_ref().map(path);
        o.substrate.sites = ov.substrate_sites.as_ref().map(path);
        o.slider.sphere_diameter_um = ov.slider_sphere_diameter_um;
        o.substrate.sphere_diameter_um = ov.substrate_sphere_diameter_um;
        let mut m = f.merge(&o);
        // a lattice flag replaces the file's site list and the other way round
        if ov.slider_lattice.is_some() {
            m.slider.sites = None;
        }
        if ov.slider_sites.is_some() {
            // the sites are the slider: the file's lattice and outline go
            m.slider.lattice = None;
            if ov.outline.is_none() {
                m.slider.outline = None;
            }
        }
        if ov.substrate_sites.is_some() {
            m.substrate.lattice = None;
        }
        Ok(m)
    }

    /// THE scene resolution of every command: preset ← scene file ← flags, with `theta_deg`
    /// (a command's `--theta-deg` for one orientation) overriding the file's `slider.theta_deg`;
    /// validated ([`Scene::validate`]: every field, the slider must fit on the substrate), and
    /// the edge warning collected ([`Scene::edge_warning`]).
    pub fn resolve(&self, theta_deg: Option<f64>) -> Result<Resolved> {
        let mut file = self.scene_file()?;
        if let Some(t) = theta_deg {
            file.slider.theta_deg = Some(super::point_args::theta_deg(t)?);
        } else if let Some(t) = file.slider.theta_deg {
            let max = super::point_args::THETA_MAX_DEG;
            if t.abs() > max {
                bail!(
                    "invalid value for `slider.theta_deg`: {t} (outside [-{max}, {max}] degrees)"
                );
            }
        }
        let scene = file.into_scene().map_err(|e| self.as_flag(e))?;
        let small = scene.slider_size_check().map_err(|e| {
            // the field as the user set it: the flag when one was given
            match (&self.overrides.slider_radius_um, &self.overrides.outline) {
                (Some(_), None) => anyhow::anyhow!("`--slider-radius-um`: {e}"),
                _ => e.into(),
            }
        })?;
        Ok(Resolved {
            warnings: small.into_iter().chain(scene.edge_warning()).collect(),
            scene,
        })
    }
}

impl SceneArgs {
    /// A scene error on a field that a flag of this command line set, restated on the flag
    /// and its value as typed (`` `--p-crit-gpa 4000`: P_crit is in GPa; … ``); any other
    /// error unchanged.
    fn as_flag(&self, e: surrogate::SceneError) -> anyhow::Error {
        let surrogate::SceneError::Invalid { field, why, .. } = &e else {
            return e.into();
        };
        let o = &self.overrides;
        let num = |v: Option<f64>| v.map(|x| x.to_string());
        let given = match field.as_str() {
            "material.youngs_GPa" => ("--youngs-gpa", num(o.youngs_gpa)),
            "coating.p_crit_GPa" => ("--p-crit-gpa", num(o.p_crit_gpa)),
            "substrate.sigma_h_um" => ("--sigma-h-um", num(o.sigma_h_um)),
            "slider.radius_um" => ("--slider-radius-um", num(o.slider_radius_um)),
            "substrate.size_um" => ("--substrate-um", o.substrate_um.clone()),
            "slider.offset_um" => ("--offset-um", o.offset_um.clone()),
            "slider.tilt_k1_N_m" => ("--tilt-k1-n-m", num(o.tilt_k1_n_m)),
            "slider.sphere_diameter_um" => (
                "--slider-sphere-diameter-um",
                num(o.slider_sphere_diameter_um),
            ),
            "substrate.sphere_diameter_um" | "sphere_diameter_um" => (
                "--substrate-sphere-diameter-um",
                num(o.substrate_sphere_diameter_um),
            ),
            "slider.lattice" => ("--slider-lattice", o.slider_lattice.clone()),
            _ => return e.into(),
        };
        match given {
            (flag, Some(v)) => anyhow::anyhow!("`{flag} {v}` ({field}): {why}"),
            _ => e.into(),
        }
    }
}

/// A seed (`--seed`): a whole number ≥ 0. Clap names the flag and the value before this text.
fn seed(t: &str) -> std::result::Result<u64, String> {
    t.trim()
        .parse()
        .map_err(|_| "a seed is a whole number ≥ 0 (0, 1, 2, …)".to_string())
}

/// The length (µm) written `t` in flag `flag`; the error names the flag.
fn um_number(flag: &str, t: &str) -> Result<f64> {
    t.trim()
        .parse()
        .with_context(|| format!("`{flag}`: `{t}` is not a number (µm)"))
}
