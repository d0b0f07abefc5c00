//! [`StepMap`]: the exact step map of a free sphere's deviation from its rest state.
//!
//! A sphere out of contact deviates from its rest state (substrate: its site; slider: the
//! common mode of the free slider spheres) by δ, and δ obeys `m δ̈ = −k δ − m δ̇/τ` whatever the
//! control layer does. The engine's velocity-Verlet step maps the deviation at an evaluation
//! point (position at step n, velocity at n − ½) linearly to the next one:
//! `δv' = δv + dt(−ω²δ − δv/τ)`, `δ' = δ + dt·δv'`, ω² = k/m. Every free sphere with the
//! same ω shares this 2×2 matrix, so a ringing sphere need not be integrated step by step: its
//! deviation is advanced by a matrix power at each evaluation, and the control layer feels the
//! sum of all deviations, integrated as one mode.

/// The homogeneous linear step map of (δ, δv).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct StepMap {
    a: [[f64; 2]; 2],
}

impl StepMap {
    /// One step of `dt` (s) for ω² (1/s²) and damping rate `inv_tau` (1/s).
    pub fn new(omega2: f64, inv_tau: f64, dt: f64) -> StepMap {
        let c = 1.0 - dt * inv_tau;
        StepMap {
            a: [[1.0 - dt * dt * omega2, dt * c], [-dt * omega2, c]],
        }
    }

    /// One step of the implicit mount (`integrator::mount`) for a free z deviation:
    /// `D(h)·C(dt)·D(h)`, D the exact damping `δv ← e^{−h/τ} δv`, C the trapezoidal map
    /// `ū = (2δv − dt ω² δ)/(2 + dt²ω²/2)`, `δ ← δ + dt ū`, `δv ← 2ū − δv`. C keeps
    /// `ω²δ² + δv²`, D only lowers it.
    pub fn implicit(omega2: f64, inv_tau: f64, dt: f64) -> StepMap {
        let e = (-0.5 * dt * inv_tau).exp();
        let a = 2.0 + 0.5 * dt * dt * omega2;
        let c = [
            [1.0 - dt * dt * omega2 / a, 2.0 * dt / a],
            [-2.0 * dt * omega2 / a, 4.0 / a - 1.0],
        ];
        let d = StepMap {
            a: [[1.0, 0.0], [0.0, e]],
        };
        d.mul(&StepMap { a: c }).mul(&d)
    }

    fn mul(&self, o: &StepMap) -> StepMap {
        let (a, b) = (&self.a, &o.a);
        StepMap {
            a: [
                [
                    a[0][0] * b[0][0] + a[0][1] * b[1][0],
                    a[0][0] * b[0][1] + a[0][1] * b[1][1],
                ],
                [
                    a[1][0] * b[0][0] + a[1][1] * b[1][0],
                    a[1][0] * b[0][1] + a[1][1] * b[1][1],
                ],
            ],
        }
    }

    /// The map of `n` steps (repeated squaring, O(log n)).
    pub fn pow(&self, mut n: u64) -> StepMap {
        let mut r = StepMap {
            a: [[1.0, 0.0], [0.0, 1.0]],
        };
        let mut b = *self;
        while n > 0 {
            if n & 1 == 1 {
                r = r.mul(&b);
            }
            b = b.mul(&b);
            n >>= 1;
        }
        r
    }

    /// Applies the map to (δ, δv).
    #[inline]
    pub fn apply(&self, x: f64, v: f64) -> (f64, f64) {
        (
            self.a[0][0] * x + self.a[0][1] * v,
            self.a[1][0] * x + self.a[1][1] * v,
        )
    }
}

/// Amplitude `√(δ² + δv²/ω²)` (m) of a deviation (|δ| when ω = 0).
#[inline]
pub(crate) fn amplitude(x: f64, v: f64, omega2: f64) -> f64 {
    if omega2 > 0.0 {
        (x * x + v * v / omega2).sqrt()
    } else {
        x.abs()
    }
}

/// [`bound_factor`] of the implicit map ([`StepMap::implicit`]): it never raises the
/// amplitude, so 1, with the same 10 % margin.
pub(crate) const IMPLICIT_BOUND_FACTOR: f64 = 1.1;

