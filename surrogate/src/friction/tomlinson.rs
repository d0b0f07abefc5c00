//! The athermal, quasi-static Prandtl–Tomlinson model on a sampled force profile.
//!
//! The slider (position x along the path) is pulled through a spring K by a support at X over
//! the energy profile V(x): total energy `E(x; X) = V(x) + ½K(x − X)²`. The profile is given by
//! its slope, the quasi-static pulling force `F(x) = V'(x)`, sampled exactly at `s_k = k·h` and
//! interpolated linearly between samples (shape-preserving: a cusp of the landscape, where the
//! contacts change partners and F jumps within one step, cannot overshoot; a smooth profile is
//! reproduced to O(h²)). Then `X(x) = x + F(x)/K`, the support position that holds the slider in
//! equilibrium at x, is piecewise linear and the model is solved exactly:
//!
//! - as X advances the slider follows the equilibria where `dX/dx = 1 + F'(x)/K > 0`;
//! - where X(x) has a local maximum (a sample where dX/dx turns negative) the equilibrium
//!   vanishes, and at fixed support `X_s` the slider runs downhill (`∂E/∂x = K(X(x) − X_s) < 0`)
//!   to the first x' beyond with `X(x') = X_s`; the jump dissipates
//!   `E(x_s; X_s) − E(x'; X_s) = K ∫_{x_s}^{x'} (X_s − X(x)) dx` (a sum of trapezoids).
//!
//! So the slider visits exactly the points where X(x) equals its running maximum, and the
//! dissipation per unit length in steady sliding is the corrugation friction force. There are
//! jumps iff `η = max(−F')/K > 1` somewhere on the path (for a sinusoid of barrier U0 and period
//! a, `max(−V'') = 2π²U0/a²`: the classical `η = 2π²U0/(K a²)`).

/// A sampled force profile on a uniform grid `s_k = k·h`, `k = 0..=n` (SI).
pub(crate) struct Profile<'a> {
    /// Sample spacing h (m).
    pub h: f64,
    /// `F_k = V'(s_k)` (N), `n + 1` values.
    pub f: &'a [f64],
    /// Whether the profile is periodic with period `n·h` (the path is one lattice period; the
    /// last sample repeats the first): it is then extended periodically.
    pub periodic: bool,
}

/// Result of the Prandtl–Tomlinson model (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tomlinson {
    /// Dissipation per unit sliding distance in steady sliding = mean corrugation friction (N).
    pub friction: f64,
    /// `max(−F')/K` over the path.
    pub eta: f64,
    /// Jumps counted in the measuring window.
    pub jumps: usize,
    /// Length (m) of the measuring window.
    pub window: f64,
}

