//! [`estimate_friction`]: the pipeline (path → samples → coating term → Prandtl–Tomlinson term).

use super::inertial::{self, Inertial};
use super::path::{lattice_period, solve_samples, Sample};
use super::resonance::TiltResonance;
use super::tomlinson::{self, Profile};
use super::transverse::transverse_starts;
use super::FrictionParams;
use crate::error::SceneError;
use crate::map::check_slider_stays_on_substrate;
use crate::scene::Scene;
use crate::solver::{check_load, Solver};
use serde::{Deserialize, Serialize};

/// The surrogate friction estimate of one (scene, θ, pulling direction, W) (SI). See the module
/// documentation ([`crate::friction`]) for the formulas.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FrictionEstimate {
    /// Slider rotation θ (rad).
    pub theta: f64,
    /// Pulling direction from the substrate x axis (rad).
    pub direction: f64,
    /// Normal load W (N).
    pub load: f64,
    /// Estimated friction coefficient in the DEM protocol: the mean spring force of the
    /// inertial model ([`crate::friction`], "Inertial model") over `starts` runs / W.
    pub mu_est: f64,
    /// Standard deviation of the inertial runs' μ over their starts: the scatter of one DEM
    /// run's μ to expect (0 in steady sliding).
    pub mu_est_spread: f64,
    /// The quasi-static (overdamped) estimate `mu_coating + mu_corrugation`: an upper bound of
    /// μ_est where the slider sticks and slips, equal to it in steady sliding.
    pub mu_quasi_static: f64,
    /// Coating term `⟨Σ μ(p0_i) F_n,i |e_t,i|⟩_path / W`.
    pub mu_coating: f64,
    /// Prandtl–Tomlinson (corrugation) term: dissipation per unit length / W (overdamped).
    pub mu_corrugation: f64,
    /// `η = max(−V'')/K` over the path (`2π²U0/(K a²)` for a sinusoidal profile): stick-slip iff
    /// η > 1.
    pub eta: f64,
    /// Energy barrier U0 = max V − min V along the path (J), V the enthalpy profile.
    pub barrier: f64,
    /// Largest quasi-static pulling force along the path (N): the static-friction barrier of the
    /// corrugation.
    pub max_lateral_force: f64,
    /// Path average of P_max (Pa).
    pub p_max_mean: f64,
    /// Largest P_max along the path and at the placement, where the DEM's slide starts before
    /// the slider drifts to the path's start (Pa).
    pub p_max_max: f64,
    /// Path average of the fraction of the normal load carried by failed contacts (p0 > P_crit),
    /// `⟨Σ_failed F_z⟩ / W`, in [0, 1].
    pub failed_fraction: f64,
    /// Path average of the contact number.
    pub contacts_mean: f64,
    /// Stiffness K (N/m) of the Prandtl–Tomlinson spring: K0 in series with the lateral
    /// stiffness of the contacting sphere chains (path average).
    pub k_spring: f64,
    /// Path length (m).
    pub length: f64,
    /// Sample spacing (m).
    pub step: f64,
    /// Number of solved samples (path steps + 1).
    pub samples: usize,
    /// Whether the path is one substrate lattice period along the direction (exactly periodic
    /// landscape) rather than a fixed length of a quasi-periodic one.
    pub periodic: bool,
    /// Stick-slip jumps counted in the Prandtl–Tomlinson measuring window.
    pub slips: usize,
    /// Length (m) of that window.
    pub window: f64,
    /// Start of the path across the pull (m, along e⊥ = e rotated by +90°): the groove the
    /// slider drifts into off the placement's crest while it slides (`friction/transverse.rs`);
    /// 0 where it stays (no transverse force, a stable placement, a coating already failed
    /// there, or `FrictionParams::transverse` = 0).
    pub transverse_offset: f64,
    /// `ω_t/ω_p` of the spring mount ([`TiltResonance`]); `None` without springs.
    pub tilt_pair_ratio: Option<f64>,
    /// Whether the estimate is outside its tested range because of the mount's tilt resonance:
    /// [`TiltResonance::expected`] (the ratio in the band, the substrate not rough enough to
    /// detune it) and contacts fail along the path (`failed_fraction > 0`). μ_est may be an upper
    /// bound there: the DEM measured 2.1–2.8× lower on flat tri-tri 30° (the verdict unchanged).
    pub mount_resonance: bool,
}

