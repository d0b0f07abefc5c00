//! Criterion benchmarks of the corrugation-map tier (issue 3), on the study's 3505-sphere
//! square-on-triangle slider at θ = 0, W = 1.4 mN:
//! - `landscape_51x51`: the 51×51 Δz landscape over the 3 µm × 3√3 µm repeat cell (2601 solves);
//! - `corrugation_sweep/direct`: α = 0:90:1 (91 paths of 30 µm, sampled every 0.5 µm: 61 solves
//!   per path, 5551 solves);
//! - `corrugation_sweep/from_landscape`: the same sweep interpolated from one 51×51 landscape
//!   (sampled every 0.05 µm; the landscape's own cost is the first benchmark).
//!
//! Before timing, the interpolation error of the landscape fast path against direct solves is
//! measured on a subset of angles and printed (max |Δ corrugation| in nm), so that every speed
//! figure comes with its error against the more exact model.
//!
//! Run: `cargo bench --bench landscape -- --warm-up-time 1 --measurement-time 3`.
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use surrogate::map::{
    compute_landscape, contact_line_direction, corrugation_direct, corrugation_from_landscape,
    MapParams,
};
use surrogate::solver::Solver;
use surrogate::Scene;

const W: f64 = 1.4e-3;

fn alphas() -> Vec<f64> {
    (0..=90).map(|a| (a as f64).to_radians()).collect()
}

fn report_interpolation_error(solver: &Solver, params: &MapParams) {
    let l = compute_landscape(solver, 0.0, W, params, &|| {}).unwrap();
    let line = contact_line_direction(solver.scene(), 0.0, params).angle;
    let sub: Vec<f64> = [0.0f64, 10.0, 30.0, 45.0, 60.0, 80.0, 90.0]
        .iter()
        .map(|a| a.to_radians())
        .collect();
    let direct = corrugation_direct(solver, 0.0, W, line, &sub, params, &|| {}).unwrap();
    let fast = corrugation_from_landscape(&l, line, &sub, params).unwrap();
    let mut worst: f64 = 0.0;
    let mut worst_rel: f64 = 0.0;
    let mut worst_f: f64 = 0.0;
    for (d, f) in direct.iter().zip(&fast) {
        let e = (d.corrugation - f.corrugation).abs();
        worst = worst.max(e);
        worst_rel = worst_rel.max(e / d.corrugation.max(1e-12));
        worst_f = worst_f.max((d.max_lateral_force - f.max_lateral_force).abs());
        eprintln!(
            "alpha {:5.1} deg: direct {:8.4} nm / {:.5} mN, landscape-interpolated {:8.4} nm / {:.5} mN",
            d.alpha.to_degrees(),
            d.corrugation * 1e9,
            d.max_lateral_force * 1e3,
            f.corrugation * 1e9,
            f.max_lateral_force * 1e3
        );
    }
    eprintln!(
        "interpolation error (51x51 landscape vs direct solves, 30 um paths every {} um): max |d corrugation| = {:.4} nm (max rel {:.2e}), max |d lateral force| = {:.5} mN",
        params.step * 1e6,
        worst * 1e9,
        worst_rel,
        worst_f * 1e3
    );
}

fn bench(c: &mut Criterion) {
    let scene = Scene::preset("square-tri").unwrap();
    let solver = Solver::new(&scene).unwrap();
    assert_eq!(solver.slider_count(), 3505);
    let params = MapParams::default();
    report_interpolation_error(&solver, &params);

    let mut g = c.benchmark_group("landscape");
    g.sample_size(10);
    g.bench_function("landscape_51x51_square-tri_1.4mN", |b| {
        b.iter(|| black_box(compute_landscape(&solver, 0.0, W, &params, &|| {}).unwrap()))
    });
    g.finish();

    let line = contact_line_direction(&scene, 0.0, &params).angle;
    let a = alphas();
    let coarse = MapParams {
        step: 0.5e-6,
        ..params
    };
    let l = compute_landscape(&solver, 0.0, W, &params, &|| {}).unwrap();
    let mut g = c.benchmark_group("corrugation_sweep");
    g.sample_size(10);
    g.bench_function("direct_alpha_0-90-1_step0.5um", |b| {
        b.iter(|| {
            black_box(corrugation_direct(&solver, 0.0, W, line, &a, &coarse, &|| {}).unwrap())
        })
    });
    g.bench_function("from_landscape_alpha_0-90-1_step0.05um", |b| {
        b.iter(|| black_box(corrugation_from_landscape(&l, line, &a, &params).unwrap()))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