/// Runs the model on `p` with spring stiffness `k` (N/m).
///
/// Periodic profiles: the support runs three periods from the slider at rest at s = 0; the jumps
/// that start in the second period are one steady-state period's dissipation (from the second
/// period on the motion repeats exactly: X(x + L) = X(x) + L), divided by the period.
/// Quasi-periodic profiles: one pass; the window runs from the first landing after `transient`
/// (m) to the last landing, so it spans whole stick-slip cycles; with a single jump after the
/// transient its dissipation is spread over the path after the transient, with none the result is
/// 0. Cost O(n).
pub(crate) fn run(p: &Profile, k: f64, transient: f64) -> Tomlinson {
    let n = p.f.len() - 1;
    let h = p.h;
    let length = n as f64 * h;
    let laps = if p.periodic { 3 } else { 1 };
    let total = laps * n; // nodes 0..=total
                          // X at node g (support position holding the slider there)
    let xs = |g: usize| -> f64 {
        let f = if p.periodic { p.f[g % n] } else { p.f[g] };
        g as f64 * h + f / k
    };
    let eta = (0..n)
        .map(|i| -(p.f[i + 1] - p.f[i]) / (h * k))
        .fold(0.0f64, f64::max);
    // (start x, landing x, dissipated energy)
    let mut jumps: Vec<(f64, f64, f64)> = Vec::new();
    let mut g = 0usize; // the slider sits at node g (or on the rising segment after it)
    while g < total {
        if xs(g + 1) >= xs(g) {
            g += 1; // follows the rising segment
            continue;
        }
        // X falls after node g: jump at support m = X(g) from x_s = g·h.
        let m = xs(g);
        let mut area = 0.0; // ∫ (m − X) dx so far
        let mut j = g;
        let mut landed = None;
        while j < total {
            let (a, b) = (m - xs(j), m - xs(j + 1)); // ≥ 0 at a
            if b <= 0.0 {
                // crossing inside [j, j+1]: (m − X) falls linearly from a to b
                let t = if a > b { a / (a - b) } else { 0.0 };
                area += 0.5 * a * t * h;
                landed = Some((j as f64 + t) * h);
                break;
            }
            area += 0.5 * (a + b) * h;
            j += 1;
        }
        match landed {
            Some(xl) => {
                jumps.push((g as f64 * h, xl, k * area));
                // continue on the rising segment [j, j+1] from the landing point
                g = j + 1;
            }
            None => break, // the slider leaves the path
        }
    }
    let (friction, count, window) = if p.periodic {
        let sel: Vec<&(f64, f64, f64)> = jumps
            .iter()
            .filter(|j| j.0 >= length && j.0 < 2.0 * length)
            .collect();
        let e: f64 = sel.iter().map(|j| j.2).sum();
        (e / length, sel.len(), length)
    } else {
        let after: Vec<&(f64, f64, f64)> = jumps.iter().filter(|j| j.1 >= transient).collect();
        match after.len() {
            0 => (0.0, 0, length - transient),
            1 => (after[0].2 / (length - transient), 1, length - transient),
            _ => {
                // window [first landing, last landing): the jumps landing in (first, last]
                let x_a = after[0].1;
                let x_b = after[after.len() - 1].1;
                let e: f64 = after[1..].iter().map(|j| j.2).sum();
                (e / (x_b - x_a), after.len() - 1, x_b - x_a)
            }
        }
    };
    Tomlinson {
        friction,
        eta,
        jumps: count,
        window,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Sinusoid V = (U0/2)(1 − cos 2πs/a) sampled over one period.
    fn sinusoid(u0: f64, a: f64, n: usize) -> (Vec<f64>, Vec<f64>) {
        let q = 2.0 * PI / a;
        let s: Vec<f64> = (0..=n).map(|k| k as f64 * a / n as f64).collect();
        (
            s.iter().map(|x| 0.5 * u0 * (1.0 - (q * x).cos())).collect(),
            s.iter().map(|x| 0.5 * u0 * q * (q * x).sin()).collect(),
        )
    }

    #[test]
    fn smooth_sliding_below_eta_one() {
        let (a, k) = (1.5e-6, 50.0);
        let u0 = 0.8 * k * a * a / (2.0 * PI * PI); // η = 0.8
        let (_, f) = sinusoid(u0, a, 200);
        let r = run(
            &Profile {
                h: a / 200.0,
                f: &f,
                periodic: true,
            },
            k,
            0.0,
        );
        assert!((r.eta - 0.8).abs() < 1e-3, "{}", r.eta);
        assert_eq!(r.friction, 0.0);
        assert_eq!(r.jumps, 0);
    }

    #[test]
    fn stick_slip_above_eta_one_approaches_the_barrier_force() {
        // η > 1: one jump per period; the mean force grows with η towards the largest lateral
        // force πU0/a of the sinusoid (reached as η → ∞).
        let (a, k) = (1.5e-6, 50.0);
        for eta in [2.0, 10.0, 1000.0] {
            let u0 = eta * k * a * a / (2.0 * PI * PI);
            let (_, f) = sinusoid(u0, a, 400);
            let r = run(
                &Profile {
                    h: a / 400.0,
                    f: &f,
                    periodic: true,
                },
                k,
                0.0,
            );
            let fmax = PI * u0 / a;
            assert_eq!(r.jumps, 1, "η {eta}");
            assert!(
                r.friction > 0.0 && r.friction < fmax,
                "η {eta}: {}",
                r.friction
            );
            if eta >= 1000.0 {
                assert!(r.friction > 0.9 * fmax, "{} vs {fmax}", r.friction);
            }
        }
        // Monotone in η.
        let f = |eta: f64| {
            let u0 = eta * k * a * a / (2.0 * PI * PI);
            let (_, f) = sinusoid(u0, a, 400);
            run(
                &Profile {
                    h: a / 400.0,
                    f: &f,
                    periodic: true,
                },
                k,
                0.0,
            )
            .friction
                / (PI * u0 / a)
        };
        assert!(f(1.5) < f(3.0) && f(3.0) < f(30.0));
    }

    #[test]
    fn quasi_periodic_window_matches_periodic() {
        // Three periods sampled as a non-periodic path: same friction as the periodic answer.
        let (a, k) = (1.5e-6, 50.0);
        let u0 = 5.0 * k * a * a / (2.0 * PI * PI);
        let (_, f1) = sinusoid(u0, a, 200);
        let per = run(
            &Profile {
                h: a / 200.0,
                f: &f1,
                periodic: true,
            },
            k,
            0.0,
        );
        let q = 2.0 * PI / a;
        let s: Vec<f64> = (0..=1200).map(|j| j as f64 * a / 200.0).collect();
        let f: Vec<f64> = s.iter().map(|x| 0.5 * u0 * q * (q * x).sin()).collect();
        let qp = run(
            &Profile {
                h: a / 200.0,
                f: &f,
                periodic: false,
            },
            k,
            a,
        );
        assert!(qp.jumps >= 3, "{}", qp.jumps);
        assert!(
            (qp.friction - per.friction).abs() < 1e-6 * per.friction,
            "{} vs {}",
            qp.friction,
            per.friction
        );
    }

    /// The closed form against a brute-force simulation of the same model on the exact sinusoid:
    /// the support advances in steps of a/20000 and the slider descends E(x; X) from where it
    /// was (Newton steps capped at a/2000, with backtracking); the energy released in each relaxation is summed over the
    /// relaxations that start in the slider's second period.
    #[test]
    fn closed_form_matches_brute_force() {
        let (a, k) = (1.5e-6, 50.0);
        let q = 2.0 * PI / a;
        for eta in [1.3, 4.0, 25.0] {
            let u0 = eta * k * a * a / (2.0 * PI * PI);
            let v = |x: f64| 0.5 * u0 * (1.0 - (q * x).cos());
            let dv = |x: f64| 0.5 * u0 * q * (q * x).sin();
            let d2v = |x: f64| 0.5 * u0 * q * q * (q * x).cos();
            let e = |x: f64, xs: f64| v(x) + 0.5 * k * (x - xs) * (x - xs);
            let mut x = 0.0;
            let mut diss = 0.0;
            let steps = 20000;
            // the spring stretches by up to F_max/K = η·a/(2π): run the support that far beyond
            let laps = 3 + (eta / 2.0).ceil() as usize;
            for j in 1..=laps * steps {
                let xs = a * j as f64 / steps as f64;
                let e0 = e(x, xs);
                let x_before = x;
                // descend: gradient steps until a local minimum
                for _ in 0..100_000 {
                    let g = dv(x) + k * (x - xs);
                    let hss = d2v(x) + k;
                    // short steps: an overdamped slider cannot hop over a barrier
                    let mut step = if hss > 0.0 {
                        -g / hss
                    } else {
                        -g.signum() * 1e-3 * a
                    }
                    .clamp(-a / 2000.0, a / 2000.0);
                    while e(x + step, xs) > e(x, xs) && step.abs() > 1e-18 {
                        step *= 0.5;
                    }
                    x += step;
                    if g.abs() < 1e-12 * u0 / a && hss > 0.0 {
                        break;
                    }
                }
                if x_before >= a && x_before < 2.0 * a {
                    diss += e0 - e(x, xs);
                }
            }
            let brute = diss / a;
            let (_, fs) = sinusoid(u0, a, 400);
            let r = run(
                &Profile {
                    h: a / 400.0,
                    f: &fs,
                    periodic: true,
                },
                k,
                0.0,
            );
            assert!(
                (r.friction - brute).abs() < 0.01 * brute,
                "η {eta}: closed form {} vs brute force {brute}",
                r.friction
            );
        }
    }
}
