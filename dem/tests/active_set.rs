//! The active set: integrating only the particles in or near contact or still ringing gives
//! the same time series as integrating every particle (within the stated tolerance), picks up
//! new contacts before they touch, and keeps the engine deterministic and resumable.

mod common;
use common::*;
use dem::protocol::{run, RunIo, RunKind};
use dem::{prepare, Start};
use std::collections::BTreeSet;

/// The tolerance this engine states for the active set (relative, per time-series column).
const STATED: f64 = 1e-6;

/// A short slide over a small square-on-triangle slider at 1 m/s: contacts are made and broken
/// (the contact count changes along the path), spheres ring down after losing contact and
/// leave the set. With and without the active set, full and reduced model: equal time series
/// within the stated tolerance.
#[test]
fn active_set_gives_the_same_time_series() {
    let scene = small("square-tri", 12.0, 10.2);
    for rigid_z in [false, true] {
        let series = |active_set: bool| {
            let p = {
                let mut params = slide_params(&scene);
                params.mount.rigid_z = rigid_z;
                params.active.enabled = active_set;
                params.protocol.equilibrate_time = 0.3e-6;
                params.protocol.relax_time = 0.3e-6;
                params.protocol.slide_time = if rigid_z { 4e-6 } else { 1.5e-6 };
                params.protocol.support_speed = 1.0;
                params.protocol.sample_interval = 0.01e-6;
                params
            };
            let mut sim = prepare(&scene, p, Start::Surrogate, None).unwrap().sim;
            let s = run_slide(&mut sim);
            (s, sim)
        };
        let (all, full) = series(false);
        let (act, sim) = series(true);
        let d = max_rel_diff(&all, &act);
        let st = sim.state.stats;
        let mean_active = st.particle_steps as f64 / sim.state.step as f64;
        let total = sim.n_slider() + sim.n_substrate();
        let contacts: BTreeSet<usize> = act.iter().map(|s| s.contacts).collect();
        eprintln!(
            "rigid_z {rigid_z}: max rel diff {d:e}; contacts seen {contacts:?}; {} evaluations, {} activations, {} deactivations, mean active {mean_active:.1} of {total}",
            st.evaluations, st.activations, st.deactivations
        );
        assert!(d < STATED, "rigid_z {rigid_z}: active set differs by {d:e}");
        assert!(contacts.len() > 2, "contacts must be made and broken");
        assert!(st.activations > 0 && st.deactivations > 0);
        assert_eq!(st.late_pairs, 0, "a pair entered the set already touching");
        assert!(
            mean_active < 0.5 * total as f64,
            "the active set saved nothing"
        );
        assert_eq!(
            full.state.stats.particle_steps,
            (total * full.state.step as usize) as u64
        );
    }
}

/// Sliding a square slider across the rows of a triangular substrate (θ = 0, perpendicular to
/// the contact lines, 6 µm: more than a substrate period) brings substrate spheres under the
/// slider that were at rest (inactive) at the start: each is activated while its gap is still
/// open (no pair enters the set already touching), and the run equals the one without the
/// active set.
#[test]
fn new_contacts_are_picked_up_before_they_touch() {
    let scene = small("square-tri", 9.0, 0.0);
    let p = {
        let mut params = slide_params(&scene);
        params.mount.rigid_z = true;
        params.active.enabled = true;
        params.protocol.equilibrate_time = 0.2e-6;
        params.protocol.relax_time = 0.2e-6;
        params.protocol.slide_time = 3e-6;
        params.protocol.support_speed = 2.0;
        params.protocol.alpha = 90f64.to_radians();
        params
    };
    let mut sim = prepare(&scene, p.clone(), Start::Surrogate, None)
        .unwrap()
        .sim;
    let at_start: BTreeSet<u32> = sim.state.act.sub.iter().copied().collect();
    let mut touched: BTreeSet<u32> = BTreeSet::new();
    dem::protocol::step_slide(&mut sim, |sim| {
        let s = &sim.state;
        for (q, o) in sim.pair_results().iter().enumerate() {
            if o.delta > 0.0 {
                touched.insert(s.pairs.j[s.act.pairs[q] as usize]);
            }
        }
    })
    .unwrap();
    let new: Vec<&u32> = touched.difference(&at_start).collect();
    eprintln!(
        "{} substrate spheres active at the start, {} touched, {} of them new; late pairs {}",
        at_start.len(),
        touched.len(),
        new.len(),
        sim.state.stats.late_pairs
    );
    assert!(
        !new.is_empty(),
        "the path brought no new substrate sphere into contact"
    );
    assert_eq!(sim.state.stats.late_pairs, 0);
    // and the same run without the active set
    let mut a = prepare(&scene, p.clone(), Start::Surrogate, None)
        .unwrap()
        .sim;
    let mut b = prepare(
        &scene,
        {
            let mut params = p;
            params.active.enabled = false;
            params
        },
        Start::Surrogate,
        None,
    )
    .unwrap()
    .sim;
    let (sa, sb) = (run_slide(&mut a), run_slide(&mut b));
    let d = max_rel_diff(&sa, &sb);
    eprintln!("with vs without the active set: {d:e}");
    assert!(d < STATED);
}

/// Work cut into many small chunks run in parallel: bit-identical on 1 and 2 threads, and a
/// run checkpointed at 60 % and resumed in a fresh engine equals the uninterrupted one.
#[test]
fn active_set_runs_are_deterministic_and_resume_bit_identically() {
    let scene = small("square-tri", 9.0, 10.2);
    let p = {
        let mut params = slide_params(&scene);
        params.active.enabled = true;
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
            let s = run_slide(&mut sim);
            (sim.state, s)
        })
    };
    let (a, sa) = go(1);
    let (b, sb) = go(2);
    assert!(a == b, "states differ between 1 and 2 threads");
    assert_eq!(sa, sb);
    let dir = tmpdir("active-resume");
    let path = dir.join("run.ckpt");
    let every = a.step * 3 / 5;
    let mut c = prepare(&scene, p.clone(), Start::Surrogate, None)
        .unwrap()
        .sim;
    let io = RunIo {
        checkpoint: Some(path.clone()),
        checkpoint_every: every,
        ..RunIo::default()
    };
    let mut sc = Vec::new();
    run(&mut c, RunKind::Slide, &io, &mut sc, &mut |_| {}).unwrap();
    let mut d = prepare(&scene, p, Start::Surrogate, None).unwrap().sim;
    let mut sd = dem::checkpoint::load(&path, &mut d).unwrap();
    assert_eq!(d.state.step, every);
    run(
        &mut d,
        RunKind::Slide,
        &RunIo::default(),
        &mut sd,
        &mut |_| {},
    )
    .unwrap();
    assert!(a == d.state, "resumed state differs");
    assert_eq!(sa, sd);
    std::fs::remove_dir_all(&dir).ok();
}
