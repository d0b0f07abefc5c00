//! [`TiltResonance`]: how close the spring mount's tilt mode is to the lateral mode of the
//! stuck contact pairs, where the DEM's friction on failed-coating contacts drops below μ_est.
//!
//! ## Math
//! The control layer on the anti-tilt springs ([`crate::scene::Mount::Springs`]) tilts about the
//! slider's own axes x', y' with stiffness `K_t = [K1·d_y², K1·d_x²]`
//! ([`crate::scene::Mount::principal_tilt_stiffness`]) and inertia
//! `I = (m_s + m_c)·[Σ y'², Σ x'²]` (every slider sphere follows its control sphere in z: on its
//! 10⁶ N/m tie it vibrates at 5.7·10⁹ rad/s, about 35× faster than this mode), so
//!
//! ```text
//! ω_t = √(K_t / I)   (per axis; reported as the r.m.s. of the two)
//! ω_p = √((k_xy + k_tether) / (2 m_s))
//! ```
//!
//! `ω_p` is the in-phase lateral mode of a slider sphere stuck to a substrate sphere (a failed
//! contact, μ2 = 0.5): the pair moves as one mass 2·m_s on its two ties.
//! Where `r = ω_t/ω_p` lies in [`RESONANCE_BAND`] and contacts fail, the DEM's tilt rocks the
//! failed contacts in step with their lateral vibration, their pressure crosses P_crit back and
//! forth (with a constant μ there is no such drop), they unload during slips, and the mean friction
//! falls up to 2.8× below μ_est (2.1–2.8× at r = 0.69–0.89; P_max spikes higher); the 1-D estimate
//! has no tilt dynamics and stays at the off-resonance value, within 0.96–1.46 of the DEM there.
//! Measured on tri-tri 30°, α = 0°, 2.45 mN (`docs/validation/friction.md`, "The mount's resonance"): K1
//! swept 10⁴–10⁸ N/m and the ties k_xy, k_tether halved and doubled; the drop tracks r, not K1 or
//! the ties alone. The study's mount sits at r = 0.89 (K1 = 10⁶ N/m, 3 µm spheres, ties of
//! 10³ N/m).
//!
//! ## Roughness detunes it
//! Random substrate heights take the drop away: on tri-tri 30°, α = 0° (study mount against
//! K1 = 10⁷ N/m, reduced model, `docs/validation/friction.md`, "Roughness detunes the resonance") the
//! DEM's friction at the study's K1 is 0.36–0.62 of the off-resonance value on the flat
//! substrate (2.45–3.86 mN), 0.38–0.68 at σ_h = 1–3 nm, and 0.85–0.92 at σ_h = 5–10 nm,
//! where μ_est/μ_DEM is 1.06–1.41 (2 seeds, 3 loads, the runs that did not lock in). So the
//! estimate does not flag a scene whose `σ_h ≥ max(`[`DETUNING_SIGMA_H`]`, δ_crit/2)`
//! ([`roughness_detunes`]), with `δ_crit = (π P_crit/(2E*))² R_eff` the Hertz overlap of two
//! equal spheres at `p0 = P_crit` (9.8 nm on the study's scene, so there the two bounds
//! coincide). Only the absolute bound was measured (E = 100 GPa, P_crit = 4 GPa); the δ_crit/2
//! bound keeps the flag on where a softer coating or a higher P_crit would need more roughness
//! if the detuning scales with the contact's overlap (not measured: the test at P_crit = 5 GPa,
//! 8 mN stuck or locked in).
//!
//! A flag means μ_est may be an upper bound, not that it is: the two rough-substrate runs of the
//! 17-run comparison (σ_h = 0.01 µm), flagged before this rule, showed no drop (μ_est/μ_DEM 1.04,
//! 0.95). Cost O(N).

use super::FrictionParams;
use crate::scene::{Mount, Scene};

/// Measured band of `r = ω_t/ω_p` in which the DEM's friction on failed-coating contacts drops
/// below μ_est: in all 10 runs at r = 0.69–0.89, part way at r = 0.63 (μ_est/μ_DEM 1.54) and in
/// 2 of 4 runs at r = 1.03, not at r ≤ 0.56 (6 runs) or r ≥ 1.26 (5 runs); the edges lie
/// between those (`docs/validation/friction.md`, "The mount's resonance").
pub const RESONANCE_BAND: [f64; 2] = [0.6, 1.15];

/// Substrate roughness σ_h (m) from which the resonance's drop was measured to fade: at
/// σ_h = 5 nm the DEM's friction on the study mount is 0.85 of the off-resonance value,
/// against 0.36–0.62 on the flat substrate ([`roughness_detunes`], `docs/validation/friction.md`,
/// "Roughness detunes the resonance").
pub const DETUNING_SIGMA_H: f64 = 5e-9;

