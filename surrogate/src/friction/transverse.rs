//! Where the path runs across the pull: the valley the DEM's slider drifts into sideways.
//!
//! The DEM pulls the control layer through an isotropic spring K0 (50 N/m), so across the pull
//! only K0 holds the slider, against landscape curvatures of 10²–10³ N/m near commensurate
//! orientations. The scene's placement is always a stationary point of the landscape across the
//! pull (the slider and substrate are both symmetric under inversion about it), but it can be a
//! ridge: square-tri at θ ≈ 0 has grooves 1.5 µm apart and 60–85 nm deep along the substrate rows,
//! and the placement sits on a crest. Off a mirror line of the scene the path then pushes the
//! slider sideways and it drifts into the groove: square-tri θ = 0.1°, α = 90.5°, 2.1 mN, DEM (design
//! protocol): the control layer moves 0.85 µm across the pull within 12 µs of the slide, 45 nm
//! lower, with 26 failed contacts (P_max 4.3 GPa), and locks in, where the straight path through
//! the placement has 227 contacts and P_max 2.9 GPa. The static solver at the DEM's drifted pose
//! gives 40 contacts, P_max 4.33 GPa and 26 failed contacts: the landscape is right, the path was
//! not. On a mirror line (square-tri θ = 0, α = 90°) the transverse force is zero by symmetry
//! and the DEM's slider stays on the crest.
//!
//! Where the coating has failed at the placement, the failed contacts (μ2) pin the slider and it
//! does not drift: the DEM's slider stays within 1 pm across the pull on rough square-tri 0°/90°
//! at 2.45 mN and on square-tri 10.2°/90° at 3.86 mN (19 failed spheres at the start), so those
//! loads keep the path through the placement.
//!
//! Elsewhere [`leaves_crest`] decides where the path runs. While the slider slides along e with
//! its contacts slipping, a transverse force F turns the slip direction (Coulomb friction C
//! opposes the velocity), so the slider drifts sideways at `dy/ds = F/C` per unit sliding
//! distance. With the force on the straight path `F_⊥(s)` (at y = 0) and the curvature of the
//! transverse profile at the placement,
//!
//! ```text
//! U(y) = V(y·e⊥) + ½ K0 y²,   e⊥ = e rotated by +90°,   k_y = U''(0),
//! dy/ds = (F_⊥(s) − k_y y) / C(s),   y(0) = 0,
//! ```
//!
//! is integrated over the DEM's sliding distance (speed × slide time; exactly on each interval, the
//! path repeated periodically), with F_⊥ and C sampled every 10th sample of the path and k_y from
//! the samples at y = 0, ±h (h ≤ the path's step). If |y| reaches h, the slider has left the crest
//! and the path runs through the lowest U on that side ([`lowest`] over `y_j = ±j·h`, `j·h ≤
//! transverse`, the groove next to the crest); otherwise it runs through the placement. The lowest,
//! not the first minimum downhill, and also past rises of the placement's profile U(y): the DEM's
//! slider crosses them. In the study protocol (30 µm of sliding) it reaches the groove and its
//! coating fails (max P_max 4.4–5.9 GPa) on square-tri 0.1°/90.5° at 0.7 and 1.05 mN and on
//! 0.2°/91.5° at 0.7, 1.05 and 1.4 mN, where U(y) at the placement rises by 0.03–1.5 pJ on the way;
//! on 0.1°/90.5° at 0.35 mN it slides with the coating intact (3.6 GPa; the estimate's groove: 3.7
//! GPa). Stopping at the first rise (the rule before) kept the slider in a 0.1 µm dip or on the
//! crest there, with the coating intact. Two things carry it over: along the path the transverse
//! force changes sign and size (±5·10⁻⁶ N against a Coulomb force of 10⁻⁵ N), so the profile at the
//! placement is only one cut of U(s, y); and its centre of mass is underdamped (damping ratio ≈
//! 0.03), so its slips (η > 1) run past shallow dips. What it leaves out: F_⊥ and C are those of
//! the straight path and k_y that of the placement (a linearisation about the crest, used only to
//! decide whether and which way the slider leaves it; the DEM took the other side on 1 of 4 checked
//! drifts, by the same distance), and along the path the slider is again kept on a straight line,
//! so a valley that bends away from the pull is not followed (the DEM's slider wanders ±0.3–0.7 µm
//! across the pull on tri-tri 21.8° and 26°). Cost: a tenth of the path's equilibria per (θ,
//! direction); where that shows a transverse force (never on a mirror line), 3 more for k_y; and
//! where a load leaves the crest, `transverse/h` more for the line on that side, with the path then
//! solved from the new start instead of the placement.

use super::path::{solve_samples, Sample};
use super::FrictionParams;
use crate::error::SceneError;
use crate::solver::Solver;

