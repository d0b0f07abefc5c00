//! The point flags, declared once for every command that takes them: slider orientation θ
//! (`--theta-deg`, degrees), pulling angle α (`--alpha-deg`, degrees from the contact line),
//! pulling direction (`--direction-deg`, degrees from the substrate x axis) and normal load W
//! (`--load-mn`, mN), with their parsing and checks (each error names the flag; mN → N and
//! degrees → rad through [`surrogate::units`]).
//!
//! One small group per flag and shape (one value, or a list `a,b` / inclusive range
//! `start:stop:step`), flattened with `#[command(flatten)]` where the command lists the flag,
//! so that `--help` keeps its order. The flag's name, hidden alias, value name, type and the
//! group's default live here; a command that words the help its own way or has another
//! default says so on its own struct: `#[command(mut_args(help(THETA, "…")))]`, [`help`] and
//! [`default`], by the ids [`THETA`], [`ALPHA`], [`DIRECTION`] and [`LOAD`].

use super::parse_list_or_range;
use crate::study::campaign::STUDY_LOADS_MN;
use anyhow::{bail, Result};
use clap::Arg;
use std::sync::LazyLock;
use surrogate::units::{deg_to_rad, mn_to_n};

/// The clap id of `--theta-deg` (for [`help`] and [`default`]).
pub const THETA: &str = "theta";
/// The clap id of `--alpha-deg`.
pub const ALPHA: &str = "alpha";
/// The clap id of `--direction-deg` (`conflicts_with` names it).
pub const DIRECTION: &str = "direction_deg";
/// The clap id of `--load-mn`.
pub const LOAD: &str = "load_mn";

/// The study's orientation sweep (degrees): `screen`'s and `design`'s default θ list.
pub const STUDY_THETAS: &str = "0:30:0.1";
/// The study's orientation-sweep loads (mN): the default of [`Loads`] (`screen`, `friction`).
pub const SCREEN_LOADS: &str = "0.35,1.4,2.1,3.86";
/// The study's load list (mN) as clap's default string (`0.35,0.7,…,3.5,3.86`), formatted from
/// its one definition [`STUDY_LOADS_MN`]: the (hidden) default of [`StudyLoads`].
pub static STUDY_LOADS: LazyLock<String> = LazyLock::new(|| {
    let loads: Vec<String> = STUDY_LOADS_MN.iter().map(|w| w.to_string()).collect();
    loads.join(",")
});

/// The help of a single `--theta-deg` that is a design's nominal θ (`tolerance`, `yield`).
pub const NOMINAL_THETA_HELP: &str =
    "Nominal slider orientation θ in degrees [default: the scene file's theta_deg, else 0]";

/// Mutator for `#[command(mut_args(…))]`: applies `f` to the flag `id` of a command, leaving
/// every other flag, and the flag's place among them, as they are (`mut_arg` would re-insert
/// it at the end of the command's list).
pub fn with(id: &'static str, f: impl Fn(Arg) -> Arg) -> impl FnMut(Arg) -> Arg {
    move |a| if a.get_id() == id { f(a) } else { a }
}

/// Mutator for `#[command(mut_args(…))]`: sets the help of the flag `id` to a command's own
/// wording, `text` shown as given (a one-paragraph doc comment loses its final period, so
/// `text` has none).
pub fn help(id: &'static str, text: &'static str) -> impl FnMut(Arg) -> Arg {
    with(id, move |a| a.help(text))
}

/// Mutator for `#[command(mut_args(…))]`: sets the default of the flag `id` to `value` (as
/// typed on the command line; shown as `[default: value]`).
pub fn default(id: &'static str, value: &'static str) -> impl FnMut(Arg) -> Arg {
    with(id, move |a| a.default_value(value))
}

/// `--theta-deg DEG`: one slider orientation θ in degrees (`None`: the scene's).
#[derive(clap::Args, Debug, Clone, Copy, Default)]
pub struct Theta {
    /// Slider orientation θ in degrees [default: the scene file's theta_deg, else 0].
    #[arg(
        id = THETA,
        long = "theta-deg",
        alias = "theta",
        value_name = "DEG",
        allow_hyphen_values = true
    )]
    pub deg: Option<f64>,
}

