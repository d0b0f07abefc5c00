//! `superlube slide`: flags → [`crate::study::slide::slide`] → time series, summary, sidecars.

use super::dem_args::DemArgs;
use crate::study::slide::slide;
use crate::study::Reporter;
use anyhow::{bail, Result};

/// Options of `superlube slide`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    dem: DemArgs,
    /// Relaxation time in µs with the pulling spring attached and the support at rest (≥ 0).
    #[arg(
        long = "relax-us",
        value_name = "US",
        default_value_t = 10.0,
        allow_hyphen_values = true
    )]
    relax_us: f64,
    /// Sliding time in µs (> 0). Friction = mean spring force over the last 2/3 (study:
    /// 100–300 µs of 300 µs).
    #[arg(
        long = "slide-us",
        value_name = "US",
        default_value_t = 300.0,
        allow_hyphen_values = true
    )]
    slide_us: f64,
    /// Support speed in m/s (= µm/µs; > 0).
    #[arg(
        long = "speed-m-s",
        value_name = "M_S",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    speed_m_s: f64,
}

/// Runs `superlube slide`.
pub fn run(a: Args) -> Result<()> {
    for (v, f) in [
        (a.relax_us, "--relax-us"),
        (a.slide_us, "--slide-us"),
        (a.speed_m_s, "--speed-m-s"),
    ] {
        if !(v.is_finite() && v >= 0.0) {
            bail!("`{f}`: {v} must be a non-negative number");
        }
    }
    if a.slide_us <= 0.0 || a.speed_m_s <= 0.0 {
        bail!("`--slide-us` and `--speed-m-s` must be positive for a sliding run");
    }
    let (sc, params) = a.dem.setup(a.relax_us, a.slide_us, a.speed_m_s)?;
    let rep = Reporter::stderr();
    sc.log(&rep);
    let outs = a.dem.outputs("slide", &sc, &params);
    let (out, report) = slide(&sc.scene, &params, &rep)?;
    a.dem.write(outs, out, report.as_ref())
}
