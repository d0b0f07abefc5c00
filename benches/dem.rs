//! Criterion benchmarks of the DEM tier: `STEPS` velocity-Verlet steps of the study scene
//! (square slider on triangular substrate, θ = 0, W = 1.4 mN, started at the surrogate's
//! equilibrium, sliding at 0.1 m/s) per model: the full model and each reduction.
//!
//! Throughput is reported in particle-steps (criterion's "elements"/s), the particle count
//! being the model's own (`Sim::particles`: substrate + slider + control + support), so pruned
//! models are charged only for the particles they keep. Compare models by the time per
//! *simulated µs* (time per step / dt), which criterion does not print: see the README.
//!
//! Run: `cargo bench --bench dem -- --warm-up-time 1 --measurement-time 3`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use dem::{prepare, SimParams, Start};

/// Steps per benchmark iteration.
const STEPS: u64 = 20;

fn study_sim(rigid_z: bool, prune: bool) -> dem::Sim {
    let scene = surrogate::Scene::preset("square-tri").expect("preset square-tri");
    let params = SimParams {
        load: 1.4e-3,
        rigid_z,
        prune_substrate: prune,
        ..SimParams::default()
    };
    let mut sim = prepare(&scene, params, Start::Surrogate, None)
        .expect("study scene prepares")
        .sim;
    // slide: release the hold, attach the spring and start the support, as in the protocol
    sim.attach_spring();
    sim.start_support();
    sim
}

fn models(c: &mut Criterion) {
    let mut g = c.benchmark_group("dem_study_scene_steps");
    g.sample_size(10);
    for (name, rigid_z, prune) in [
        ("full", false, false),
        ("prune", false, true),
        ("rigid_z", true, false),
        ("rigid_z+prune", true, true),
    ] {
        let sim = study_sim(rigid_z, prune);
        eprintln!(
            "{name}: {} particles, dt = {:.4e} µs (stable-step estimate {:.4e} µs)",
            sim.particles(),
            sim.dt * 1e6,
            sim.dt_crit * 1e6
        );
        g.throughput(Throughput::Elements(STEPS * sim.particles() as u64));
        let mut running = sim;
        g.bench_function(name, |b| {
            b.iter(|| {
                for _ in 0..STEPS {
                    running.step().expect("stable");
                }
            })
        });
    }
    g.finish();
}

criterion_group!(benches, models);
criterion_main!(benches);