impl Theta {
    /// θ in degrees, checked ([`theta_deg`]); `None` when not given.
    pub fn checked(&self) -> Result<Option<f64>> {
        self.deg.map(theta_deg).transpose()
    }
}

/// `--theta-deg LIST`: slider orientations θ in degrees, a list or range (`None`: the
/// command's default, e.g. the scene's θ).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct Thetas {
    /// Slider orientations θ in degrees: a list `0,21.8,30` or an inclusive range
    /// `start:stop:step` [default: the scene file's theta_deg if set, else 0:30:0.1].
    #[arg(
        id = THETA,
        long = "theta-deg",
        alias = "theta",
        value_name = "DEG",
        allow_hyphen_values = true
    )]
    pub text: Option<String>,
}

impl Thetas {
    /// The orientations in degrees, each checked ([`thetas_deg`]); `None` when not given.
    pub fn degrees(&self) -> Result<Option<Vec<f64>>> {
        self.text.as_deref().map(thetas_deg).transpose()
    }

    /// The orientations in rad, each checked ([`thetas`]); `None` when not given.
    pub fn radians(&self) -> Result<Option<Vec<f64>>> {
        self.text.as_deref().map(thetas).transpose()
    }
}

/// `--alpha-deg DEG`: one pulling angle α in degrees from the slider's contact line.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct Alpha {
    /// Pulling angle α in degrees from the slider's contact line (as in `superlube slide`).
    #[arg(
        id = ALPHA,
        long = "alpha-deg",
        alias = "alpha",
        value_name = "DEG",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    pub deg: f64,
}

impl Alpha {
    /// α in rad, checked ([`alpha`]).
    pub fn radians(&self) -> Result<f64> {
        alpha(self.deg)
    }
}

/// `--alpha-deg LIST`: pulling angles α in degrees from the contact line, a list or range
/// (default `0`).
#[derive(clap::Args, Debug, Clone)]
pub struct Alphas {
    /// Pulling angles α in degrees from the contact line, |α| ≤ 180: a list `0,90` or an
    /// inclusive range `start:stop:step`.
    #[arg(
        id = ALPHA,
        long = "alpha-deg",
        alias = "alpha",
        value_name = "DEG",
        default_value = "0",
        allow_hyphen_values = true
    )]
    pub text: String,
}

impl Alphas {
    /// The angles in degrees, each checked ([`alphas_deg`]).
    pub fn degrees(&self) -> Result<Vec<f64>> {
        alphas_deg(&self.text)
    }

    /// The angles in rad, each checked ([`alphas`]).
    pub fn radians(&self) -> Result<Vec<f64>> {
        alphas(&self.text)
    }
}

/// The nominal pulling direction as either `--alpha-deg DEG` (from the slider's contact line)
/// or `--direction-deg DEG` (from the substrate x axis), not both; neither is required here.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct Pull {
    /// Nominal pulling angle α in degrees from the slider's contact line at the nominal θ
    /// (as in `design`'s ranking; 90 = across the lines). Give this or --direction-deg.
    #[arg(
        id = ALPHA,
        long = "alpha-deg",
        alias = "alpha",
        value_name = "DEG",
        allow_hyphen_values = true,
        conflicts_with = DIRECTION
    )]
    pub alpha_deg: Option<f64>,
    /// Nominal pulling direction in degrees from the substrate's x axis (design's
    /// `direction_deg`). Give this or --alpha-deg.
    #[arg(id = DIRECTION, long = "direction-deg", value_name = "DEG", allow_hyphen_values = true)]
    pub direction_deg: Option<f64>,
}

/// `--direction-deg DEG` (required): the pulling direction in degrees from the substrate's x
/// axis.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct Direction {
    /// Nominal pulling direction in degrees from the substrate's x axis (design's
    /// `direction_deg`); a misaligned device keeps it in the substrate frame.
    #[arg(id = DIRECTION, long = "direction-deg", value_name = "DEG", allow_hyphen_values = true)]
    pub deg: f64,
}

