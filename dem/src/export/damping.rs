//! The Rust engine's contact damping (γ_n, γ_t of [`crate::SimParams`]) expressed as LAMMPS
//! `pair_style granular` inputs (`damping tsuji`, tangential damping ratio `xgammat`).
//!
//! Rust: `F_n,d = −γ_n √(m_eff S_n) v_n` with `S_n = 2E*a`, and `F_t,d = −γ_t √(m_eff k_t) v_t`
//! with `k_t = 8G*a` ([`crate::model`]). LAMMPS `hertz/material … damping tsuji`:
//! `F_n,d = −α(e) √(m_eff k_n a) v_n` with `k_n = 4/3 E*`, where the pair coefficient is a
//! restitution `e` that LAMMPS turns into α by Tsuji's polynomial fit, and
//! `F_t,d = −xgammat · α √(m_eff k_n a) v_t`. Hence
//! `α = γ_n √(3/2)` and `xgammat = (γ_t/α) √(8G*/(4/3 E*)) = (γ_t/α) √(3(1−ν)/(2−ν))` for two
//! spheres of one material (`G* = E/(4(2−ν)(1+ν))`, `E* = E/(2(1−ν²))`).

use crate::DemError;

/// Tsuji et al. (1992) fit used by LAMMPS (`pair_granular.cpp`): damping coefficient α of a
/// restitution coefficient `e` (–). Decreasing on [0, 1], from 1.2728 at e = 0 to ≈ 3·10⁻⁴ at 1.
pub fn tsuji_alpha(e: f64) -> f64 {
    1.2728 - 4.2783 * e + 11.087 * e.powi(2) - 22.348 * e.powi(3) + 27.467 * e.powi(4)
        - 18.022 * e.powi(5)
        + 4.8218 * e.powi(6)
}

/// The restitution `e ∈ [0, 1]` with `tsuji_alpha(e) = alpha` (bisection to machine precision),
/// or `None` outside the fit's range `[tsuji_alpha(1), tsuji_alpha(0)]`.
pub fn tsuji_e_for_alpha(alpha: f64) -> Option<f64> {
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    if !(alpha.is_finite() && tsuji_alpha(hi) <= alpha && alpha <= tsuji_alpha(lo)) {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if tsuji_alpha(mid) > alpha {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// LAMMPS damping inputs of the pair style.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LammpsDamping {
    /// `damping tsuji` with restitution `e` (–) and tangential ratio `xgammat` (–).
    Tsuji {
        /// Restitution coefficient given to LAMMPS (it computes α(e) from it).
        e: f64,
        /// Tangential / normal damping ratio.
        xgammat: f64,
    },
    /// No contact damping (`damping viscoelastic` with coefficient 0, `xgammat` 0): γ_n = γ_t = 0.
    None,
}

/// Maps γ_n, γ_t and the Poisson ratio ν to LAMMPS inputs. Errors name `gamma_n`/`gamma_t`
/// when LAMMPS cannot express them: γ_n beyond Tsuji's range (α = γ_n√(3/2) must lie in
/// [3·10⁻⁴, 1.2728], i.e. 2.5·10⁻⁴ ≤ γ_n ≤ 1.039), or γ_t > 0 with γ_n = 0 (LAMMPS scales the
/// tangential damping by the normal one).
pub fn lammps_damping(gamma_n: f64, gamma_t: f64, nu: f64) -> Result<LammpsDamping, DemError> {
    lammps_damping_ratio(gamma_n, gamma_t, 3.0 * (1.0 - nu) / (2.0 - nu))
}

/// [`lammps_damping`] for a pair of two materials: `shear_ratio` = `8G*/(4/3 E*)` of the pair
/// (`3(1−ν)/(2−ν)` for one material), so `xgammat = (γ_t/α) √shear_ratio`.
pub fn lammps_damping_ratio(
    gamma_n: f64,
    gamma_t: f64,
    shear_ratio: f64,
) -> Result<LammpsDamping, DemError> {
    if !(gamma_t.is_finite() && gamma_t >= 0.0) {
        return Err(DemError::invalid(
            "gamma_t",
            gamma_t,
            "must be a non-negative number",
        ));
    }
    if gamma_n == 0.0 {
        if gamma_t > 0.0 {
            return Err(DemError::invalid(
                "gamma_t",
                gamma_t,
                "LAMMPS scales the tangential damping by the normal one: needs gamma_n > 0",
            ));
        }
        return Ok(LammpsDamping::None);
    }
    let alpha = gamma_n * 1.5f64.sqrt();
    let e = tsuji_e_for_alpha(alpha).ok_or_else(|| {
        DemError::invalid(
            "gamma_n",
            gamma_n,
            &format!(
                "outside the range LAMMPS `damping tsuji` can express ({:.3e} to {:.4})",
                tsuji_alpha(1.0) / 1.5f64.sqrt(),
                tsuji_alpha(0.0) / 1.5f64.sqrt()
            ),
        )
    })?;
    // the α LAMMPS will actually use (the bisection is exact to rounding)
    let alpha = tsuji_alpha(e);
    let xgammat = gamma_t / alpha * shear_ratio.sqrt();
    Ok(LammpsDamping::Tsuji { e, xgammat })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tsuji_fit_is_decreasing_and_inverted() {
        let mut prev = f64::INFINITY;
        for k in 0..=1000 {
            let a = tsuji_alpha(k as f64 / 1000.0);
            assert!(a < prev, "not decreasing at e = {}", k as f64 / 1000.0);
            prev = a;
        }
        for a in [0.001, 0.1, 0.5, 1.2] {
            let e = tsuji_e_for_alpha(a).unwrap();
            assert!((tsuji_alpha(e) - a).abs() < 1e-12, "{a}");
        }
        assert!(tsuji_e_for_alpha(1.3).is_none());
        assert!(tsuji_e_for_alpha(0.0).is_none());
    }

    #[test]
    fn rust_defaults_give_the_peer_scripts_values() {
        // The values the LAMMPS peer (dem/lammps/damping.py) used for γ_n = γ_t = 0.1, ν = 0.3:
        // the restitution 0.8417 these give in LAMMPS is in dem/lammps/reference.
        match lammps_damping(0.1, 0.1, 0.3).unwrap() {
            LammpsDamping::Tsuji { e, xgammat } => {
                assert!((e - 0.784_449_103_661_308_6).abs() < 1e-12, "{e}");
                assert!(
                    (xgammat - 0.907_485_212_973_030_1).abs() < 1e-9,
                    "{xgammat}"
                );
            }
            d => panic!("{d:?}"),
        }
        assert_eq!(lammps_damping(0.0, 0.0, 0.3).unwrap(), LammpsDamping::None);
        let e = lammps_damping(0.0, 0.1, 0.3).unwrap_err().to_string();
        assert!(e.contains("gamma_t"), "{e}");
        let e = lammps_damping(2.0, 0.1, 0.3).unwrap_err().to_string();
        assert!(e.contains("gamma_n"), "{e}");
    }
}
