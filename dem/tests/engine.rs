//! The DEM engine on small scenes (seconds each in the dev profile): agreement with the
//! surrogate, energy conservation, time-step blow-up detection, thread-count independence,
//! checkpoint/resume, steady sliding friction and lock-in detection.

mod common;

use common::{params, run_slide, slide_params, small};
use dem::model::{Constant, Friction};
use dem::protocol::{lock_in, run, RunIo, RunKind, Sample};
use dem::{prepare, Prepared, SimParams, Start};
use surrogate::Scene;

fn quiet() -> impl FnMut(&dem::protocol::Progress) {
    |_| {}
}

/// Equilibrates `scene` from `start` and asserts the DEM equilibrium matches the surrogate's:
/// same contact number, P_max within 2 %, the load carried by the contacts within 2 %.
fn assert_settles_on_the_surrogate(scene: &Scene, p: SimParams, start: Start, label: &str) {
    let Prepared {
        mut sim,
        start: surrogate,
        ..
    } = prepare(scene, p, start, None).unwrap();
    let mut samples = Vec::new();
    run(
        &mut sim,
        RunKind::Equilibrate,
        &RunIo::default(),
        &mut samples,
        &mut quiet(),
    )
    .unwrap();
    let o = sim.observe();
    eprintln!(
        "{label}: DEM {} contacts, P_max {} GPa; surrogate {} contacts, {} GPa",
        o.contacts,
        o.p_max * 1e-9,
        surrogate.contacts,
        surrogate.p_max * 1e-9
    );
    assert_eq!(o.contacts, surrogate.contacts, "{label}");
    assert!(
        (o.p_max / surrogate.p_max - 1.0).abs() < 0.02,
        "{label}: DEM {} vs surrogate {}",
        o.p_max,
        surrogate.p_max
    );
    assert!(
        (o.contact_fz / sim.params.protocol.load - 1.0).abs() < 0.02,
        "{label}: load not carried"
    );
}

#[test]
fn equilibrium_agrees_with_the_surrogate() {
    for (pattern, theta) in [("tri-tri", 0.0), ("square-tri", 0.0), ("tri-tri", 30.0)] {
        let scene = small(pattern, 12.0, theta);
        let p = params(&scene);
        assert_settles_on_the_surrogate(
            &scene,
            p,
            Start::Surrogate,
            &format!("{pattern} {theta}°"),
        );
    }
}

/// Falling from a 20 nm gap, the damped slider settles onto the surrogate's equilibrium.
#[test]
fn equilibrium_from_a_gap_reaches_the_surrogate_answer() {
    for (pattern, theta) in [("tri-tri", 0.0), ("square-tri", 10.2)] {
        let scene = small(pattern, 12.0, theta);
        let p = {
            let mut sp = params(&scene);
            sp.protocol.equilibrate_time = 8e-6;
            sp
        };
        let label = format!("from gap, {pattern} {theta}°");
        assert_settles_on_the_surrogate(&scene, p, Start::Gap(20e-9), &label);
    }
}

#[test]
fn undamped_run_conserves_energy() {
    let scene = small("tri-tri", 6.0, 30.0);
    let mut p = params(&scene);
    p.numerics.damping_time = f64::INFINITY;
    p.contact.gamma_n = 0.0;
    p.contact.gamma_t = 0.0;
    let Prepared {
        mut sim, stable, ..
    } = prepare(
        &scene,
        {
            let mut params = p;
            params.numerics.dt = None;
            params.numerics.dt_safety = 0.1;
            params
        },
        Start::Gap(2e-9),
        Some(Friction::Constant(Constant { mu: 0.0 })),
    )
    .unwrap();
    assert!(sim.dt <= 0.1 * stable.dt_crit * (1.0 + 1e-12));
    let e0 = sim.energy();
    let mut scale: f64 = 0.0; // largest kinetic + elastic exchange seen
    let mut drift: f64 = 0.0;
    for k in 0..100_000 {
        sim.step().unwrap();
        if k % 100 == 0 {
            let e = sim.energy();
            drift = drift.max((e - e0).abs());
            // energy released by the fall: W·(Z0 − Z)
            scale = scale
                .max(sim.params.protocol.load * (sim.spec.control_z - sim.state.cl_x[2]).abs());
        }
    }
    eprintln!(
        "energy: drift {drift:e} J, exchanged {scale:e} J, dt/dt_crit = {}",
        sim.dt / stable.dt_crit
    );
    assert!(sim.observe().max_overlap > 0.0, "the slider never touched");
    assert!(scale > 0.0);
    assert!(
        drift < 1e-3 * scale,
        "energy drift {drift:e} J vs exchanged {scale:e} J"
    );
}

