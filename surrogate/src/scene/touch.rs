//! When two spheres touch rather than overlap ([`TOUCH_TOL`], [`overlaps`]), and the 1e-9 µm
//! grid that site coordinates are snapped to ([`snap_um`]): shared by the lattices
//! (`pattern.rs`) and the site files (`sites.rs`).

/// `x` (µm) on the 1e-9 µm grid: `round(x·10⁹)/10⁹`, the double nearest to its 9-decimal text.
pub(super) fn snap_um(x: f64) -> f64 {
    (x * 1e9).round() / 1e9
}

/// Relative tolerance of every sphere-overlap check (lattices, bases, site files, families):
/// spheres whose centres are at least `d · (1 − 1e-6)` apart (d the contact distance, the sum
/// of the radii) count as touching, not overlapping, so that coordinates typed to 6 decimals in
/// µm (a honeycomb basis `[2.598076, 1.5]` at 5.196152 µm, 0.18 pm short of 3 µm) are
/// accepted. A real overlap (more than 3 pm for 3 µm spheres) is refused.
pub const TOUCH_TOL: f64 = 1e-6;

/// Whether spheres at centre distance `dist` overlap for the contact distance `d` (m), beyond
/// the [`TOUCH_TOL`] allowance.
pub fn overlaps(dist: f64, d: f64) -> bool {
    dist < d * (1.0 - TOUCH_TOL)
}
