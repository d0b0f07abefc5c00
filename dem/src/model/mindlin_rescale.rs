//! [`MindlinRescale`]: the Mindlin displacement history scaled down with the contact radius on
//! unloading (LAMMPS `tangential mindlin_rescale`), so a stuck contact that unloads sheds its
//! tangential force as `k_t·ξ ∝ a²` instead of keeping its old displacement.
//!
//! LAMMPS stores the previous contact radius in the pair history. Here it is reconstructed from
//! the pair's previous separation `d − v·dt` (exact where positions advance by `v·dt`, as in the
//! velocity-Verlet drift), so the history and the checkpoint format are unchanged.

use super::{Mindlin, TangentialModel};

/// Mindlin spring whose history ξ is scaled by `a/a_prev` when the contact radius falls
/// (`a < a_prev`) before the usual Mindlin update. O(1) per contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MindlinRescale {
    /// Stiffness law and damping (the same parameters as the displacement form).
    pub spring: Mindlin,
}

impl MindlinRescale {
    /// The tangential force (N) as [`Mindlin`]'s, with the history first rescaled on unloading
    /// from the previous contact radius `a_prev` (m) to the current `a` (m).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn force(
        &self,
        xi: &mut [f64; 3],
        n: [f64; 3],
        v_t: [f64; 3],
        a: f64,
        a_prev: f64,
        cap: f64,
        m_eff: f64,
        dt: f64,
    ) -> [f64; 3] {
        if a < a_prev && a_prev > 0.0 {
            let s = a / a_prev;
            for v in xi.iter_mut() {
                *v *= s;
            }
        }
        self.spring.force(xi, n, v_t, a, cap, m_eff, dt)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unloading at rest: the stored displacement, hence the force ∝ a·ξ, falls as a²; loading
    /// leaves it as Mindlin's.
    #[test]
    fn unloading_scales_the_history_with_the_radius() {
        let m = Mindlin {
            g_star: 20e9,
            gamma_t: 0.0,
        };
        let r = MindlinRescale { spring: m };
        let n = [0.0, 0.0, 1.0];
        let (m_eff, dt, cap) = (1e-14, 1e-12, 1.0);
        let xi0 = [1e-9, 0.0, 0.0];
        // unloading to half the radius, no sliding
        let mut xi = xi0;
        let f = r.force(&mut xi, n, [0.0; 3], 50e-9, 100e-9, cap, m_eff, dt);
        let mut xm = xi0;
        let fm = m.force(&mut xm, n, [0.0; 3], 50e-9, cap, m_eff, dt);
        assert!((xi[0] - 0.5e-9).abs() < 1e-21, "{xi:?}");
        assert!(
            (f[0] - 0.5 * fm[0]).abs() < 1e-12 * fm[0].abs(),
            "{f:?} {fm:?}"
        );
        // loading: unchanged
        let mut xi = xi0;
        let f = r.force(&mut xi, n, [0.0; 3], 100e-9, 50e-9, cap, m_eff, dt);
        let mut xm = xi0;
        let fm = m.force(&mut xm, n, [0.0; 3], 100e-9, cap, m_eff, dt);
        assert_eq!(f, fm);
        assert_eq!(xi, xm);
    }
}