/// Transverse forces |F_⊥| (N) up to this fraction of the load W count as none (the round-off
/// of the solver's forces): a path along which every sampled |F_⊥| stays within it is a mirror
/// line of the scene and does not drift ([`transverse_starts`]; `docs/validation/friction.md`,
/// "The drift across the pull").
const TRANSVERSE_FORCE_TOL: f64 = 1e-9;

/// The drift model takes F_⊥ and the coating's C on every `DRIFT_SAMPLE_EVERY`-th sample of the
/// straight path (and its end): 0.5 µm apart at the default 0.05 µm step, finer than the
/// 1.5–3 µm scale of the landscape ([`transverse_starts`]; `docs/validation/friction.md`, "The
/// drift across the pull": "every 10th sample").
const DRIFT_SAMPLE_EVERY: usize = 10;

/// Step 2 of [`super::estimate_friction_loads`]: per load of `loads` (N), the start
/// of the path across the pull, in samples of `h` (m) along e⊥ (0: through the placement), and
/// P_max (Pa) at the placement where the path leaves it (else 0).
/// `s`: the path's samples (m) along `e`; `m`: samples of the one-sided line across the pull.
#[allow(clippy::too_many_arguments)]
pub(super) fn transverse_starts(
    solver: &Solver,
    theta: f64,
    e: [f64; 2],
    loads: &[f64],
    s: &[f64],
    h: f64,
    m: usize,
    params: &FrictionParams,
) -> (Vec<i64>, Vec<f64>) {
    let e_perp = [-e[1], e[0]];
    let tol_f = |w: f64| TRANSVERSE_FORCE_TOL * w;
    // F_⊥ and C along the straight path, every DRIFT_SAMPLE_EVERY-th sample (and its end)
    let mut coarse: Vec<f64> = s.iter().step_by(DRIFT_SAMPLE_EVERY).copied().collect();
    if coarse.last() != s.last() {
        coarse.push(*s.last().expect("a path has samples"));
    }
    let along = solve_samples(solver, theta, [0.0, 0.0], e, loads, &coarse, params);
    let pushed = |r: &Result<Vec<Sample>, SceneError>, w: f64| {
        r.as_ref()
            .is_ok_and(|x| x.iter().any(|x| x.f_perp.abs() > tol_f(w)))
    };
    let mut start = vec![0i64; loads.len()];
    let mut placed = vec![0.0; loads.len()];
    if !along.iter().zip(loads).any(|(r, &w)| pushed(r, w)) {
        // a mirror line of the scene: no transverse force anywhere
        return (start, placed);
    }
    // U'' at the placement from y = −h, 0, +h (U = V + ½K0y²)
    let stencil = solve_samples(
        solver,
        theta,
        [-h * e_perp[0], -h * e_perp[1]],
        e_perp,
        loads,
        &[0.0, h, 2.0 * h],
        params,
    );
    let distance = params.speed * params.slide_time;
    let mut side = vec![None; loads.len()];
    for (i, (&w, (path, st))) in loads.iter().zip(along.iter().zip(&stencil)).enumerate() {
        let (Ok(path), Ok(st)) = (path, st) else {
            continue;
        };
        if solver.scene().coating.failed(path[0].p_max) {
            // contacts failed at the start pin it (μ2): the DEM's slider stays (rough
            // square-tri 0°/90° at 2.45 mN, square-tri 10.2°/90° at 3.86 mN)
            continue;
        }
        let k_y = (st[0].v - 2.0 * st[1].v + st[2].v) / (h * h) + params.k0;
        let f: Vec<f64> = path.iter().map(|x| x.f_perp).collect();
        let c: Vec<f64> = path.iter().map(|x| x.coating).collect();
        side[i] = leaves_crest(k_y, &coarse, &f, &c, distance, h, tol_f(w));
    }
    // the line on each side that a load leaves to: the lowest U on it
    let y: Vec<f64> = (0..=m).map(|j| j as f64 * h).collect();
    for sign in [-1.0f64, 1.0] {
        let which: Vec<usize> = (0..loads.len())
            .filter(|&i| side[i] == Some(sign))
            .collect();
        if which.is_empty() {
            continue;
        }
        let w_side: Vec<f64> = which.iter().map(|&i| loads[i]).collect();
        let dir = [sign * e_perp[0], sign * e_perp[1]];
        let line = solve_samples(solver, theta, [0.0, 0.0], dir, &w_side, &y, params);
        for (&i, r) in which.iter().zip(line) {
            let Ok(r) = r else { continue };
            let u: Vec<f64> = r
                .iter()
                .zip(&y)
                .map(|(x, &yj)| x.v + 0.5 * params.k0 * yj * yj)
                .collect();
            let j = lowest(&u);
            start[i] = sign as i64 * j as i64;
            placed[i] = r[0].p_max;
        }
    }
    (start, placed)
}