/// Factor F such that every later |δ| of a free deviation is at most F × its [`amplitude`] now.
/// Undamped, the step map keeps `I = ω²δ² + δv² − dt ω² δ δv` (δv at the half step), an
/// ellipse whose largest |δ| is `√(I/(ω²(1 − (ωdt/2)²)))`, and `I ≤ (1 + ωdt/2)(ω²δ² + δv²)`,
/// so `F = 1/√(1 − ωdt/2)`; damping only shrinks the orbit; 10 % margin. Infinite where the step
/// is unstable (ωdt ≥ 2) or there is no spring.
pub(crate) fn bound_factor(omega2: f64, dt: f64) -> f64 {
    let h = 0.5 * dt * omega2.sqrt();
    if omega2 > 0.0 && h < 0.99 {
        1.1 / (1.0 - h).sqrt()
    } else {
        f64::INFINITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The matrix power equals stepping, and the bound holds along every orbit tried.
    #[test]
    fn power_equals_stepping_and_the_bound_holds() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for wdt in [0.01, 0.085, 0.3, 0.5, 1.0, 1.6] {
            for q in [f64::INFINITY, 100.0, 3.0] {
                let (dt, w2) = (1e-10, (wdt / 1e-10f64).powi(2));
                let it = if q.is_finite() { w2.sqrt() / q } else { 0.0 };
                let m = StepMap::new(w2, it, dt);
                for _ in 0..20 {
                    let (x0, v0) = (rnd() * 1e-10, rnd() * 1e-10 * w2.sqrt());
                    let (mut x, mut v) = (x0, v0);
                    let bound = bound_factor(w2, dt) * amplitude(x0, v0, w2);
                    // the speed bound of `Sim::ring_since_mark`: ω × the position bound
                    let speed = w2.sqrt() * bound;
                    for n in 1..=500 {
                        let f = -w2 * x - v * it;
                        v += dt * f;
                        x += dt * v;
                        assert!(x.abs() <= bound, "ωdt {wdt} Q {q}: {x} > {bound}");
                        assert!(v.abs() <= speed, "ωdt {wdt} Q {q}: speed {v} > {speed}");
                        let moved = (x - x0).abs();
                        assert!(moved <= n as f64 * dt * speed, "ωdt {wdt} Q {q}: {moved}");
                    }
                    let (y, u) = m.pow(500).apply(x0, v0);
                    assert!((y - x).abs() <= 1e-9 * bound, "{y} vs {x}");
                    assert!((u - v).abs() <= 1e-9 * bound * w2.sqrt(), "{u} vs {v}");
                }
            }
        }
    }

    /// The implicit mount's map keeps |δ| and |δv|/ω within `IMPLICIT_BOUND_FACTOR` × the
    /// amplitude, so the speed bound of `Sim::ring_since_mark` holds for it too.
    #[test]
    fn the_implicit_map_keeps_position_and_speed_bounds() {
        for wdt in [0.01, 0.3, 1.0, 3.0] {
            let (dt, w2) = (1e-10, (wdt / 1e-10f64).powi(2));
            for it in [0.0, 1e6, 1e8] {
                let m = StepMap::implicit(w2, it, dt);
                for (x0, v0) in [
                    (1e-9, 0.0),
                    (0.0, 1e-9 * w2.sqrt()),
                    (-3e-10, 7e-10 * w2.sqrt()),
                ] {
                    let bound = IMPLICIT_BOUND_FACTOR * amplitude(x0, v0, w2);
                    let (mut x, mut v) = (x0, v0);
                    for n in 1..=300 {
                        (x, v) = m.apply(x, v);
                        assert!(x.abs() <= bound, "ωdt {wdt}: {x} > {bound}");
                        assert!(v.abs() <= w2.sqrt() * bound, "ωdt {wdt}: speed {v}");
                        let moved = (x - x0).abs();
                        assert!(
                            moved <= n as f64 * dt * w2.sqrt() * bound,
                            "ωdt {wdt}: {moved}"
                        );
                    }
                }
            }
        }
    }
}