/// A step 30× the stable one is caught and reported with the stable step, never as NaN output:
/// also with the active set when every slider sphere is free (falling from a gap), where the
/// blow-up is in the common mode of the free spheres.
#[test]
fn too_large_a_step_is_reported_not_nan() {
    let scene = small("tri-tri", 6.0, 0.0);
    for (active_set, start) in [
        (false, Start::Surrogate),
        (true, Start::Surrogate),
        (true, Start::Gap(20e-9)),
    ] {
        let p = {
            let mut sp = params(&scene);
            sp.active.enabled = active_set;
            sp
        };
        let probe = prepare(&scene, p.clone(), start, None).unwrap();
        let dt_crit = probe.stable.dt_crit;
        let Prepared { mut sim, .. } = prepare(
            &scene,
            {
                let mut params = p;
                params.numerics.dt = Some(30.0 * dt_crit);
                params
            },
            start,
            None,
        )
        .unwrap();
        let mut samples = Vec::new();
        let err = run(
            &mut sim,
            RunKind::Equilibrate,
            &RunIo::default(),
            &mut samples,
            &mut quiet(),
        )
        .expect_err("a step 30× the stable one must be caught");
        let msg = err.to_string();
        eprintln!("active set {active_set}, {start:?}: {msg}");
        assert!(matches!(err, dem::DemError::Unstable { .. }), "{msg}");
        assert!(msg.contains("stable") || msg.contains("crit"), "{msg}");
        assert!(samples
            .iter()
            .all(|s| s.z_um.is_finite() && s.z_um.abs() < 10.0 && s.p_max_gpa.is_finite()));
    }
}

/// Work cut into small chunks run in parallel (as a large scene would be): the 1-, 2- and
/// 4-thread trajectories are bit-identical.
#[test]
fn results_do_not_depend_on_the_thread_count() {
    let scene = small("square-tri", 9.0, 10.2);
    let p = {
        let mut params = slide_params(&scene);
        params.numerics.chunk_min = 4;
        params.numerics.parallel_min_work = 0;
        params
    };
    let go = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let mut sim = prepare(&scene, p.clone(), Start::Surrogate, None)
                .unwrap()
                .sim;
            let samples = run_slide(&mut sim);
            (sim.state, samples)
        })
    };
    let (a, sa) = go(1);
    // 2 threads; 4 on this 2-core machine: more threads than cores, so chunks are taken over
    // from descheduled threads (work stealing in `run_steps`'s team)
    for threads in [2, 4] {
        let (b, sb) = go(threads);
        assert!(a == b, "states differ between 1 and {threads} threads");
        assert_eq!(sa, sb);
    }
}