/// Estimates the friction coefficient μ_est of the DEM protocol for `solver`'s scene at rotation
/// `theta` (rad), pulled along `direction` (rad from the substrate x axis) under load `load` W
/// (N), from the quasi-static path ([`crate::friction`] documents the formula).
///
/// The path runs parallel to the pull from the scene's placement or, where the slider drifts
/// off a crest of the landscape across the pull, from the lowest groove beside it
/// (`friction/transverse.rs`); its samples are solved with [`crate::solver::Model::Auto`] (so
/// the slider obeys the scene's mount), continuing from sample to sample
/// ([`crate::solver::Solver::solve_along_loads`]), in parallel over chunks of path,
/// deterministically.
/// Cost: `length/step + 1` equilibria (≈ 61–241 with the defaults), each about a quarter of a
/// fresh solve's cost (docs/validation/path-solve.md), a tenth of that for the drift check (3
/// more where it shows a transverse force, never on a mirror line of the scene, and
/// `transverse/step` more where the slider drifts); plus O(samples) for the Prandtl–Tomlinson
/// model and, where η > 1, `params.starts` runs of the inertial model (≈ 1.5 ms each, in
/// parallel). Several loads of one (θ, direction): [`estimate_friction_loads`] (same results,
/// cheaper).
///
/// Errors: a bad knob (field `friction.*`), non-positive load (`load_mN`), non-finite θ or
/// direction (`theta_deg`, `alpha_deg`), a path that takes the slider off the substrate
/// (`friction.length_um`; `friction.transverse_um` where only the search across the pull does), a
/// failed solve.
pub fn estimate_friction(
    solver: &Solver,
    theta: f64,
    direction: f64,
    load: f64,
    params: &FrictionParams,
) -> Result<FrictionEstimate, SceneError> {
    params.validate()?;
    check_load(load)?;
    let mut one = estimate_friction_loads(solver, theta, direction, &[load], params)?;
    one.pop().expect("one result per load")
}

/// [`estimate_friction`] at several loads `loads` (N) of one (θ, direction): one path, whose
/// candidate searches and per-sample pair lists serve every load
/// ([`crate::solver::Solver::solve_along_loads`]); each estimate is bit-identical to
/// [`estimate_friction`] at that load alone. Returns one result per load, in order (a
/// non-positive load or a failed solve errs in its own slot); the outer error is what fails for
/// every load (a bad knob, θ or direction, a path off the substrate).
pub fn estimate_friction_loads(
    solver: &Solver,
    theta: f64,
    direction: f64,
    loads: &[f64],
    params: &FrictionParams,
) -> Result<Vec<Result<FrictionEstimate, SceneError>>, SceneError> {
    params.validate()?;
    check_angles(theta, direction)?;
    let scene = solver.scene();
    let e = [direction.cos(), direction.sin()];
    let e_perp = [-e[1], e[0]];

    // 1. The path: one lattice period along lattice directions, else a fixed length.
    // (a substrate from a site file has no lattice period: the fixed length)
    let period = if scene.geometry.substrate_sites.is_some() {
        None
    } else {
        lattice_period(
            &scene.substrate.lattice,
            e,
            params.max_period,
            params.direction_tol,
        )
    };
    let length = period.unwrap_or(params.length);
    let n = (length / params.step - 1e-9).ceil().max(1.0) as usize;
    let h = length / n as f64;
    let s: Vec<f64> = (0..=n).map(|k| k as f64 * h).collect();
    let end = [length * e[0], length * e[1]];
    let (side, m_side, h_side) = if params.transverse > 0.0 {
        let m = (params.transverse / params.step - 1e-9).ceil().max(1.0) as usize;
        (params.transverse, m, params.transverse / m as f64)
    } else {
        (0.0, 0, 0.0)
    };
    // the path, then (where there is one) the path with the search across the pull
    check_reaches(scene, end, e_perp, side)?;

    let valid: Vec<f64> = loads
        .iter()
        .copied()
        .filter(|&w| check_load(w).is_ok())
        .collect();

    // 2. Where the path runs across the pull (`transverse.rs`): per load, the offset (in
    //    samples of h_side along e⊥) of its start from the placement.
    let (start, placement_p_max) = if m_side > 0 {
        transverse_starts(solver, theta, e, &valid, &s, h_side, m_side, params)
    } else {
        (vec![0; valid.len()], vec![0.0; valid.len()])
    };

    // 3. One equilibrium per sample and load along the path from its start, reduced to the
    //    sums the estimate needs: one path (and pair search) per distinct start.
    let solved = solve_by_start(solver, theta, e, &valid, &start, &s, h_side, params);
    let body = Body::of(solver, params);
    let tilt = TiltResonance::of(scene, params);
    let mut per_valid = start.into_iter().zip(solved).zip(placement_p_max);
    Ok(loads
        .iter()
        .map(|&load| {
            check_load(load)?;
            let ((j, smp), p_placed) = per_valid.next().expect("one path per valid load");
            let offset = j as f64 * h_side;
            let smp = smp.expect("every start's path solved")?;
            let mut est = from_samples(
                &smp, theta, direction, load, period, length, h, n, params, &body, tilt,
            );
            est.transverse_offset = offset;
            // the DEM's slide starts at the placement, before the drift: its P_max counts
            est.p_max_max = est.p_max_max.max(p_placed);
            Ok(est)
        })
        .collect())
}

