//! The DEM protocol on a one-dimensional slider: the Prandtl–Tomlinson model with the slider's
//! mass, the DEM's damping and Coulomb friction of the coating.
//!
//! The slider's centre of mass (position x along the path, velocity u) carries the slider's mass
//! M (slider spheres and control layer) and is pulled through the spring K by the support
//! `X(t) = X₀ + v t` at the DEM's speed v:
//!
//! ```text
//! M u̇ = K (X − x) − F(x) − γ (u − v) − C(x) sgn(u),        ẋ = u
//! ```
//!
//! with `F = V'` the quasi-static pulling force (the enthalpy slope, linear between samples as in
//! [`super::tomlinson`]), `C(x) = Σ μ(p0_i) F_n,i |e_t,i|` the coating's Coulomb force at that
//! position (the coating term's integrand) and `γ = m_cl/τ` the damping of the DEM's control
//! layer relative to the support (the only damping of the centre-of-mass motion in the DEM: the
//! slider spheres are damped relative to the control layer). With `u = 0` the slider sticks
//! while `|K(X − x) − F(x) + γv| ≤ C(x)` (static = kinetic coefficient, as in the DEM's capped
//! Mindlin spring). Integrated with the symplectic Euler scheme at a step ≤ `0.05/ω_max`,
//! `ω_max = √((K + max|F'|)/M)`, and ≤ the time to cross half a sample at the current speed; a
//! velocity that changes sign within a step is set to zero (the slider sticks), and a stuck
//! phase is skipped in closed form (the drive grows at K·v; the spring force is linear in t).
//!
//! The run starts in steady sliding at `x_start` (u = v, spring force `F + C` there) and, as in the
//! DEM's protocol, moves the support for `duration` and returns the mean spring force over the
//! part after `window_start`. On a flat profile (F = 0, C constant) it is exactly C: steady
//! sliding. The profile is extended periodically (a periodic path exactly; a quasi-periodic one
//! by repeating its samples, which adds a seam every path length). Cost O(duration/dt), about
//! 10⁵ steps (≈ 1.5 ms).
//!
//! What it adds to the quasi-static model: inertia. In the DEM the centre of mass is
//! underdamped (damping ratio `γ/(2√(KM))` ≈ 0.03 for the study's slider), so a slip runs past
//! the next well and the spring unloads further than in the overdamped jump; the mean force
//! falls below the quasi-static one.

/// Knobs of a run ([`Runner`]) (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Inertial {
    /// Mass M of the sliding body (kg).
    pub mass: f64,
    /// Damping coefficient γ (kg/s), relative to the support's velocity.
    pub gamma: f64,
    /// Spring stiffness K (N/m).
    pub k: f64,
    /// Support speed v (m/s).
    pub speed: f64,
    /// Duration of the run (s).
    pub duration: f64,
    /// Start of the measuring window (s), < duration.
    pub window_start: f64,
}

/// Result of a run ([`Runner`]) (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct InertialRun {
    /// Mean spring force over the window (N).
    pub friction: f64,
    /// Times the slider stuck (u → 0) in the window.
    pub sticks: usize,
}

/// Two periodic, piecewise linear profiles `f` and `c` over samples `[0..=n]` spaced `h` (the
/// last sample closes the last interval; the next period starts again at the first), read at
/// the same position. The interval of the last read is kept: the slider moves at most half a
/// sample per step, so most reads skip the floor and the wrap (same values as computing them).
struct Lin<'a> {
    h: f64,
    f: &'a [f64],
    c: &'a [f64],
    /// The last interval: its start in samples (unwrapped) and its index in the period.
    fl: f64,
    i: usize,
}

impl<'a> Lin<'a> {
    fn new(h: f64, f: &'a [f64], c: &'a [f64]) -> Self {
        Lin {
            h,
            f,
            c,
            fl: f64::NAN,
            i: 0,
        }
    }

