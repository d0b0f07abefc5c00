//! Criterion benchmarks of the DEM tier: `STEPS` velocity-Verlet steps of the study scene
//! (square slider on triangular substrate, θ = 0, W = 1.4 mN, started at the surrogate's
//! equilibrium; sliding at 0.1 m/s perpendicular to the contact lines unless "equilibrate") per
//! model: the full model integrating every particle (the LAMMPS-comparable engine), and the
//! models as `--model full|reduced` run them (prune + active set).
//!
//! Throughput is reported in particle-steps (criterion's "elements"/s), the particle count
//! being the model's own (`Sim::particles`: substrate + slider + control body), whether or not
//! the active set integrates them all. Thread scaling: run with `RAYON_NUM_THREADS=1`, `=2`, …;
//! `..._forced_parallel` always runs the passes on the team of threads (the others let
//! `run_steps` pick the faster of the team and one thread, which on a loaded machine can be one
//! thread).
//!
//! Run: `cargo bench --bench dem -- --warm-up-time 1 --measurement-time 3`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use dem::{prepare, SimParams, Start};

/// Steps per benchmark iteration (one `run_steps` call, which starts its team of threads once:
/// the protocol calls it with hundreds to thousands of steps per sample).
const STEPS: u64 = 200;

fn study_sim(rigid_z: bool, prune: bool, active_set: bool, slide: bool, forced: bool) -> dem::Sim {
    let scene = surrogate::Scene::preset("square-tri").expect("preset square-tri");
    let params = SimParams {
        protocol: dem::ProtocolParams {
            load: 1.4e-3,
            alpha: 90f64.to_radians(),
            ..Default::default()
        },
        mount: dem::MountParams {
            rigid_z,
            ..Default::default()
        },
        numerics: dem::NumericsParams {
            // 0: always run the eligible passes in parallel (no timing probes)
            parallel_min_work: if forced {
                0
            } else {
                SimParams::default().numerics.parallel_min_work
            },
            ..Default::default()
        },
        active: dem::ActiveSetParams {
            prune_substrate: prune,
            enabled: active_set,
            ..Default::default()
        },
        ..SimParams::default()
    };
    let mut sim = prepare(&scene, params, Start::Surrogate, None)
        .expect("study scene prepares")
        .sim;
    if slide {
        // release the hold, attach the spring and start the support, as in the protocol
        sim.attach_spring();
        sim.start_support();
    }
    sim
}

fn models(c: &mut Criterion) {
    let mut g = c.benchmark_group("dem_study_scene_steps");
    g.sample_size(10);
    for (name, rigid_z, prune, active, slide, forced) in [
        (
            "full_all_particles_equilibrate",
            false,
            false,
            false,
            false,
            false,
        ),
        (
            "full_all_particles_equilibrate_forced_parallel",
            false,
            false,
            false,
            false,
            true,
        ),
        ("full_all_particles", false, false, false, true, false),
        ("full_prune_active_set", false, true, true, true, false),
        ("reduced_prune", true, true, false, true, false),
        ("reduced_prune_active_set", true, true, true, true, false),
    ] {
        let sim = study_sim(rigid_z, prune, active, slide, forced);
        eprintln!(
            "{name}: {} particles ({} integrated now), dt = {:.4e} µs (stable-step estimate {:.4e} µs), {} threads",
            sim.particles(),
            sim.active_particles(),
            sim.dt * 1e6,
            sim.dt_crit * 1e6,
            rayon::current_num_threads()
        );
        g.throughput(Throughput::Elements(STEPS * sim.particles() as u64));
        let mut running = sim;
        g.bench_function(name, |b| {
            b.iter(|| running.run_steps(STEPS).expect("stable"))
        });
    }
    g.finish();
}

criterion_group!(benches, models);
criterion_main!(benches);
