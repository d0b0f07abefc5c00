//! `superlube slide`: the full DEM protocol (equilibrate, attach the pulling spring and relax,
//! slide at constant support speed): friction force and coefficient, lock-in.

use super::dem_args::{DemArgs, RunInfo};
use anyhow::{bail, Result};
use dem::protocol::{slide_summary, RunKind, SlideSummary};
use serde::Serialize;

/// Options of `superlube slide`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    dem: DemArgs,
    /// Relaxation time in µs with the pulling spring attached and the support at rest.
    #[arg(
        long = "relax-us",
        value_name = "US",
        default_value_t = 10.0,
        allow_hyphen_values = true
    )]
    relax_us: f64,
    /// Sliding time in µs. Friction = mean spring force over the last 2/3 (study: 100–300 µs).
    #[arg(
        long = "slide-us",
        value_name = "US",
        default_value_t = 300.0,
        allow_hyphen_values = true
    )]
    slide_us: f64,
    /// Support speed in m/s (= µm/µs).
    #[arg(long = "speed-m-s", value_name = "M_S", default_value_t = 0.1)]
    speed_m_s: f64,
}

#[derive(Serialize)]
struct Summary {
    #[serde(flatten)]
    result: SlideSummary,
    #[serde(flatten)]
    run: RunInfo,
}

/// Runs `superlube slide`.
pub fn run(args: Args) -> Result<()> {
    for (v, f) in [
        (args.relax_us, "--relax-us"),
        (args.slide_us, "--slide-us"),
        (args.speed_m_s, "--speed-m-s"),
    ] {
        if !(v.is_finite() && v >= 0.0) {
            bail!("`{f}`: {v} must be a non-negative number");
        }
    }
    if args.slide_us <= 0.0 || args.speed_m_s <= 0.0 {
        bail!("`--slide-us` and `--speed-m-s` must be positive for a sliding run");
    }
    let (scene, params) = args
        .dem
        .setup(args.relax_us, args.slide_us, args.speed_m_s)?;
    let p = params.clone();
    let f = args.dem.execute(&scene, params, RunKind::Slide)?;
    let result = slide_summary(&f.samples, &p, f.prepared.sim.state.step, f.wall_s);
    eprintln!(
        "slide: friction {:.5} mN (μ = {:.5}), {:.1} contacts on average, max P_max {:.3} GPa{}; {} steps in {:.1} s",
        result.friction_mn,
        result.mu,
        result.mean_contacts,
        result.max_p_max_gpa,
        if result.locked_in { ", LOCKED IN" } else { "" },
        f.steps_this_process,
        f.wall_s
    );
    args.dem.write_summary(&Summary {
        result,
        run: f.info,
    })
}