/// Errs on a non-finite θ or pulling direction (rad).
fn check_angles(theta: f64, direction: f64) -> Result<(), SceneError> {
    if !theta.is_finite() {
        return Err(SceneError::invalid(
            "theta_deg",
            theta.to_degrees(),
            "must be finite",
        ));
    }
    if !direction.is_finite() {
        return Err(SceneError::invalid(
            "alpha_deg",
            direction.to_degrees(),
            "the pulling direction must be finite",
        ));
    }
    Ok(())
}

/// Errs when the slider leaves the substrate along the path to `end` (m), or, with a search
/// across the pull (`side` > 0, m), along the path swept `side` along `e_perp`.
fn check_reaches(
    scene: &Scene,
    end: [f64; 2],
    e_perp: [f64; 2],
    side: f64,
) -> Result<(), SceneError> {
    let reaches = [
        (0.0, "friction.length_um"),
        (side, "friction.transverse_um"),
    ];
    for &(r, field) in &reaches[..if side > 0.0 { 2 } else { 1 }] {
        let reach = [r * e_perp[0].abs(), r * e_perp[1].abs()];
        check_slider_stays_on_substrate(
            scene,
            [
                [end[0].min(0.0) - reach[0], end[1].min(0.0) - reach[1]],
                [end[0].max(0.0) + reach[0], end[1].max(0.0) + reach[1]],
            ],
            field,
        )?;
    }
    Ok(())
}

/// The samples of each `valid` load along the path `s` (m, along `e`) from its start (`start`:
/// in samples of `h_side` across the pull): one path, and pair search, per distinct start.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn solve_by_start(
    solver: &Solver,
    theta: f64,
    e: [f64; 2],
    valid: &[f64],
    start: &[i64],
    s: &[f64],
    h_side: f64,
    params: &FrictionParams,
) -> Vec<Option<Result<Vec<Sample>, SceneError>>> {
    let e_perp = [-e[1], e[0]];
    let mut groups: std::collections::BTreeMap<i64, Vec<usize>> = Default::default();
    for (i, &j) in start.iter().enumerate() {
        groups.entry(j).or_default().push(i);
    }
    let mut solved: Vec<Option<Result<Vec<Sample>, SceneError>>> =
        valid.iter().map(|_| None).collect();
    for (&j, members) in &groups {
        let y = j as f64 * h_side;
        let group_loads: Vec<f64> = members.iter().map(|&i| valid[i]).collect();
        let origin = [y * e_perp[0], y * e_perp[1]];
        let path = solve_samples(solver, theta, origin, e, &group_loads, s, params);
        for (&i, r) in members.iter().zip(path) {
            solved[i] = Some(r);
        }
    }
    solved
}

/// The sliding body of the inertial model: mass (kg) and damping coefficient (kg/s).
struct Body {
    mass: f64,
    gamma: f64,
}

impl Body {
    /// Slider spheres plus control-layer spheres (one per slider sphere); the control layer is
    /// damped relative to the support with τ.
    fn of(solver: &Solver, params: &FrictionParams) -> Body {
        let scene = solver.scene();
        let n = solver.slider_count() as f64;
        let m_c = scene
            .slider_material()
            .sphere_mass(params.control_sphere_radius);
        let mass = if scene.slider_radii().is_some() {
            scene.slider_spheres_mass() + n * m_c
        } else {
            n * (scene
                .slider_material()
                .sphere_mass(scene.slider_sphere_radius())
                + m_c)
        };
        Body {
            mass,
            gamma: n * m_c / params.tau,
        }
    }
}