impl Direction {
    /// The direction in degrees, checked ([`direction_deg`]).
    pub fn checked(&self) -> Result<f64> {
        direction_deg(self.deg)
    }
}

/// `--load-mn MN`: one normal load W in mN (default 1.4).
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct Load {
    /// Normal load W in mN (> 0).
    #[arg(
        id = LOAD,
        long = "load-mn",
        value_name = "MN",
        default_value_t = 1.4,
        allow_hyphen_values = true
    )]
    pub mn: f64,
}

impl Load {
    /// The load in N, checked ([`load`]).
    pub fn newtons(&self) -> Result<f64> {
        load(self.mn)
    }
}

/// `--load-mn LIST`: normal loads W in mN, a list or range (default [`SCREEN_LOADS`]).
#[derive(clap::Args, Debug, Clone)]
pub struct Loads {
    /// Normal loads W in mN: a list `0.35,1.4` or a range `0.35:3.5:0.35` (each > 0).
    #[arg(
        id = LOAD,
        long = "load-mn",
        value_name = "MN",
        default_value = SCREEN_LOADS,
        allow_hyphen_values = true
    )]
    pub text: String,
}

impl Loads {
    /// The loads in mN, each checked ([`load`]).
    pub fn mn(&self) -> Result<Vec<f64>> {
        loads_mn(&self.text)
    }

    /// The loads in N, each checked ([`loads`]).
    pub fn newtons(&self) -> Result<Vec<f64>> {
        loads(&self.text)
    }
}

/// `--load-mn LIST`: a load ladder in mN, a list or range (default the study's
/// [`STUDY_LOADS`], not shown); the command checks that it increases.
#[derive(clap::Args, Debug, Clone)]
pub struct StudyLoads {
    /// Normal loads W in mN, strictly increasing [default: the study's 0.35 … 3.86].
    #[arg(
        id = LOAD,
        long = "load-mn",
        value_name = "MN",
        default_value = STUDY_LOADS.as_str(),
        hide_default_value = true,
        allow_hyphen_values = true
    )]
    pub text: String,
}

impl StudyLoads {
    /// The loads in N, each checked ([`loads`]); not yet checked to increase.
    pub fn newtons(&self) -> Result<Vec<f64>> {
        loads(&self.text)
    }
}

/// `--load-mn LIST` without a default: loads in mN, a list or range (`None`: the command's
/// own list).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct LoadsOr {
    /// Loads in mN, a list or range.
    #[arg(
        id = LOAD,
        long = "load-mn",
        value_name = "MN",
        allow_hyphen_values = true
    )]
    pub text: Option<String>,
}

impl LoadsOr {
    /// The loads in mN, each checked ([`load`]), or `default` (mN) when not given.
    pub fn mn_or(&self, default: &[f64]) -> Result<Vec<f64>> {
        match &self.text {
            None => Ok(default.to_vec()),
            Some(t) => loads_mn(t),
        }
    }
}

/// One load in mN (> 0, plausible: [`super::checks::plausible`]) → N.
pub fn load(v: f64) -> Result<f64> {
    if !(v.is_finite() && v > 0.0) {
        bail!("`--load-mn`: {v} must be a positive load in mN");
    }
    Ok(mn_to_n(super::checks::plausible(v, "--load-mn")?))
}

/// `--load-mn` list or range, each checked by [`load`], in mN.
pub fn loads_mn(text: &str) -> Result<Vec<f64>> {
    let v = parse_list_or_range(text, "--load-mn")?;
    for &w in &v {
        load(w)?;
    }
    Ok(v)
}

/// `--load-mn` list or range (each checked by [`load`]) → N.
pub fn loads(text: &str) -> Result<Vec<f64>> {
    Ok(loads_mn(text)?.into_iter().map(mn_to_n).collect())
}

/// The largest |θ| in degrees a command takes: a full turn either way, so that a sweep
/// `0:360:1` of a pattern without symmetry is one range.
pub const THETA_MAX_DEG: f64 = 360.0;

