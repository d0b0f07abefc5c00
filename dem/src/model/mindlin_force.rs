//! [`MindlinForce`]: Mindlin tangential spring whose history is the elastic tangential *force*
//! (incremental stiffness), so a change of the contact radius changes only the increments.
//!
//! Same conventions as [`super::Mindlin`] (history rotated into the current tangent plane with
//! its magnitude kept, viscous damping on top, Coulomb cap with the history reset to the elastic
//! part of the capped force); the history differs: `f_el += −k_t(a)·v_t·dt` instead of
//! `ξ += v_t·dt` with `F = −k_t(a)·ξ` (LAMMPS `tangential mindlin_force`; Thornton et al. 2013).
//! Under a constant contact radius both give the same force; when the load and hence `a` change
//! while a contact sticks, [`super::Mindlin`]'s force jumps by `a_new/a_old`, this one's does not.

use super::mindlin::rotate_history;
use super::{Mindlin, TangentialModel};

/// Incremental Mindlin spring: `k_t = 8 G* a`, history = elastic force (N), damping
/// `γ_t √(m_eff k_t) v_t`, total capped at `μ F_n`. O(1) per contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MindlinForce {
    /// Stiffness law and damping (the same parameters as the displacement form).
    pub spring: Mindlin,
}

#[inline]
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl TangentialModel for MindlinForce {
    /// `xi` holds the elastic tangential force (N) here, not a displacement.
    #[inline]
    fn force(
        &self,
        xi: &mut [f64; 3],
        n: [f64; 3],
        v_t: [f64; 3],
        a: f64,
        cap: f64,
        m_eff: f64,
        dt: f64,
    ) -> [f64; 3] {
        rotate_history(xi, n);
        let kt = self.stiffness(a);
        for k in 0..3 {
            xi[k] -= kt * v_t[k] * dt;
        }
        let eta = self.spring.gamma_t * (m_eff * kt).sqrt();
        let mut f = [0.0; 3];
        for k in 0..3 {
            f[k] = xi[k] - eta * v_t[k];
        }
        let f2 = dot(f, f);
        if f2 > cap * cap {
            let fm = f2.sqrt();
            let s = if fm > 0.0 { cap / fm } else { 0.0 };
            for k in 0..3 {
                f[k] *= s;
                xi[k] = f[k] + eta * v_t[k];
            }
        }
        f
    }
    #[inline]
    fn stiffness(&self, a: f64) -> f64 {
        self.spring.stiffness(a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const N: [f64; 3] = [0.0, 0.0, 1.0];

    fn models() -> (Mindlin, MindlinForce) {
        let m = Mindlin::equal_spheres(100e9, 0.3, 0.5);
        (m, MindlinForce { spring: m })
    }

    #[test]
    fn equals_the_displacement_form_at_constant_radius() {
        let (disp, force) = models();
        let (mut xi, mut fe) = ([0.0; 3], [0.0; 3]);
        let (a, m_eff, dt, cap) = (80e-9, 1.5e-14, 1e-10, 1e-4);
        let mut worst: f64 = 0.0;
        for s in 0..400 {
            let t = s as f64 * dt;
            let v = [0.3 * (t * 3e8).sin(), 0.1 * (t * 1e8).cos(), 0.0];
            let f1 = disp.force(&mut xi, N, v, a, cap, m_eff, dt);
            let f2 = force.force(&mut fe, N, v, a, cap, m_eff, dt);
            let scale = dot(f1, f1).sqrt().max(1e-12);
            for k in 0..3 {
                worst = worst.max((f1[k] - f2[k]).abs() / scale);
            }
        }
        assert!(worst < 1e-9, "relative difference {worst}");
    }

    #[test]
    fn stuck_force_does_not_jump_when_the_radius_changes() {
        let (disp, force) = models();
        let (mut xi, mut fe) = ([0.0; 3], [0.0; 3]);
        let (m_eff, dt, cap) = (1.5e-14, 1e-10, 1.0);
        let v = [0.05, 0.0, 0.0];
        let f1 = disp.force(&mut xi, N, v, 80e-9, cap, m_eff, dt);
        let f2 = force.force(&mut fe, N, v, 80e-9, cap, m_eff, dt);
        // Unload to half the radius with the contact at rest: the displacement form's force
        // halves, the force form keeps its force.
        let g1 = disp.force(&mut xi, N, [0.0; 3], 40e-9, cap, m_eff, dt);
        let g2 = force.force(&mut fe, N, [0.0; 3], 40e-9, cap, m_eff, dt);
        let el1 = -disp.stiffness(80e-9) * v[0] * dt;
        assert!((g1[0] / el1 - 0.5).abs() < 1e-12, "{} vs {el1}", g1[0]);
        assert!((g2[0] / el1 - 1.0).abs() < 1e-12, "{} vs {el1}", g2[0]);
        assert!(f1[0] < 0.0 && f2[0] < 0.0);
    }

    #[test]
    fn slip_caps_the_force_and_keeps_the_elastic_part() {
        let (_, force) = models();
        let mut fe = [0.0; 3];
        let (a, m_eff, dt, cap) = (80e-9, 1.5e-14, 1e-10, 1e-7);
        let v = [1.0, 0.5, 0.0];
        let mut f = [0.0; 3];
        for _ in 0..50 {
            f = force.force(&mut fe, N, v, a, cap, m_eff, dt);
        }
        let fm = dot(f, f).sqrt();
        assert!((fm / cap - 1.0).abs() < 1e-12, "|F| = {fm}");
        let eta = force.spring.gamma_t * (m_eff * force.stiffness(a)).sqrt();
        for k in 0..3 {
            assert!((fe[k] - (f[k] + eta * v[k])).abs() <= 1e-12 * cap);
        }
    }
}