/// The path-average weights of the n + 1 samples: periodic paths average the n distinct
/// samples of one period (the last repeats the first); quasi-periodic ones use the trapezoid
/// rule over [0, L].
fn path_weights(n: usize, periodic: bool) -> Vec<f64> {
    (0..=n)
        .map(|k| match (periodic, k == 0 || k == n) {
            (true, _) if k == n => 0.0,
            (true, _) => 1.0 / n as f64,
            (false, true) => 0.5 / n as f64,
            (false, false) => 1.0 / n as f64,
        })
        .collect()
}

/// μ and its spread over the starts from the inertial model where the path can stick and
/// slip: `f` the pull (N) at the samples `smp` (step `h`, m), `k_spring` (N/m) in series.
#[allow(clippy::too_many_arguments)]
fn stick_slip_mu(
    smp: &[Sample],
    f: &[f64],
    h: f64,
    body: &Body,
    k_spring: f64,
    params: &FrictionParams,
    load: f64,
) -> (f64, f64) {
    let coat: Vec<f64> = smp.iter().map(|x| x.coating).collect();
    let (friction, spread) = inertial::ensemble(
        f,
        &coat,
        h,
        &Inertial {
            mass: body.mass,
            gamma: body.gamma,
            k: k_spring,
            speed: params.speed,
            duration: params.slide_time,
            window_start: params.window_start,
        },
        params.starts,
    );
    (friction / load, spread / load)
}

/// Steps 3–4 of the estimate from the solved samples of one load.
#[allow(clippy::too_many_arguments)]
fn from_samples(
    smp: &[Sample],
    theta: f64,
    direction: f64,
    load: f64,
    period: Option<f64>,
    length: f64,
    h: f64,
    n: usize,
    params: &FrictionParams,
    body: &Body,
    tilt: Option<TiltResonance>,
) -> FrictionEstimate {
    // 3. Path averages: periodic paths average the n distinct samples of one period (the last
    //    repeats the first); quasi-periodic ones use the trapezoid rule over [0, L].
    let weights = path_weights(n, period.is_some());
    let avg = |f: &dyn Fn(&Sample) -> f64| -> f64 {
        smp.iter().zip(&weights).map(|(x, w)| w * f(x)).sum()
    };
    let mu_coating = avg(&|x| x.coating) / load;
    let failed_fraction = (avg(&|x| x.failed_load) / load).clamp(0.0, 1.0);
    let p_max_mean = avg(&|x| x.p_max);
    let contacts_mean = avg(&|x| x.contacts as f64);
    let k_lateral = avg(&|x| x.k_lateral);
    let p_max_max = smp.iter().map(|x| x.p_max).fold(0.0, f64::max);

    // 4. Prandtl–Tomlinson on the enthalpy profile, spring K0 in series with the contacts.
    let k_spring = if k_lateral > 0.0 {
        1.0 / (1.0 / params.k0 + 1.0 / k_lateral)
    } else {
        params.k0
    };
    let v: Vec<f64> = smp.iter().map(|x| x.v).collect();
    let f: Vec<f64> = smp.iter().map(|x| x.f_pull).collect();
    let pt = tomlinson::run(
        &Profile {
            h,
            f: &f,
            periodic: period.is_some(),
        },
        k_spring,
        params.transient,
    );
    let vmin = v.iter().copied().fold(f64::INFINITY, f64::min);
    let vmax = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mu_corrugation = pt.friction / load;
    let mu_quasi = mu_coating + mu_corrugation;
    // η ≤ 1: no instability, steady sliding: the quasi-static value is the exact dissipation
    // per unit length, so the inertial model (which would only add its window's sampling) runs
    // only where the path can stick and slip
    let (mu_est, mu_est_spread) = if pt.eta <= 1.0 {
        (mu_quasi, 0.0)
    } else {
        stick_slip_mu(smp, &f, h, body, k_spring, params, load)
    };
    FrictionEstimate {
        theta,
        direction,
        load,
        mu_est,
        mu_est_spread,
        mu_quasi_static: mu_quasi,
        mu_coating,
        mu_corrugation,
        eta: pt.eta,
        barrier: vmax - vmin,
        max_lateral_force: f.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        p_max_mean,
        p_max_max,
        failed_fraction,
        contacts_mean,
        k_spring,
        length,
        step: h,
        samples: n + 1,
        periodic: period.is_some(),
        slips: pt.jumps,
        window: pt.window,
        transverse_offset: 0.0,
        tilt_pair_ratio: tilt.map(|t| t.ratio),
        mount_resonance: failed_fraction > 0.0 && tilt.is_some_and(|t| t.expected()),
    }
}
