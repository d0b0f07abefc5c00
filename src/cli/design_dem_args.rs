//! [`DesignDemArgs`]: the design's DEM protocol and model flags (`--dem-equilibrate-us`,
//! `--dem-relax-us`, `--dem-slide-us`, `--dem-speed-m-s`, `--dem-dt-us`, `--dem-model`) and
//! `--jobs`, with the design's defaults (2 + 2 + 60 µs at 0.1 m/s, the reduced model), for the
//! commands that run the DEM the way `design` does (`yield`).

use super::checks;
use super::dem_args::ModelArg;
use crate::study::dem_run::{DemParams, ModelSpec};
use anyhow::{bail, Result};
use dem::protocol::RunIo;
use dem::{SimParams, Start};
use surrogate::units::{mn_to_n, us_to_s};

/// The design's DEM protocol (its defaults are the design's).
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct DesignDemArgs {
    /// Equilibration in µs of each DEM run (study: 10).
    #[arg(
        long = "dem-equilibrate-us",
        value_name = "US",
        default_value_t = 2.0,
        allow_hyphen_values = true
    )]
    pub equilibrate_us: f64,
    /// Relaxation in µs with the pulling spring attached (study: 10).
    #[arg(
        long = "dem-relax-us",
        value_name = "US",
        default_value_t = 2.0,
        allow_hyphen_values = true
    )]
    pub relax_us: f64,
    /// Sliding time in µs of each DEM run; friction over its last two thirds (study: 300).
    #[arg(
        long = "dem-slide-us",
        value_name = "US",
        default_value_t = 60.0,
        allow_hyphen_values = true
    )]
    pub slide_us: f64,
    /// Support speed in m/s (study: 0.1).
    #[arg(
        long = "dem-speed-m-s",
        value_name = "M_S",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    pub speed_m_s: f64,
    /// DEM time step in µs [default: 0.25 × the stable-step estimate].
    #[arg(long = "dem-dt-us", value_name = "US", allow_hyphen_values = true)]
    pub dt_us: Option<f64>,
    /// DEM model (as `slide --model`): `reduced` (rigid-z, default, as `design`), `auto`,
    /// `full` or `full-explicit`. A run whose estimate lies in the springs mount's resonance
    /// band uses `auto` where `reduced` was asked (as `design` does outside the validated
    /// range).
    #[arg(long = "dem-model", value_enum, default_value_t = ModelArg::Reduced)]
    pub model: ModelArg,
    /// DEM runs side by side, one thread each [default: the number of CPU cores].
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,
}

/// The parameters of a design's DEM run: `sim` (the protocol; load and α are set per run), the
/// contact line `line` (rad; `None`: the moiré estimate), the model `request`; starting from the
/// surrogate's equilibrium, no checkpoint, no trajectory. The one place `design` and `yield`
/// build them. Cost: none.
pub fn design_run_params(
    sim: SimParams,
    line: Option<f64>,
    request: dem::ModelRequest,
) -> DemParams {
    DemParams {
        sim,
        alpha: 0.0,
        line,
        start: Start::Surrogate,
        friction: None,
        io: RunIo {
            checkpoint: None,
            checkpoint_every: 50_000,
            xyz: None,
            xyz_every: 10_000,
        },
        resume: None,
        model: ModelSpec {
            request,
            ..ModelSpec::default()
        },
    }
}

impl DesignDemArgs {
    /// The checked DEM parameters (load, α set per run; `line` the contact line, rad) and the
    /// runs side by side; each error names its flag.
    pub fn params(&self, line: Option<f64>) -> Result<(DemParams, usize)> {
        for (v, f) in [
            (self.equilibrate_us, "--dem-equilibrate-us"),
            (self.slide_us, "--dem-slide-us"),
            (self.speed_m_s, "--dem-speed-m-s"),
        ] {
            checks::positive(v, f)?;
        }
        checks::non_negative(self.relax_us, "--dem-relax-us")?;
        let dt = self
            .dt_us
            .map(|d| checks::time_us(d, "--dem-dt-us"))
            .transpose()?;
        let jobs = match self.jobs {
            Some(0) => bail!("`--jobs`: give ≥ 1 DEM runs side by side"),
            Some(j) => j,
            None => std::thread::available_parallelism().map_or(1, |n| n.get()),
        };
        let sim = SimParams {
            protocol: dem::ProtocolParams {
                load: mn_to_n(1.0),
                equilibrate_time: us_to_s(self.equilibrate_us),
                relax_time: us_to_s(self.relax_us),
                slide_time: us_to_s(self.slide_us),
                support_speed: self.speed_m_s,
                ..Default::default()
            },
            numerics: dem::NumericsParams {
                dt,
                ..Default::default()
            },
            ..SimParams::default()
        };
        Ok((design_run_params(sim, line, self.model.request()), jobs))
    }
}