/// One slider orientation θ in degrees, finite with |θ| ≤ [`THETA_MAX_DEG`] (θ and θ ± 360°
/// are the same orientation, so a larger value is a typing slip); returned unchanged.
pub fn theta_deg(v: f64) -> Result<f64> {
    if !(v.is_finite() && v.abs() <= THETA_MAX_DEG) {
        bail!("`--theta-deg`: {v}° is outside [-{THETA_MAX_DEG}, {THETA_MAX_DEG}] degrees");
    }
    Ok(v)
}

/// `--theta-deg` list or range (degrees, each checked by [`theta_deg`]), in degrees.
pub fn thetas_deg(text: &str) -> Result<Vec<f64>> {
    parse_list_or_range(text, "--theta-deg")?
        .into_iter()
        .map(theta_deg)
        .collect()
}

/// `--theta-deg` list or range (degrees, each checked by [`theta_deg`]) → rad.
pub fn thetas(text: &str) -> Result<Vec<f64>> {
    Ok(thetas_deg(text)?.into_iter().map(deg_to_rad).collect())
}

/// One pulling angle α (degrees from the contact line, |α| ≤ 180) → rad.
pub fn alpha(v: f64) -> Result<f64> {
    if !(v.is_finite() && v.abs() <= 180.0) {
        bail!("`--alpha-deg`: {v}° is outside [-180, 180] degrees");
    }
    Ok(deg_to_rad(v))
}

/// `--alpha-deg` list or range (degrees, each checked by [`alpha`]), in degrees.
pub fn alphas_deg(text: &str) -> Result<Vec<f64>> {
    let v = parse_list_or_range(text, "--alpha-deg")?;
    for &a in &v {
        alpha(a)?;
    }
    Ok(v)
}

/// `--alpha-deg` list or range (each checked by [`alpha`]) → rad.
pub fn alphas(text: &str) -> Result<Vec<f64>> {
    Ok(alphas_deg(text)?.into_iter().map(deg_to_rad).collect())
}

/// One pulling direction in degrees from the substrate x axis: finite; returned unchanged.
pub fn direction_deg(v: f64) -> Result<f64> {
    if !v.is_finite() {
        bail!("`--direction-deg`: {v} is not a finite angle");
    }
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{Args, Command};

    /// Every group declares its flag under the id that [`help`] and [`default`] take.
    #[test]
    fn the_groups_use_the_ids() {
        let ids = |c: Command| -> Vec<String> {
            c.get_arguments().map(|a| a.get_id().to_string()).collect()
        };
        for (c, id) in [
            (Theta::augment_args(Command::new("t")), THETA),
            (Thetas::augment_args(Command::new("t")), THETA),
            (Alpha::augment_args(Command::new("t")), ALPHA),
            (Alphas::augment_args(Command::new("t")), ALPHA),
            (Direction::augment_args(Command::new("t")), DIRECTION),
            (Load::augment_args(Command::new("t")), LOAD),
            (Loads::augment_args(Command::new("t")), LOAD),
            (StudyLoads::augment_args(Command::new("t")), LOAD),
            (LoadsOr::augment_args(Command::new("t")), LOAD),
        ] {
            assert_eq!(ids(c), vec![id.to_string()]);
        }
        assert_eq!(
            ids(Pull::augment_args(Command::new("t"))),
            vec![ALPHA.to_string(), DIRECTION.to_string()]
        );
    }

    /// Each check names its flag; mN → N.
    #[test]
    fn checks_name_the_flag() {
        assert_eq!(load(1.4).unwrap(), mn_to_n(1.4));
        let err = |r: Result<f64>| r.unwrap_err().to_string();
        assert!(err(load(-1.0)).starts_with("`--load-mn`"));
        assert!(err(theta_deg(400.0)).starts_with("`--theta-deg`"));
        assert!(err(alpha(200.0)).starts_with("`--alpha-deg`"));
        assert!(err(direction_deg(f64::NAN)).starts_with("`--direction-deg`"));
    }
}
