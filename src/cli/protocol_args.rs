//! [`ProtocolArgs`]: the sliding protocol's flags (`--relax-us`, `--slide-us`, `--speed-m-s`),
//! declared once for `slide` and `export-lammps` with the study's defaults (10 µs relaxation,
//! 300 µs sliding at 0.1 m/s). `figures --friction` (study defaults unless given, friction
//! campaign only) and `design` (`--dem-` prefixed, a shorter default) keep their own.

use super::checks::non_negative;
use anyhow::{bail, Result};
use dem::ProtocolParams;
use surrogate::units::us_to_s;

/// The sliding protocol of one DEM run, in µs and m/s as given on the command line.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct ProtocolArgs {
    /// Relaxation time in µs with the pulling spring attached and the support at rest (≥ 0;
    /// 0: none).
    #[arg(
        long = "relax-us",
        value_name = "US",
        default_value_t = 10.0,
        allow_hyphen_values = true
    )]
    pub relax_us: f64,
    /// Sliding time in µs (`slide`: > 0; `export-lammps`: 0 = equilibrate and relax only).
    /// Friction = mean spring force over its last 2/3 (study: 100–300 µs of 300 µs).
    #[arg(
        long = "slide-us",
        value_name = "US",
        default_value_t = 300.0,
        allow_hyphen_values = true
    )]
    pub slide_us: f64,
    /// Support speed in m/s (= µm/µs; > 0 for a sliding run).
    #[arg(
        long = "speed-m-s",
        value_name = "M_S",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    pub speed_m_s: f64,
}

impl ProtocolArgs {
    /// No relaxation and no sliding: the protocol of `equilibrate`.
    pub const AT_REST: ProtocolArgs = ProtocolArgs {
        relax_us: 0.0,
        slide_us: 0.0,
        speed_m_s: 0.0,
    };

    /// Sets its part of the DEM protocol `p`: `relax_time`, `slide_time` (s) and
    /// `support_speed` (m/s).
    pub fn apply(&self, p: &mut ProtocolParams) {
        p.relax_time = us_to_s(self.relax_us);
        p.slide_time = us_to_s(self.slide_us);
        p.support_speed = self.speed_m_s;
    }

    /// Checks every flag, naming it: times ≥ 0 and finite, speed ≥ 0 and finite; a run that
    /// slides (`--slide-us` > 0, required when `must_slide`) needs `--speed-m-s` > 0.
    pub fn check(&self, must_slide: bool) -> Result<()> {
        non_negative(self.relax_us, "--relax-us")?;
        non_negative(self.slide_us, "--slide-us")?;
        non_negative(self.speed_m_s, "--speed-m-s")?;
        if must_slide && self.slide_us <= 0.0 {
            bail!(
                "`--slide-us`: {} must be positive for a sliding run",
                self.slide_us
            );
        }
        if self.slide_us > 0.0 && self.speed_m_s <= 0.0 {
            let or = if must_slide {
                ""
            } else {
                " (or use --slide-us 0)"
            };
            bail!(
                "`--speed-m-s`: {} must be positive for a sliding run{or}",
                self.speed_m_s
            );
        }
        Ok(())
    }
}