#[test]
fn checkpoint_and_resume_are_bit_identical() {
    let scene = small("tri-tri", 6.0, 21.8);
    let p = slide_params(&scene);
    let fresh = || {
        prepare(&scene, p.clone(), Start::Surrogate, None)
            .unwrap()
            .sim
    };
    // uninterrupted
    let mut a = fresh();
    let sa = run_slide(&mut a);
    // interrupted: the only checkpoint is written at 60 % of the run, then a new process
    // (a fresh Sim) resumes from it
    let total = a.state.step;
    let dir = std::env::temp_dir().join(format!("dem-ckpt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("run.ckpt");
    let every = total * 3 / 5;
    let mut b = fresh();
    let mut sb = Vec::new();
    let io = RunIo {
        checkpoint: Some(path.clone()),
        checkpoint_every: every,
        ..RunIo::default()
    };
    run(&mut b, RunKind::Slide, &io, &mut sb, &mut |_| {}).unwrap();
    let mut c = fresh();
    let mut sc = dem::checkpoint::load(&path, &mut c).unwrap();
    assert_eq!(c.state.step, every);
    run(
        &mut c,
        RunKind::Slide,
        &RunIo::default(),
        &mut sc,
        &mut |_| {},
    )
    .unwrap();
    assert!(a.state == c.state, "resumed state differs");
    assert_eq!(sa, sc);
    std::fs::remove_dir_all(&dir).ok();
}

/// `p_max_peak_GPa` of a sample is the largest p0 at any step since the previous sample: a run
/// sampled every 10 steps reports, at each sample, exactly the maximum of the per-step P_max of
/// the same run sampled every step (sampling does not change the trajectory), and somewhere more
/// than its own instantaneous P_max (so the column is not the instantaneous value); the slide
/// summary's `max_p_max_GPa` is the largest of them.
#[test]
fn the_peak_pressure_of_a_sample_is_the_largest_at_any_step_since_the_last() {
    let scene = small("tri-tri", 6.0, 21.8);
    let p = slide_params(&scene);
    let sampled_every = |k: f64| {
        let mut sim = prepare(&scene, p.clone(), Start::Surrogate, None)
            .unwrap()
            .sim;
        sim.params.protocol.sample_interval = k * sim.dt;
        let samples = run_slide(&mut sim);
        (sim.state, samples)
    };
    let (sa, every_step) = sampled_every(1.0);
    let (sb, every_10th) = sampled_every(10.0);
    assert!(sa == sb, "sampling changed the trajectory");
    assert!(every_10th.len() > 20 && every_step.len() > 10 * (every_10th.len() - 2));
    let mut strict = 0;
    let mut k = 1; // every_step[0] is the start, as every_10th[0]
    for w in every_10th.windows(2) {
        let (prev, b) = (w[0], w[1]);
        assert!(b.p_max_peak_gpa >= b.p_max_gpa);
        let mut peak = 0.0f64;
        while k < every_step.len() && every_step[k].t_us <= b.t_us {
            assert!(every_step[k].t_us > prev.t_us);
            peak = peak.max(every_step[k].p_max_gpa);
            k += 1;
        }
        assert_eq!(every_step[k - 1].t_us, b.t_us, "sample times differ");
        assert_eq!(b.p_max_peak_gpa, peak, "at t = {} µs", b.t_us);
        strict += (b.p_max_peak_gpa > b.p_max_gpa) as usize;
    }
    assert!(
        strict > 0,
        "no sample's peak exceeds its instantaneous P_max"
    );
    let summary = dem::protocol::slide_summary(&every_10th, &p, 0, 0.0);
    let (t0, t1) = (
        (p.protocol.equilibrate_time
            + p.protocol.relax_time
            + p.protocol.measure_from * p.protocol.slide_time)
            * 1e6,
        (p.protocol.equilibrate_time + p.protocol.relax_time + p.protocol.slide_time) * 1e6,
    );
    let in_window = every_step
        .iter()
        .filter(|s| s.t_us >= t0 - 1e-9 && s.t_us <= t1 + 1e-9)
        .map(|s| s.p_max_gpa)
        .fold(0.0, f64::max);
    assert!(
        summary.max_p_max_gpa >= in_window,
        "{} < {in_window}",
        summary.max_p_max_gpa
    );
}

/// A small slider with a constant, large μ dragged at steady state perpendicular to its contact
/// lines (square-tri θ = 0, α = 90°: near-zero corrugation): the pulling force → μW.
#[test]
fn steady_sliding_force_is_mu_w() {
    let scene = small("square-tri", 12.0, 0.0);
    let mu = 0.3;
    let p = {
        let mut params = slide_params(&scene);
        params.protocol.alpha = 90f64.to_radians();
        params.mount.rigid_z = true;
        params.protocol.equilibrate_time = 0.5e-6;
        params.protocol.relax_time = 0.5e-6;
        params.protocol.slide_time = 3e-6;
        params.protocol.support_speed = 1.0;
        params.protocol.measure_from = 1.0 / 3.0;
        params
    };
    let Prepared { mut sim, .. } = prepare(
        &scene,
        p.clone(),
        Start::Surrogate,
        Some(Friction::Constant(Constant { mu })),
    )
    .unwrap();
    let samples = run_slide(&mut sim);
    let s = dem::protocol::slide_summary(&samples, &p, sim.state.step, 0.0);
    eprintln!(
        "steady sliding: F/W = {} (μ = {mu}), contacts {}",
        s.mu, s.mean_contacts
    );
    assert!(!s.locked_in);
    assert!(
        (s.mu / mu - 1.0).abs() < 0.05,
        "spring force / W = {} (μ = {mu})",
        s.mu
    );
}

#[test]
fn lock_in_is_detected() {
    let mk = |t: f64, support: f64, slider: f64, f: f64| Sample {
        t_us: t,
        support_x_um: support,
        slider_x_um: slider,
        spring_force_mn: f,
        ..Sample::default()
    };
    let (k0, v) = (50.0, 0.1);
    // locked: the support advances 0.1 µm/µs, the slider stays, the force rises at K0·v
    let locked: Vec<Sample> = (0..100)
        .map(|k| {
            let t = k as f64;
            mk(t, 0.1 * t, 0.0, k0 * 0.1e-6 * t * 1e3)
        })
        .collect();
    let l = lock_in(&locked, k0, v, 0.5);
    assert!(l.locked_in);
    assert!((l.force_slope_ratio - 1.0).abs() < 1e-9);
    // sliding: the slider follows with a stick-slip wobble, the force is flat on average
    let sliding: Vec<Sample> = (0..100)
        .map(|k| {
            let t = k as f64;
            mk(t, 0.1 * t, 0.1 * t - 0.01 * (t * 0.7).sin(), 0.02)
        })
        .collect();
    let s = lock_in(&sliding, k0, v, 0.5);
    assert!(!s.locked_in);
    assert!((s.advance_ratio - 1.0).abs() < 0.05);
}

/// Leaving out the substrate spheres the slider can never reach changes nothing: the sliding time
/// series with and without pruning are identical to the last bit.
#[test]
fn pruning_the_substrate_is_exact() {
    let scene = small("square-tri", 9.0, 10.2);
    let series = |prune: bool| {
        let p = {
            let mut params = slide_params(&scene);
            params.active.prune_substrate = prune;
            params.mount.rigid_z = true;
            params.protocol.relax_time = 0.3e-6;
            params.protocol.slide_time = 1.5e-6;
            params
        };
        let Prepared { mut sim, start, .. } = prepare(&scene, p, Start::Surrogate, None).unwrap();
        let samples = run_slide(&mut sim);
        (samples, start.pruned)
    };
    let (full, none_pruned) = series(false);
    let (pruned, n_pruned) = series(true);
    assert_eq!(none_pruned, 0);
    assert!(
        n_pruned > 0,
        "nothing was pruned: the test would prove nothing"
    );
    assert!(full.iter().any(|s| s.contacts > 0));
    assert_eq!(full.len(), pruned.len());
    for (a, b) in full.iter().zip(&pruned) {
        assert_eq!(format!("{a:?}"), format!("{b:?}"));
    }
}

/// `run_steps(n)` (two parallel passes per step: the substrate forces are fused with the next
/// step's first pass) is bit-identical to `n` single steps, with and without the active set.
#[test]
fn pipelined_steps_equal_single_steps() {
    let scene = small("square-tri", 9.0, 10.2);
    for active_set in [false, true] {
        let p = {
            let mut params = slide_params(&scene);
            params.active.enabled = active_set;
            params.numerics.chunk_min = 4;
            params.numerics.parallel_min_work = 0;
            params
        };
        let mut a = prepare(&scene, p.clone(), Start::Surrogate, None)
            .unwrap()
            .sim;
        let mut b = prepare(&scene, p, Start::Surrogate, None).unwrap().sim;
        for s in [&mut a, &mut b] {
            s.attach_spring();
            s.start_support();
        }
        for _ in 0..3 {
            a.run_steps(700).unwrap();
            for _ in 0..700 {
                b.step().unwrap();
            }
            assert!(a.state == b.state, "active set {active_set}: states differ");
        }
    }
}