/// Largest measured ratio μ_est/μ_DEM on failed-coating rows of a mount in the band on a flat
/// substrate: the DEM's friction 2.1–2.8× below μ_est on tri-tri 30° at 2.45–3.86 mN (the 3
/// such runs of the 17-run DEM comparison; `docs/validation/friction.md`, "The mount's
/// resonance"). User-facing warnings quote this constant.
pub const RESONANCE_DROP_MAX: f64 = 2.8;

/// Fraction of the critical overlap δ_crit ([`critical_overlap`]) that σ_h must also reach for
/// roughness to detune the resonance ([`roughness_detunes`]): not measured, it keeps the flag on
/// where a softer coating or a higher P_crit would need more roughness if the detuning scales
/// with the contact's overlap (module doc, "Roughness detunes it"). On the study's scene
/// δ_crit/2 = 4.9 nm ≈ [`DETUNING_SIGMA_H`].
pub const DETUNING_OVERLAP_FRACTION: f64 = 0.5;

/// Overlap δ_crit (m) of a slider–substrate sphere pair of `scene` whose Hertz pressure p0 is P_crit
/// ([`crate::contact::Hertz::overlap_for_p0`]: `a = π P_crit R_eff / (2E*)`, `δ_crit = a² / R_eff`; 9.8 nm on the
/// study's scene). O(1).
pub fn critical_overlap(scene: &Scene) -> f64 {
    scene.hertz().overlap_for_p0(scene.coating.p_crit)
}

/// Whether `scene`'s substrate is rough enough to detune the mount's resonance:
/// `σ_h ≥ max(`[`DETUNING_SIGMA_H`]`, `[`DETUNING_OVERLAP_FRACTION`]` · δ_crit)` (δ_crit/2) with
/// δ_crit of [`critical_overlap`]. O(1).
pub fn roughness_detunes(scene: &Scene) -> bool {
    scene.substrate.sigma_h
        >= DETUNING_SIGMA_H.max(DETUNING_OVERLAP_FRACTION * critical_overlap(scene))
}

/// The spring mount's tilt frequency against the stuck pairs' lateral frequency (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TiltResonance {
    /// r.m.s. of the two principal tilt angular frequencies ω_t (rad/s).
    pub tilt_omega: f64,
    /// In-phase lateral angular frequency ω_p (rad/s) of a stuck slider–substrate pair.
    pub pair_omega: f64,
    /// `ω_t / ω_p`.
    pub ratio: f64,
    /// Whether the scene's substrate roughness detunes the resonance ([`roughness_detunes`]).
    pub detuned: bool,
}

impl TiltResonance {
    /// The ratio of `scene`'s mount with the ties of `params`; `None` unless the mount is
    /// `springs` with K1 > 0.
    pub fn of(scene: &Scene, params: &FrictionParams) -> Option<TiltResonance> {
        Self::with_ties(
            scene,
            params.k_slider_xy,
            params.k_substrate_xy,
            params.control_sphere_radius,
        )
    }

    /// The ratio of `scene`'s mount with slider ties `k_xy` and substrate tethers `k_tether`
    /// (N/m) and control spheres of radius `r_control` (m), as a DEM run has them; `None` unless
    /// the mount is `springs` with K1 > 0.
    pub fn with_ties(
        scene: &Scene,
        k_xy: f64,
        k_tether: f64,
        r_control: f64,
    ) -> Option<TiltResonance> {
        if !matches!(scene.slider.mount, Mount::Springs { k1 } if k1 > 0.0) {
            return None;
        }
        let local = scene.slider_sites_local();
        let k = scene.slider.mount.principal_tilt_stiffness(&local);
        let n = local.len() as f64;
        let c = local
            .iter()
            .fold([0.0, 0.0], |a, p| [a[0] + p[0] / n, a[1] + p[1] / n]);
        let (mut sxx, mut syy) = (0.0, 0.0);
        for p in &local {
            sxx += (p[0] - c[0]).powi(2);
            syy += (p[1] - c[1]).powi(2);
        }
        // the mean slider sphere mass (per-site sizes: Σ m_i / N)
        let m_s = match scene.slider_radii() {
            Some(_) => scene.slider_spheres_mass() / n,
            None => scene
                .slider_material()
                .sphere_mass(scene.slider_sphere_radius()),
        };
        let unit = m_s + scene.slider_material().sphere_mass(r_control);
        let w2 = [k[0] / (unit * syy), k[1] / (unit * sxx)];
        let tilt_omega = (0.5 * (w2[0] + w2[1])).sqrt();
        let pair_omega = ((k_xy + k_tether) / (2.0 * m_s)).sqrt();
        let ratio = tilt_omega / pair_omega;
        ratio.is_finite().then_some(TiltResonance {
            tilt_omega,
            pair_omega,
            ratio,
            detuned: roughness_detunes(scene),
        })
    }

