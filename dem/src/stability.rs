//! Stable time-step estimate from the stiffnesses and masses of a model.
//!
//! Velocity-Verlet is stable for a harmonic mode of angular frequency ω when `dt < 2/ω`,
//! `ω = √(k/m)`. The estimate takes the largest ω over the model's stiff modes:
//! - slider sphere against the control layer in z (full model only):
//!   `ω² = k_z (1/m_c + 1/m_s)` (in-phase mode of all springs; m_c = control sphere mass),
//! - slider sphere laterally: `(k_xy + S_n + k_t)/m_s`,
//! - substrate sphere laterally: `(k_tether + S_n + k_t)/m_b` (m_b: a substrate sphere's mass,
//!   m_s a slider sphere's; they differ when the two bodies have different sphere sizes),
//! - a contact pair: `(S_n + k_t)(1/m_s + 1/m_b)`,
//! - the slider as a whole on its contacts in z (rigid-z): `Σ S_n / (M + N m_s)`,
//! - with the implicit mount (full model, `implicit_mount`): the z springs, the layer's Z and
//!   tilts are integrated implicitly (unconditionally stable), so their two modes and the tilt
//!   mode leave the list; the lateral relative mode of the slider spheres against the light
//!   layer, `k_xy (1/m_c + 1/m_s)`, joins it (0.25× its limit never binds today: the contact
//!   pair is ~10 % below it at 4 GPa). On the study scene the contact pair then limits the step,
//!   1.9·10⁻³ µs instead of 6.7·10⁻⁵ µs,
//!
//! with contact stiffnesses `S_n = 2E*a`, `k_t = 8G*a` at the contact radius `a` of a contact
//! at pressure `p_ref` (Hertz: `a = π p0 R_eff / (2E*)`). Cost O(1).

use crate::model::reduced_mass;
use crate::SimParams;
use surrogate::contact::Hertz;

/// Estimated critical steps (s) and the dominating mode.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StableStep {
    /// `2/ω_max` (s).
    pub dt_crit: f64,
    /// Name of the mode with the largest ω.
    pub mode: &'static str,
}

/// Inputs of the estimate (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StabilityInput {
    /// Slider sphere mass m_s (kg).
    pub m_slider: f64,
    /// Substrate sphere mass m_b (kg).
    pub m_substrate: f64,
    /// Control-layer sphere mass (kg).
    pub m_control: f64,
    /// Number of slider spheres.
    pub n_slider: usize,
    /// Number of contacts expected (for the rigid-z body mode).
    pub n_contacts: usize,
    /// E* (Pa).
    pub e_star: f64,
    /// G* (Pa).
    pub g_star: f64,
    /// R_eff (m).
    pub r_eff: f64,
    /// Contact pressure at which the contact stiffness is evaluated (Pa).
    pub p_ref: f64,
    /// ω² (1/s²) of the control layer tilting on its mount springs (0 without springs).
    pub tilt_omega2: f64,
}

/// The stable-step estimate for `params` (reads `rigid_z` and the spring constants).
pub fn stable_step(inp: &StabilityInput, params: &SimParams) -> StableStep {
    let hertz = Hertz {
        e_star: inp.e_star,
        r_eff: inp.r_eff,
    };
    let a = hertz.contact_radius_for_p0(inp.p_ref);
    let sn = 2.0 * inp.e_star * a;
    let kt = 8.0 * inp.g_star * a;
    let (ms, mb) = (inp.m_slider, inp.m_substrate);
    let mut modes: Vec<(&'static str, f64)> = vec![
        (
            "slider sphere lateral",
            (params.mount.k_slider_xy + sn + kt) / ms,
        ),
        (
            "substrate sphere lateral",
            (params.mount.k_substrate_xy + sn + kt) / mb,
        ),
        // (1/m_s + 1/m_b) = 1/m_eff; for equal masses (sn + kt)/(m/2), bit for bit 2(sn + kt)/m
        ("contact pair", (sn + kt) / reduced_mass(ms, mb)),
    ];
    let m_body = inp.n_slider as f64 * (inp.m_control + ms);
    let implicit = params.mount.implicit_mount && !params.mount.rigid_z;
    if implicit {
        modes.push((
            "slider spheres vs control layer (lateral springs)",
            params.mount.k_slider_xy * (1.0 / inp.m_control + 1.0 / ms),
        ));
    } else if params.mount.rigid_z {
        modes.push((
            "slider body on its contacts (z)",
            inp.n_contacts as f64 * sn / m_body,
        ));
    } else {
        modes.push((
            "slider sphere vs control layer (z spring)",
            params.mount.k_slider_z * (1.0 / inp.m_control + 1.0 / ms),
        ));
        modes.push((
            "slider sphere on contact + z spring",
            (params.mount.k_slider_z + sn) / ms,
        ));
    }
    if inp.tilt_omega2 > 0.0 && !implicit {
        modes.push(("control-layer tilt on the mount springs", inp.tilt_omega2));
    }
    let (mode, w2) = modes
        .into_iter()
        .fold(("", 0.0), |a, b| if b.1 > a.1 { b } else { a });
    StableStep {
        dt_crit: 2.0 / w2.sqrt(),
        mode,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(m_slider: f64, m_substrate: f64) -> StabilityInput {
        StabilityInput {
            m_slider,
            m_substrate,
            m_control: 1e-14,
            n_slider: 100,
            n_contacts: 10,
            e_star: 55e9,
            g_star: 19e9,
            r_eff: 0.75e-6,
            p_ref: 4e9,
            tilt_omega2: 0.0,
        }
    }

    /// Two sphere sizes: the contact pair's mode takes 1/m_s + 1/m_b and the substrate's lateral
    /// mode the substrate's mass. With the implicit mount and one size the contact pair limits
    /// the step, at ω² = 2(S_n + k_t)/m; a substrate 10⁶ times heavier about halves ω² (the
    /// slider sphere's lateral mode, (k_xy + S_n + k_t)/m, then limits it); a lighter one
    /// limits it itself.
    #[test]
    fn each_body_has_its_own_mass() {
        let p = SimParams {
            mount: crate::MountParams {
                implicit_mount: true,
                ..Default::default()
            },
            ..SimParams::default()
        };
        let m = 3e-14;
        let w2 = |s: &StableStep| (2.0 / s.dt_crit).powi(2);
        let one = stable_step(&input(m, m), &p);
        assert_eq!(one.mode, "contact pair");
        let heavy = stable_step(&input(m, 1e6 * m), &p);
        assert_eq!(heavy.mode, "slider sphere lateral");
        let r = w2(&heavy) / w2(&one);
        assert!(r > 0.5 && r < 0.55, "{r}");
        let light = stable_step(&input(m, 0.1 * m), &p);
        assert!(light.mode.starts_with("substrate") || light.mode == "contact pair");
        assert!(w2(&light) > 5.0 * w2(&one));
    }
}
