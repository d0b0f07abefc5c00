//! Criterion benchmark of the DEM engine on the study's scene: square-tri, θ = 0, W = 1.4 mN,
//! 3505 slider spheres over the 364 × 270 µm substrate, sliding along α = 90° (support moving).
//! One iteration = 100 velocity-Verlet steps (forces, neighbour checks, damping, springs).
//! Variants: the full model, `rigid_z` (slider spheres follow the control layer in z), and
//! `rigid_z + prune` (untouchable substrate spheres left out). Particle-steps/s = 100 × particles
//! / (time per iteration); the particle counts are printed once per variant.
//!
//! Run: `cargo bench --bench dem -- --warm-up-time 1 --measurement-time 3`.
use criterion::{criterion_group, criterion_main, Criterion};
use dem::{prepare, SimParams, Start};
use surrogate::Scene;

fn engine(c: &mut Criterion) {
    let scene = Scene::preset("square-tri").expect("preset");
    let mut group = c.benchmark_group("dem_study_scene_100_steps");
    group.sample_size(10);
    for (name, rigid_z, prune) in [
        ("full", false, false),
        ("rigid_z", true, false),
        ("rigid_z_prune", true, true),
    ] {
        let params = SimParams {
            load: 1.4e-3,
            alpha: 90f64.to_radians(),
            rigid_z,
            prune_substrate: prune,
            ..SimParams::default()
        };
        let mut sim = prepare(&scene, params, Start::Surrogate, None)
            .expect("prepare the study scene")
            .sim;
        sim.attach_spring();
        sim.start_support();
        eprintln!(
            "{name}: {} particles, dt = {:.4e} µs",
            sim.particles(),
            sim.dt * 1e6
        );
        group.bench_function(name, |b| {
            b.iter(|| {
                for _ in 0..100 {
                    sim.step().expect("stable step");
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, engine);
criterion_main!(benches);