    /// Whether `ratio` lies in [`RESONANCE_BAND`].
    pub fn in_band(&self) -> bool {
        (RESONANCE_BAND[0]..=RESONANCE_BAND[1]).contains(&self.ratio)
    }

    /// Whether the drop is expected where contacts fail: the ratio [in the band](Self::in_band)
    /// and the substrate not rough enough to detune it ([`roughness_detunes`]).
    pub fn expected(&self) -> bool {
        self.in_band() && !self.detuned
    }
}

impl std::fmt::Display for TiltResonance {
    /// The ratio against the band, the common head of the warnings that cite it: "the springs
    /// mount's tilt mode is at 0.89 of a stuck contact pair's lateral frequency (resonance band
    /// 0.6–1.15)".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "the springs mount's tilt mode is at {:.2} of a stuck contact pair's lateral \
             frequency (resonance band {}–{})",
            self.ratio, RESONANCE_BAND[0], RESONANCE_BAND[1]
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::Hertz;
    use crate::scene::{Scene, STUDY_K1};

    #[test]
    fn study_mount_sits_in_the_band_and_a_stiffer_one_does_not() {
        let mut scene = Scene::preset("tri-tri").unwrap();
        let p = FrictionParams::default();
        let r = TiltResonance::of(&scene, &p).unwrap();
        // Closed form for a uniform disc of N sites, radius R: d = 8R/(3π), Σy² = N R²/4,
        // so ω_t² = K1 (8/(3π))² · 4 / (N (m_s + m_c)).
        let n = scene.slider_sites_local().len() as f64;
        let m = scene.material.sphere_mass(scene.sphere_radius)
            + scene.material.sphere_mass(p.control_sphere_radius);
        let disc = (STUDY_K1 * (8.0 / (3.0 * std::f64::consts::PI)).powi(2) * 4.0 / (n * m)).sqrt();
        assert!(
            (r.tilt_omega / disc - 1.0).abs() < 0.02,
            "{} vs {disc}",
            r.tilt_omega
        );
        assert!(r.in_band(), "study ratio {}", r.ratio);
        // ω_t ∝ √K1: 4× K1 doubles the ratio, out of the band.
        scene.slider.mount = Mount::Springs { k1: 4.0 * STUDY_K1 };
        let r4 = TiltResonance::of(&scene, &p).unwrap();
        assert!((r4.ratio / r.ratio - 2.0).abs() < 1e-12);
        assert!(!r4.in_band());
        scene.slider.mount = Mount::Free;
        assert!(TiltResonance::of(&scene, &p).is_none());
    }

    /// δ_crit is the Hertz overlap at p0 = P_crit (9.8 nm on the study's scene); the drop is
    /// expected on the study mount up to σ_h < 5 nm, not from 5 nm on, and a softer coating
    /// (E = 50 GPa: δ_crit four times larger) keeps it expected at σ_h = 10 nm.
    #[test]
    fn roughness_of_half_the_critical_overlap_detunes_the_resonance() {
        let mut scene = Scene::preset("tri-tri").unwrap();
        let p = FrictionParams::default();
        let d = critical_overlap(&scene);
        let h = Hertz::equal_spheres(scene.sphere_radius, &scene.material);
        assert!((h.p0(d) / scene.coating.p_crit - 1.0).abs() < 1e-12);
        assert!((d - 9.8e-9).abs() < 0.1e-9, "{d}");
        let at = |scene: &mut Scene, sigma: f64| {
            scene.substrate.sigma_h = sigma;
            TiltResonance::of(scene, &p).unwrap()
        };
        let flat = at(&mut scene, 0.0);
        assert!(flat.in_band() && !flat.detuned && flat.expected());
        let slight = at(&mut scene, 3e-9);
        assert!(slight.expected());
        let rough = at(&mut scene, DETUNING_SIGMA_H);
        assert!(rough.in_band() && rough.detuned && !rough.expected());
        assert_eq!(rough.ratio, flat.ratio);
        scene.material.youngs = 50e9;
        assert!((critical_overlap(&scene) / d - 4.0).abs() < 1e-9);
        assert!(at(&mut scene, 10e-9).expected());
        let half = 0.5 * critical_overlap(&scene);
        assert!(!at(&mut scene, half).expected());
    }
}
