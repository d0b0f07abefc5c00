//! Cost of one path sample of the friction estimate: the whole `estimate_friction_loads` time
//! divided by its samples, on the five scenes of `benches/friction.rs` at 1.75 mN, and on the
//! square-tri slider at radius 100 / 200 / 400 µm (substrate four times as wide) for the growth
//! with the slider's size. Prints one line per scene and a digest of the results (so two builds
//! can be compared for identical answers).
//!
//! Run: `cargo run --release -p surrogate --example path_cost [-- --sizes] [-- --reps N]
//! [-- --cold]` (`--cold`: each repetition at a θ offset by 1e-9 rad, so no kept search is
//! reused, as on a first path)
use std::time::Instant;
use surrogate::friction::{estimate_friction_loads, FrictionParams};
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::solver::Solver;
use surrogate::units::{deg_to_rad, mn_to_n, um_to_m};
use surrogate::Scene;

fn digest(e: &surrogate::friction::FrictionEstimate) -> String {
    format!(
        "{:e} {:e} {:e} {:e} {:e} {}",
        e.mu_est, e.p_max_mean, e.p_max_max, e.contacts_mean, e.barrier, e.samples
    )
}

fn time(s: &Solver, theta: f64, dir: f64, loads: &[f64], reps: usize) -> (f64, usize, String) {
    let p = FrictionParams::default();
    let t = Instant::now();
    let mut out = Vec::new();
    let cold = std::env::args().any(|a| a == "--cold");
    for k in 0..reps {
        // --cold: each repetition at θ offset by k·1e-9 rad, so no search kept by the last
        // repetition is reused (a first path's cost)
        let th = if cold { theta + k as f64 * 1e-9 } else { theta };
        out = estimate_friction_loads(s, th, dir, loads, &p).unwrap();
    }
    let dt = t.elapsed().as_secs_f64() / reps as f64;
    let e = out.pop().unwrap().unwrap();
    (dt, e.samples, digest(&e))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let reps: usize = args
        .iter()
        .position(|a| a == "--reps")
        .map(|i| args[i + 1].parse().unwrap())
        .unwrap_or(20);
    let threads = rayon::current_num_threads();
    println!("threads {threads}, reps {reps}");
    let load = [mn_to_n(1.75)];
    if args.iter().any(|a| a == "--tolerance") {
        // a tolerance-box sample of square-tri 0°/90° with the study's 11 loads
        let loads: Vec<f64> = [0.35, 0.7, 1.05, 1.4, 1.75, 2.1, 2.45, 2.8, 3.15, 3.5, 3.86]
            .iter()
            .map(|w| mn_to_n(*w))
            .collect();
        let sc = Scene::preset("square-tri").unwrap();
        let s = Solver::new(&sc).unwrap();
        for (th, al) in [(0.0, 90.0), (0.04, 90.25), (-0.1, 89.5)] {
            let theta = deg_to_rad(th);
            let dir =
                contact_line_direction(&sc, theta, &MapParams::default()).angle + deg_to_rad(al);
            let (dt, n, d) = time(&s, theta, dir, &loads, reps);
            println!(
                "square-tri θ {th}° α {al}°, 11 loads: {:.1} µs/sample ({n} samples, {:.2} ms) | {d}",
                dt / n as f64 * 1e6,
                dt * 1e3
            );
        }
        return;
    }
    if args.iter().any(|a| a == "--sizes") {
        for r_um in [100.0, 200.0, 400.0] {
            let mut sc = Scene::preset("square-tri").unwrap();
            sc.slider.radius = um_to_m(r_um);
            sc.substrate.size = [um_to_m(8.0 * r_um + 64.0), um_to_m(8.0 * r_um + 64.0)];
            let s = Solver::new(&sc).unwrap();
            let theta = deg_to_rad(10.2);
            let dir =
                contact_line_direction(&sc, theta, &MapParams::default()).angle + deg_to_rad(90.0);
            let (dt, n, d) = time(&s, theta, dir, &load, reps.div_ceil(4));
            println!(
                "radius {r_um} µm ({} spheres): {:.1} µs/sample ({n} samples, {:.2} ms) | {d}",
                s.slider_count(),
                dt / n as f64 * 1e6,
                dt * 1e3
            );
        }
        return;
    }
    let mut total = 0.0;
    let mut samples = 0;
    for (pattern, theta_deg, alpha_deg) in [
        ("square-tri", 0.0f64, 90.0f64),
        ("square-tri", 0.0, 0.0),
        ("square-tri", 10.2, 90.0),
        ("tri-tri", 30.0, 90.0),
        ("square-tri", 0.1, 90.5),
    ] {
        let sc = Scene::preset(pattern).unwrap();
        let s = Solver::new(&sc).unwrap();
        let theta = deg_to_rad(theta_deg);
        let dir =
            contact_line_direction(&sc, theta, &MapParams::default()).angle + deg_to_rad(alpha_deg);
        let (dt, n, d) = time(&s, theta, dir, &load, reps);
        total += dt;
        samples += n;
        println!(
            "{pattern} θ {theta_deg}° α {alpha_deg}°: {:.1} µs/sample ({n} samples, {:.2} ms) | {d}",
            dt / n as f64 * 1e6,
            dt * 1e3
        );
    }
    println!(
        "all five: {:.1} µs/sample ({samples} samples, {:.1} ms)",
        total / samples as f64 * 1e6,
        total * 1e3
    );
}
