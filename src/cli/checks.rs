//! Flag checks shared by the commands: each error names the flag and the rule, before any work.

use anyhow::{bail, Result};
use surrogate::scene::plausible::{self, Plausible};
use surrogate::units::{deg_to_rad, um_to_m, us_to_s};

/// A clap parse error as this tool's error: clap's own message, without its `error: ` prefix
/// (the caller's error chain adds one) and trailing blank lines.
pub fn clap_error(e: clap::Error) -> anyhow::Error {
    anyhow::anyhow!(
        "{}",
        e.render()
            .to_string()
            .trim_start_matches("error: ")
            .trim_end()
    )
}

/// The plausible range ([`surrogate::scene::plausible`]) of a flag, from the unit in its
/// name: `…dt-us` the time step, other `…-us` a duration, `…speed-m-s` a speed, `…load-mn` a
/// load, `…-n-m` a spring, other `…-um` a length; `None` for the rest.
pub fn range_of(flag: &str) -> Option<&'static Plausible> {
    Some(if flag.ends_with("dt-us") {
        &plausible::DT_US
    } else if flag.ends_with("-us") {
        &plausible::DURATION_US
    } else if flag.ends_with("speed-m-s") {
        &plausible::SPEED_M_S
    } else if flag.ends_with("load-mn") {
        &plausible::LOAD_MN
    } else if flag.ends_with("-n-m") {
        &plausible::SPRING_N_M
    } else if flag.ends_with("-um") {
        &plausible::SIZE_UM
    } else {
        return None;
    })
}

/// A value > 0 of `flag` checked against the flag's plausible range ([`range_of`]); the
/// refusal names the flag, the value as typed, the unit and the likely slip.
pub fn plausible(v: f64, flag: &str) -> Result<f64> {
    match range_of(flag).map(|p| p.check(v)) {
        Some(Err(why)) => bail!("`{flag} {v}`: {why}"),
        _ => Ok(v),
    }
}

/// `v` must be finite and > 0 (and plausible for the unit in the flag's name: [`plausible`]).
pub fn positive(v: f64, flag: &str) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        plausible(v, flag)
    } else {
        bail!("`{flag}`: {v} must be a positive number")
    }
}

/// `v` must be finite and ≥ 0 (0 is "none"; a positive value must be plausible for the unit
/// in the flag's name: [`plausible`]).
pub fn non_negative(v: f64, flag: &str) -> Result<f64> {
    if v.is_finite() && v == 0.0 {
        Ok(v)
    } else if v.is_finite() && v > 0.0 {
        plausible(v, flag)
    } else {
        bail!("`{flag}`: {v} must be a non-negative number")
    }
}

/// A step count that must be at least 1.
pub fn every(v: u64, flag: &str, what: &str) -> Result<u64> {
    if v == 0 {
        bail!("`{flag}`: 0 would never write a {what}; give a number of steps ≥ 1");
    }
    Ok(v)
}

/// Refuses a command whose α (from the contact line) the user gives on a scene with a site
/// file when `--line-deg` is not given: a site file has no lattice for the moiré estimate of
/// the line (the scene keeps the base preset's lattice, which the file replaced), so α would
/// be measured from a line of a lattice that is not there. `design` and `tolerance
/// --direction-deg` do not need this: they measure α from the substrate x axis and say so.
pub fn line_for(scene: &surrogate::Scene, line: Option<f64>) -> Result<()> {
    if line.is_none() {
        if let Some(why) = crate::study::corrugation::site_file_body(scene) {
            bail!(
                "`--line-deg`: {why}, which has no lattice for the moiré contact-line estimate that α is measured from; give --line-deg DEG (the contact-line direction from the substrate x axis; 0 measures α from the x axis)"
            );
        }
    }
    Ok(())
}

/// `--line-deg` (finite degrees from the substrate x axis) → rad.
pub fn line_deg(v: Option<f64>) -> Result<Option<f64>> {
    match v {
        Some(l) if !l.is_finite() => bail!("`--line-deg`: {l} is not a finite angle"),
        l => Ok(l.map(deg_to_rad)),
    }
}

/// `--distance-um` and `--step-um` → (m, m).
pub fn path(distance_um: f64, step_um: f64) -> Result<(f64, f64)> {
    if !(distance_um.is_finite() && distance_um > 0.0) {
        bail!("`--distance-um`: {distance_um} must be a positive distance in µm");
    }
    if !(step_um.is_finite() && step_um > 0.0 && step_um <= distance_um) {
        bail!("`--step-um`: {step_um} must be positive and at most --distance-um");
    }
    Ok((um_to_m(distance_um), um_to_m(step_um)))
}

/// `--grid` (≥ 2: both cell edges are included).
pub fn grid(n: usize) -> Result<usize> {
    if n < 2 {
        bail!("`--grid`: {n} must be at least 2 (both cell edges are included)");
    }
    Ok(n)
}

/// The warning for a landscape grid of `n` points per side that under-samples the finest
/// feature of Δz of `scene` at its θ ([`surrogate::map::grid_need`]: the moiré of the two
/// lattices, its second harmonic at 4 points per period), naming the `--grid` it needs;
/// `None` when `n` resolves it. Cost: milliseconds (one structure-factor scan).
pub fn grid_warning(scene: &surrogate::Scene, n: usize) -> Option<String> {
    let need = surrogate::map::grid_need(scene);
    let [pa, pb] = need.periods?;
    (n < need.grid).then(|| {
        format!(
            "the {n}×{n} grid under-samples Δz: at θ = {}° the slider and substrate lattices make a moiré of wavelength {} µm, {pa} and {pb} periods along the repeat cell's edges, whose second harmonic needs `--grid {}` or more ({} points per period; docs/validation/maps.md); at {n} the map aliases (a checkerboard where there are stripes)",
            surrogate::units::significant(surrogate::units::rad_to_deg(scene.slider.theta), 6),
            surrogate::units::significant(surrogate::units::m_to_um(need.wavelength), 3),
            need.grid,
            surrogate::map::POINTS_PER_PERIOD
        )
    })
}

/// A time in µs that must be positive → s.
pub fn time_us(v: f64, flag: &str) -> Result<f64> {
    Ok(us_to_s(positive(v, flag)?))
}

/// A comma list of substrate seeds (`flag` names it in errors): whole numbers ≥ 0.
pub fn seed_list(text: &str, flag: &str) -> Result<Vec<u64>> {
    text.split(',')
        .map(|x| {
            x.trim().parse::<u64>().map_err(|_| {
                anyhow::anyhow!(
                    "`{flag}`: `{}` is not a non-negative integer seed",
                    x.trim()
                )
            })
        })
        .collect()
}