    /// `(f(x), c(x))`, interpolated linearly. O(1).
    #[inline]
    fn at(&mut self, x: f64) -> (f64, f64) {
        let t = x / self.h;
        // the same interval as the last read (NaN at first: never)
        if !(t >= self.fl && t < self.fl + 1.0) {
            let n = self.f.len() - 1;
            // floor and wrap, the cheap way on the common case 0 ≤ t < n (same values)
            (self.fl, self.i) = if (0.0..n as f64).contains(&t) {
                let i = t as usize;
                (i as f64, i)
            } else {
                let fl = t.floor();
                (fl, (fl as i64).rem_euclid(n as i64) as usize)
            };
        }
        let (i, w) = (self.i, t - self.fl);
        (
            self.f[i] + w * (self.f[i + 1] - self.f[i]),
            self.c[i] + w * (self.c[i + 1] - self.c[i]),
        )
    }
}

/// The mean of the runs ([`Runner`]) over `starts` starts in steady sliding at `x = j·n·h/starts`,
/// `j = 0..starts` (evenly spread over the profile): the stick-slip of an underdamped slider is
/// chaotic, and a single run's window mean scatters by ±20–30 % with its start. Returns the
/// runs' mean friction and its standard deviation (N) — the scatter a single DEM run of the
/// same length has to expect. Parallel over groups of [`INTERLEAVE`] starts (rayon), each group
/// stepped in turn on one thread ([`Runner`]: one run's step is a chain of dependent
/// divisions, and independent runs fill its latency); deterministic, each run's result the
/// same bits as when run alone.
pub(crate) fn ensemble(f: &[f64], c: &[f64], h: f64, p: &Inertial, starts: usize) -> (f64, f64) {
    use rayon::prelude::*;
    let starts = starts.max(1);
    let n = (f.len() - 1) as f64;
    let x_start = |j: usize| j as f64 * n * h / starts as f64;
    let groups: Vec<Vec<f64>> = (0..starts.div_ceil(INTERLEAVE))
        .into_par_iter()
        .map(|g| {
            let js = g * INTERLEAVE..((g + 1) * INTERLEAVE).min(starts);
            let mut runners: Vec<Runner> =
                js.map(|j| Runner::new(f, c, h, p, x_start(j))).collect();
            while runners.iter_mut().fold(false, |any, r| r.advance() | any) {}
            runners.iter().map(|r| r.result().friction).collect()
        })
        .collect();
    let friction: Vec<f64> = groups.into_iter().flatten().collect();
    let k = friction.len() as f64;
    let mean = friction.iter().sum::<f64>() / k;
    let var = friction
        .iter()
        .map(|r| (r - mean) * (r - mean))
        .sum::<f64>()
        / (k - 1.0).max(1.0);
    (mean, var.sqrt())
}

/// The part of the step `[t0, t1]` inside the measuring window `t ≥ t_w` (s): the weight of the
/// step's end-of-step spring force in the window integral (a step that straddles the window's
/// start counts only its part after it).
fn in_window(t0: f64, t1: f64, t_w: f64) -> f64 {
    (t1 - t0.max(t_w)).max(0.0)
}

/// Runs the model on the force profile `f` (= V', N) and Coulomb profile `c` (N, ≥ 0), both
/// sampled at `s_k = k·h`, `k = 0..=n` (see the module documentation), starting in steady
/// sliding at `x_start` (m). (The tests' single run; [`ensemble`] interleaves several.)
#[cfg(test)]
pub(crate) fn run(f: &[f64], c: &[f64], h: f64, p: &Inertial, x_start: f64) -> InertialRun {
    let mut r = Runner::new(f, c, h, p, x_start);
    while r.advance() {}
    r.result()
}

/// Starts of [`ensemble`] stepped in turn on one thread.
const INTERLEAVE: usize = 4;

/// One run of the model from steady sliding (see the module documentation), advanced step by
/// step ([`Runner::advance`]) so that several can be interleaved on one thread.
struct Runner<'a> {
    prof: Lin<'a>,
    /// Constants: mass, damping, spring, speed (SI); end of the run and start of the window
    /// (s); the largest step (s); the support's start (m). (The sample spacing is `prof.h`.)
    m: f64,
    g: f64,
    k: f64,
    v: f64,
    t_end: f64,
    t_w: f64,
    dt_max: f64,
    x0_support: f64,
    /// State: position (m), velocity (m/s), time (s), ∫ spring force dt over the window
    /// (N·s), times stuck in the window.
    x: f64,
    u: f64,
    t: f64,
    sum: f64,
    sticks: usize,
}