/// Where the slider that left the crest ends up on the profile `u` (J, samples outward from the
/// placement on the side it left to): the lowest sample, the first of equal ones ([module
/// documentation](self): the DEM's slider crosses the rises of this one cut of the landscape).
/// O(len(u)).
pub(crate) fn lowest(u: &[f64]) -> usize {
    let mut best = 0;
    for (j, &x) in u.iter().enumerate() {
        if x < u[best] {
            best = j;
        }
    }
    best
}

/// Whether the slider leaves the crest it is placed on while it slides ([module
/// documentation](self)), and to which side: `Some(±1.0)` when the drift `y` along the path
/// reaches `h`, else `None`.
///
/// `k_y`: U''(0) (N/m); `s`: positions (m, ascending from 0) of the samples of `F_⊥` and `C`
/// (N) along the straight path, whose last interval closes a period (the path repeats from
/// the first sample); `distance` (m): how far the slider slides; forces within `tol_f` (N) of
/// zero count as zero (rounding). Exact on each interval for F and C constant there.
/// O(distance / sample spacing).
pub(crate) fn leaves_crest(
    k_y: f64,
    s: &[f64],
    f_perp: &[f64],
    coat: &[f64],
    distance: f64,
    h: f64,
    tol_f: f64,
) -> Option<f64> {
    if s.len() < 2 || f_perp.iter().all(|f| f.abs() <= tol_f) {
        return None;
    }
    let n = s.len() - 1;
    let (mut y, mut run) = (0.0f64, 0.0f64);
    let mut k = 0usize;
    while run < distance {
        let i = k % n;
        let ds = s[i + 1] - s[i];
        let (f, c) = (f_perp[i], coat[i]);
        if c <= 0.0 {
            // nothing holds it: it goes with the force
            if f.abs() > tol_f {
                y = f.signum() * h;
            }
        } else {
            let a = (-k_y / c).clamp(-50.0 / ds, 50.0 / ds);
            let g = if (a * ds).abs() < 1e-9 {
                ds
            } else {
                (a * ds).exp_m1() / a
            };
            y = y * (a * ds).exp() + f / c * g;
        }
        if y.abs() >= h {
            return Some(y.signum());
        }
        run += ds;
        k += 1;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::{leaves_crest, lowest};

    #[test]
    fn a_crest_is_left_only_when_the_path_pushes_off_it() {
        // a crest of U'' = −440 N/m, C = 0.01 × 2 mN, samples every 0.5 µm of a 3 µm period
        let s: Vec<f64> = (0..=6).map(|k| k as f64 * 0.5e-6).collect();
        let (h, k_y, coat) = (0.05e-6, -440.0, vec![2e-5; 7]);
        // on a mirror line: no transverse force, the slider stays on the crest
        assert_eq!(
            leaves_crest(k_y, &s, &[0.0; 7], &coat, 30e-6, h, 1e-12),
            None
        );
        // a push of 10⁻⁹ N to −e⊥ grows at 440/2e-5 = 22/µm: off to −e⊥
        let mut f = vec![0.0; 7];
        f[1] = -1e-9;
        assert_eq!(
            leaves_crest(k_y, &s, &f, &coat, 30e-6, h, 1e-12),
            Some(-1.0)
        );
        // the same push in a groove (U'' > 0): it stays
        assert_eq!(leaves_crest(440.0, &s, &f, &coat, 30e-6, h, 1e-12), None);
        // a push below the rounding tolerance counts as none
        assert_eq!(leaves_crest(k_y, &s, &f, &coat, 30e-6, h, 1e-8), None);
        // held by a large Coulomb force over a short slide, it does not get off in time
        assert_eq!(leaves_crest(k_y, &s, &f, &[1.0; 7], 1e-6, h, 1e-12), None);
        // nothing holds it: it goes with the force at once
        assert_eq!(
            leaves_crest(k_y, &s, &f, &[0.0; 7], 30e-6, h, 1e-12),
            Some(-1.0)
        );
    }

    #[test]
    fn the_lowest_groove_on_the_side_wins_over_a_dip_and_a_rise() {
        // a shallow dip at 1, then a rise above the start, then the groove at 5
        let u = [0.0, -0.1, 0.5, -1.0, -2.0, -3.0, -2.5];
        assert_eq!(lowest(&u), 5);
        // a rise right at the start does not stop it either
        assert_eq!(lowest(&[0.0, 0.1, -3.0]), 2);
        // nothing lower than the start: it stays
        assert_eq!(lowest(&[0.0, 0.1, 0.2]), 0);
        // the first of equal values; a single sample
        assert_eq!(lowest(&[2.0, 1.0, 1.0]), 1);
        assert_eq!(lowest(&[7.0]), 0);
    }
}
