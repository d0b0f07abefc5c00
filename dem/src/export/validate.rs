//! The checks of [`super::export_lammps`]'s inputs before any work, each naming its field in
//! user units, and the contact damping as LAMMPS expresses it.

use super::damping::{self, LammpsDamping};
use super::ExportOptions;
use crate::{DemError, SimParams};
use surrogate::Scene;

fn check_nonneg(v: f64, field: &str, unit_scale: f64) -> Result<(), DemError> {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        Err(DemError::invalid(
            field,
            v * unit_scale,
            "must be a non-negative number",
        ))
    }
}

/// Refuses what cannot be exported (rigid-z, a negative μ, times, speed, sample interval, tie
/// length, a bond split with k_z < k_xy), naming the field; returns the contact damping of
/// `params.contact` in LAMMPS terms for the scene's materials. Cost: O(1).
pub(super) fn validate(
    scene: &Scene,
    params: &SimParams,
    opts: &ExportOptions,
) -> Result<LammpsDamping, DemError> {
    scene.validate()?;
    if params.mount.rigid_z {
        return Err(DemError::invalid(
            "rigid_z",
            true,
            "the rigid-z reduction has no LAMMPS equivalent; export the full model",
        ));
    }
    if !(opts.mu.is_finite() && opts.mu >= 0.0) {
        return Err(DemError::invalid(
            "mu",
            opts.mu,
            "must be a non-negative number",
        ));
    }
    check_nonneg(opts.dump_interval, "dump_us", 1e6)?;
    if !(opts.tie_length.is_finite() && opts.tie_length > 0.0) {
        return Err(DemError::invalid(
            "tie_length_um",
            opts.tie_length * 1e6,
            "must be positive",
        ));
    }
    for (v, f) in [
        (params.protocol.equilibrate_time, "equilibrate_us"),
        (params.protocol.relax_time, "relax_us"),
        (params.protocol.slide_time, "slide_us"),
        (params.protocol.support_speed, "speed_m_s"),
    ] {
        let scale = if f == "speed_m_s" { 1.0 } else { 1e6 };
        check_nonneg(v, f, scale)?;
    }
    if !(params.protocol.sample_interval.is_finite() && params.protocol.sample_interval > 0.0) {
        return Err(DemError::invalid(
            "sample_us",
            params.protocol.sample_interval * 1e6,
            "must be positive",
        ));
    }
    if !(params.mount.k_slider_z >= params.mount.k_slider_xy && params.mount.k_slider_xy >= 0.0) {
        return Err(DemError::invalid(
            "k_slider_z",
            params.mount.k_slider_z,
            "the bond split needs k_slider_z ≥ k_slider_xy ≥ 0 (N/m)",
        ));
    }
    let (m_sl, m_sb) = (scene.slider_material(), scene.substrate_material());
    let damping = if m_sl == m_sb {
        damping::lammps_damping(params.contact.gamma_n, params.contact.gamma_t, m_sl.poisson)?
    } else {
        let ratio = 6.0 * m_sl.g_star_with(&m_sb) / m_sl.e_star_with(&m_sb);
        damping::lammps_damping_ratio(params.contact.gamma_n, params.contact.gamma_t, ratio)?
    };
    Ok(damping)
}