impl<'a> Runner<'a> {
    /// The run from steady sliding at `x_start` (m). O(n) (the profile's largest slope).
    fn new(f: &'a [f64], c: &'a [f64], h: f64, p: &Inertial, x_start: f64) -> Runner<'a> {
        assert!(f.len() == c.len() && f.len() >= 2);
        let mut prof = Lin::new(h, f, c);
        // the fastest natural frequency sets the largest step; a moving slider also crosses at
        // most half a sample per step
        let slope = f
            .windows(2)
            .map(|w| ((w[1] - w[0]) / h).abs())
            .fold(0.0f64, f64::max);
        let omega = ((p.k + slope) / p.mass).sqrt();
        let dt_max = (0.05 / omega).min(p.duration / 1e4);
        // steady sliding at x_start
        let (f0, c0) = prof.at(x_start);
        Runner {
            prof,
            m: p.mass,
            g: p.gamma,
            k: p.k,
            v: p.speed,
            t_end: p.duration,
            t_w: p.window_start,
            dt_max,
            x0_support: x_start + (f0 + c0) / p.k,
            x: x_start,
            u: p.speed,
            t: 0.0,
            sum: 0.0,
            sticks: 0,
        }
    }

    /// The spring force (N) at time `t` (s) with the slider at `x` (m).
    #[inline(always)]
    fn spring(&self, t: f64, x: f64) -> f64 {
        self.k * (self.x0_support + self.v * t - x)
    }

    /// One step (a stuck phase skipped in closed form, then one step from rest; or one
    /// sliding step); false once the run has ended (and then a no-op). O(1).
    #[inline(always)]
    fn advance(&mut self) -> bool {
        let (m, g, k, v) = (self.m, self.g, self.k, self.v);
        let (t_end, t_w) = (self.t_end, self.t_w);
        // the run's loop test `t < t_end` (a NaN time ends it too)
        let running = self.t < t_end;
        if !running {
            return false;
        }
        let (fx, coulomb) = self.prof.at(self.x);
        if self.u == 0.0 {
            // stuck: the drive K(X − x) − F(x) + γv grows at K·v; it frees the slider when it
            // leaves [−C, C]
            let drive = self.spring(self.t, self.x) - fx + g * v;
            let wait = if drive.abs() > coulomb {
                0.0
            } else {
                (coulomb - drive) / (k * v)
            };
            if wait > 0.0 {
                let t2 = (self.t + wait).min(t_end);
                // the spring force is linear in t while stuck: integrate it exactly
                let (a, b) = (self.t.max(t_w), t2);
                if b > a {
                    let (sa, sb) = (self.spring(a, self.x), self.spring(b, self.x));
                    self.sum += 0.5 * (sa + sb) * (b - a);
                }
                self.t = t2;
                if self.t >= t_end {
                    return false;
                }
            }
            // free: one step from rest in the direction of the drive (x has not moved)
            let drive = self.spring(self.t, self.x) - fx + g * v;
            let dt = self.dt_max.min(t_end - self.t);
            self.u = (drive - coulomb.copysign(drive)) / m * dt;
            if (drive.abs() - coulomb) <= 0.0 {
                self.u = 0.0;
            }
            self.x += self.u * dt;
            let t0 = self.t;
            self.t += dt;
            self.sum += self.spring(self.t, self.x) * in_window(t0, self.t, t_w);
            return true;
        }
        let u = self.u;
        let dt = self
            .dt_max
            .min(0.5 * self.prof.h / u.abs())
            .min(t_end - self.t);
        let drive = self.spring(self.t, self.x) - fx - g * (u - v);
        let un = u + (drive - coulomb.copysign(u)) / m * dt;
        if un * u <= 0.0 {
            self.u = 0.0;
            if self.t > t_w {
                self.sticks += 1;
            }
        } else {
            self.u = un;
        }
        self.x += self.u * dt;
        let t0 = self.t;
        self.t += dt;
        self.sum += self.spring(self.t, self.x) * in_window(t0, self.t, t_w);
        true
    }

    /// The run's result (valid once [`Runner::advance`] returned false).
    fn result(&self) -> InertialRun {
        let span = (self.t_end - self.t_w).max(f64::MIN_POSITIVE);
        InertialRun {
            friction: self.sum / span,
            sticks: self.sticks,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn study() -> Inertial {
        Inertial {
            mass: 1.13e-10,
            gamma: 4.0e-6,
            k: 50.0,
            speed: 0.1,
            duration: 300e-6,
            window_start: 100e-6,
        }
    }

    #[test]
    fn a_step_counts_only_its_part_inside_the_window() {
        // before, straddling, inside, and ending exactly at the window's start
        assert_eq!(in_window(1.0, 2.0, 3.0), 0.0);
        assert_eq!(in_window(2.5, 3.5, 3.0), 0.5);
        assert_eq!(in_window(3.25, 3.75, 3.0), 0.5);
        assert_eq!(in_window(2.0, 3.0, 3.0), 0.0);
    }

    #[test]
    fn flat_profile_slides_steadily_at_the_coulomb_force() {
        let c = vec![1.4e-5; 61];
        let f = vec![0.0; 61];
        let r = run(&f, &c, 0.05e-6, &study(), 0.0);
        assert!((r.friction - 1.4e-5).abs() <= 1e-9 * 1.4e-5, "{r:?}");
        assert_eq!(r.sticks, 0);
    }

    /// Period (m) and samples of the sinusoidal test profiles.
    const A: f64 = 3e-6;
    const N: usize = 120;

    /// `F0 sin(2π s/A)` (N) at the `N + 1` samples of one period.
    fn sinus(f0: f64) -> Vec<f64> {
        (0..=N)
            .map(|j| f0 * (2.0 * PI * j as f64 / N as f64).sin())
            .collect()
    }

    #[test]
    fn weak_corrugation_adds_no_mean_force_and_strong_corrugation_sticks_and_slips() {
        let (a, n) = (A, N);
        let h = a / n as f64;
        let p = study();
        let c = vec![0.0; n + 1];
        // η = 2π F0/(K a) = 0.5: smooth sliding, mean force ≈ 0 (only the damping's)
        let f0 = 0.5 * p.k * a / (2.0 * PI);
        let r = run(&sinus(f0), &c, h, &p, 0.0);
        assert!(r.friction.abs() < 0.05 * f0, "{r:?}");
        // η = 10: stick-slip; the mean force is positive and below the barrier force F0
        let f0 = 10.0 * p.k * a / (2.0 * PI);
        let r = run(&sinus(f0), &c, h, &p, 0.0);
        assert!(r.friction > 0.05 * f0 && r.friction < f0, "{r:?}");
        // more damping → closer to the overdamped (quasi-static) limit: a larger mean force
        let heavy = Inertial {
            gamma: 200.0 * p.gamma,
            ..p
        };
        let r2 = run(&sinus(f0), &c, h, &heavy, 0.0);
        assert!(r2.friction > r.friction, "{r2:?} vs {r:?}");
    }

    /// The ensemble's interleaved runs give the bits of the same runs alone: the mean and
    /// spread of 11 stick-slip runs (groups of 4, 4 and 3), with a Coulomb profile.
    #[test]
    fn interleaved_runs_give_the_bits_of_runs_alone() {
        let (a, n) = (A, N);
        let h = a / n as f64;
        let p = study();
        let f0 = 10.0 * p.k * a / (2.0 * PI);
        let f = sinus(f0);
        let c: Vec<f64> = (0..=n)
            .map(|j| 0.05 * f0 * (1.0 + (4.0 * PI * j as f64 / n as f64).cos()))
            .collect();
        let starts = 11;
        let alone: Vec<InertialRun> = (0..starts)
            .map(|j| run(&f, &c, h, &p, j as f64 * n as f64 * h / starts as f64))
            .collect();
        assert!(alone.iter().all(|r| r.sticks > 0), "stick-slip expected");
        let k = starts as f64;
        let mean = alone.iter().map(|r| r.friction).sum::<f64>() / k;
        let var = alone
            .iter()
            .map(|r| (r.friction - mean) * (r.friction - mean))
            .sum::<f64>()
            / (k - 1.0);
        let (m, sd) = ensemble(&f, &c, h, &p, starts);
        assert_eq!(m.to_bits(), mean.to_bits());
        assert_eq!(sd.to_bits(), var.sqrt().to_bits());
        assert!(sd > 0.0);
    }
}
