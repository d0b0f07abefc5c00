//! Criterion benchmarks of the screening tier (issue 2):
//! - one (θ, W) equilibrium of the study's 3505-sphere slider (grid vs parry3d BVH search,
//!   rigid-z vs rigid-tilt vs compliant),
//! - cost vs slider radius (50, 100, 200, 400 µm; substrate 900×900 µm),
//! - one θ of the orientation sweep (4 loads sharing one pair list).
//!
//! Run: `cargo bench --bench screen -- --warm-up-time 1 --measurement-time 3`
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use surrogate::solver::{Model, Pose, SearchKind, Solver};
use surrogate::Scene;

fn pose(deg: f64) -> Pose {
    Pose {
        theta: deg.to_radians(),
        shift: [0.0, 0.0],
    }
}

fn single(c: &mut Criterion) {
    let mut g = c.benchmark_group("single_equilibrium_3505");
    g.sample_size(20);
    for search in [SearchKind::Grid, SearchKind::Bvh] {
        let mut s = Solver::new(&Scene::preset("tri-tri").unwrap()).unwrap();
        s.search = search;
        for deg in [0.0, 10.0] {
            g.bench_function(
                format!("tri-tri_theta{deg}_3.86mN_rigid-z_{search:?}"),
                |b| b.iter(|| black_box(s.solve(pose(deg), 3.86e-3, Model::RigidZ).unwrap())),
            );
        }
        g.bench_function(format!("pairs_only_theta10_{search:?}"), |b| {
            b.iter(|| black_box(s.pairs_at(pose(10.0))))
        });
    }
    let mut sc = Scene::preset("tri-tri").unwrap();
    sc.substrate.sigma_h = 0.01e-6;
    let s = Solver::new(&sc).unwrap();
    for m in [Model::RigidZ, Model::RigidTilt, Model::Compliant] {
        g.bench_function(format!("sigma_h_0.01um_theta0_3.86mN_{}", m.name()), |b| {
            b.iter(|| black_box(s.solve(pose(0.0), 3.86e-3, m).unwrap()))
        });
    }
    g.finish();
}

fn sweep_theta(c: &mut Criterion) {
    let loads = [0.35e-3, 1.4e-3, 2.1e-3, 3.86e-3];
    let mut g = c.benchmark_group("one_theta_4_loads");
    g.sample_size(20);
    for p in ["tri-tri", "square-tri"] {
        let s = Solver::new(&Scene::preset(p).unwrap()).unwrap();
        g.bench_function(p, |b| {
            b.iter(|| black_box(s.solve_loads(pose(12.3), &loads, Model::Auto)))
        });
    }
    g.finish();
}

fn radius(c: &mut Criterion) {
    let mut g = c.benchmark_group("radius_scaling_rigid-z_theta10_per_sphere_load");
    g.sample_size(10);
    for r in [50.0, 100.0, 200.0, 400.0] {
        let mut sc = Scene::preset("tri-tri").unwrap();
        sc.slider.radius = r * 1e-6;
        sc.substrate.size = [900e-6, 900e-6];
        let s = Solver::new(&sc).unwrap();
        let w = 1.1e-6 * s.slider_count() as f64; // same mean load per sphere as 3.86 mN / 3505
        g.bench_with_input(BenchmarkId::from_parameter(r), &r, |b, _| {
            b.iter(|| black_box(s.solve(pose(10.0), w, Model::RigidZ).unwrap()))
        });
    }
    g.finish();
}

criterion_group!(benches, single, sweep_theta, radius);
criterion_main!(benches);
