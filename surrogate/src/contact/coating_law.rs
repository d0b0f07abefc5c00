//! The coating law μ(p0): the one friction law of the study's superlubric coating, used by the
//! surrogate (scene [`crate::Coating`], the friction estimate's path samples) and the DEM
//! (`dem::model::PressureSwitched`).

/// Whether a contact whose maximum Hertz pressure is `p0` (Pa) has broken through a coating of
/// strength `p_crit` (Pa): `p0 > P_crit` (a contact exactly at P_crit is intact). Cost: one
/// comparison.
#[inline]
pub fn coating_failed(p0: f64, p_crit: f64) -> bool {
    p0 > p_crit
}

/// Friction coefficient of a contact whose maximum Hertz pressure is `p0` (Pa), for a coating
/// of strength `p_crit` (Pa), switching between `mu1` (intact) and `mu2` (failed):
///
/// ```text
/// μ(p0) = μ1   if p0 ≤ P_crit
///         μ2   if p0 > P_crit
/// ```
///
/// Dimensionless (μ1, μ2 as given; study: 0.01 and 0.5 at P_crit = 4 GPa). Cost: one comparison.
#[inline]
pub fn coating_mu(p0: f64, p_crit: f64, mu1: f64, mu2: f64) -> f64 {
    if coating_failed(p0, p_crit) {
        mu2
    } else {
        mu1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn switches_strictly_above_p_crit() {
        assert_eq!(coating_mu(4e9, 4e9, 0.01, 0.5), 0.01);
        assert_eq!(coating_mu(4e9 * (1.0 + 1e-12), 4e9, 0.01, 0.5), 0.5);
        assert!(!coating_failed(4e9, 4e9));
        assert!(coating_failed(4.1e9, 4e9));
    }
}
