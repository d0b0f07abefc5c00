//! Corrugation maps of the quasi-static tier: the equilibrium-height landscape Δz(x, y) over the
//! substrate's repeat cell, the contact-line direction of a pattern pair, and the corrugation and
//! static-friction barrier felt along a pulling direction α.
//!
//! Data flow: [`crate::solver::Solver`] (one solve per lateral pose) → [`Landscape`] /
//! [`PathProfile`] → [`CorrugationPoint`]. Every numerical knob lives in [`MapParams`].
//! All quantities are SI (m, N, rad) inside this module.

mod cell;
mod contact_line;
mod corrugation;
mod landscape;
mod params;
mod resolution;

pub use cell::RepeatCell;
pub use contact_line::{contact_line_direction, ContactLine};
pub use corrugation::{
    check_alpha, check_path_stays_on_substrate, corrugation_direct, corrugation_from_landscape,
    path_profile, CorrugationPoint, PathProfile,
};
pub use landscape::{compute_landscape, Landscape};
pub use params::MapParams;
pub use resolution::{grid_need, GridNeed, COINCIDENCE, MAX_PERIODS, POINTS_PER_PERIOD};

use crate::error::SceneError;
use crate::scene::Scene;
use crate::units::m_to_um;

/// Checks that the slider disc (radius + one sphere radius), with its centre moved anywhere in the
/// rectangle spanned by `extent` (min/max shift `[[x_lo, y_lo], [x_hi, y_hi]]`, m) around the
/// scene's offset, stays over the substrate rectangle. Otherwise a map would mix in edge effects
/// (a landscape would not be periodic). `field` names the user option blamed in the error.
pub fn check_slider_stays_on_substrate(
    scene: &Scene,
    extent: [[f64; 2]; 2],
    field: &str,
) -> Result<(), SceneError> {
    let r = scene.slider.radius + scene.max_slider_sphere_radius();
    let [lx, ly] = scene.substrate.size;
    let o = scene.slider.offset;
    let x_lo = o[0] + extent[0][0] - r;
    let x_hi = o[0] + extent[1][0] + r;
    let y_lo = o[1] + extent[0][1] - r;
    let y_hi = o[1] + extent[1][1] + r;
    if x_lo < -0.5 * lx || x_hi > 0.5 * lx || y_lo < -0.5 * ly || y_hi > 0.5 * ly {
        let um = m_to_um;
        // lengths as given (to 0.1 nm), not with the binary rounding of the µm → m conversion
        let given = |v: f64| (um(v) * 1e4).round() / 1e4;
        let remedy = if field.ends_with("transverse_um") {
            "a narrower search across the pull"
        } else {
            "a shorter path"
        };
        return Err(SceneError::invalid(
            field,
            format!(
                "slider x {:.2}..{:.2} µm, y {:.2}..{:.2} µm",
                um(x_lo),
                um(x_hi),
                um(y_lo),
                um(y_hi)
            ),
            &format!(
                "the slider (radius {} µm) leaves the {}x{} µm substrate; use a smaller slider, a larger substrate or {remedy}",
                given(scene.slider.radius),
                given(lx),
                given(ly)
            ),
        ));
    }
    Ok(())
}
