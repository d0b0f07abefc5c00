//! Criterion benchmark of the surrogate friction estimate (issue 8): one (θ, α, W) of the study's
//! 3505-sphere sliders with the default `FrictionParams` (one lattice period along lattice
//! directions, 12 µm otherwise, step ≤ 0.05 µm):
//! - square-tri θ = 0, α = 90° (the design point; one 3√3 µm period: 105 samples),
//! - square-tri θ = 0, α = 0° (along the contact lines; one 3 µm period: 61 samples),
//! - square-tri θ = 10.2°, α = 90° and tri-tri θ = 30°, α = 90° (quasi-periodic: 12 µm, 241
//!   samples),
//! - square-tri θ = 0.1°, α = 90.5° (quasi-periodic, and the slider drifts off the placement's
//!   crest: the drift check, the line across the pull and the path from the new start; the worst
//!   case of the defaults).
//!
//! And the unit of `superlube friction` and `superlube design`: the study's 11 loads
//! (0.35 … 3.86 mN) of one (θ, α) sharing one path (`estimate_friction_loads`), per (θ, α):
//! divide by 11 for the cost per (θ, α, W).
//!
//! Run: `cargo bench --bench friction -- --warm-up-time 1 --measurement-time 5`
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use surrogate::friction::{estimate_friction, estimate_friction_loads, FrictionParams};
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::solver::Solver;
use surrogate::Scene;

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("friction_estimate_3505");
    g.sample_size(10);
    let p = FrictionParams::default();
    for (pattern, theta_deg, alpha_deg) in [
        ("square-tri", 0.0f64, 90.0f64),
        ("square-tri", 0.0, 0.0),
        ("square-tri", 10.2, 90.0),
        ("tri-tri", 30.0, 90.0),
        // the slider drifts off the crest into a groove: the transverse line and a second path
        ("square-tri", 0.1, 90.5),
    ] {
        let sc = Scene::preset(pattern).unwrap();
        let s = Solver::new(&sc).unwrap();
        assert_eq!(s.slider_count(), 3505);
        let theta = theta_deg.to_radians();
        let dir = contact_line_direction(&sc, theta, &MapParams::default()).angle
            + alpha_deg.to_radians();
        let e = estimate_friction(&s, theta, dir, 1.4e-3, &p).unwrap();
        eprintln!(
            "{pattern} θ {theta_deg}° α {alpha_deg}°, 1.4 mN: μ_est {:.5} (coating {:.5}, PT {:.5}, η {:.2}), {} samples over {:.2} µm",
            e.mu_est,
            e.mu_coating,
            e.mu_corrugation,
            e.eta,
            e.samples,
            e.length * 1e6
        );
        g.bench_function(
            format!("{pattern}_theta{theta_deg}_alpha{alpha_deg}_1.4mN"),
            |b| b.iter(|| black_box(estimate_friction(&s, theta, dir, 1.4e-3, &p).unwrap())),
        );
        let loads: Vec<f64> = [0.35, 0.7, 1.05, 1.4, 1.75, 2.1, 2.45, 2.8, 3.15, 3.5, 3.86]
            .iter()
            .map(|w| w * 1e-3)
            .collect();
        g.bench_function(
            format!("{pattern}_theta{theta_deg}_alpha{alpha_deg}_11_loads"),
            |b| b.iter(|| black_box(estimate_friction_loads(&s, theta, dir, &loads, &p).unwrap())),
        );
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
