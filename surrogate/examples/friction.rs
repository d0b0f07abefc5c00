//! Surrogate friction estimates of the study's configurations, their cost, and their error
//! against finer and longer paths.
//!
//! Run: `cargo run --release -p surrogate --example friction [-- --convergence]`
use std::time::Instant;
use surrogate::friction::{estimate_friction, FrictionEstimate, FrictionParams};
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::solver::Solver;
use surrogate::units::{deg_to_rad, m_to_um, n_to_mn, pa_to_gpa, um_to_m};
use surrogate::{Mount, Scene};

fn scene(pattern: &str, sigma_h: f64, seed: u64, mount: Mount) -> Scene {
    let mut s = Scene::preset(pattern).unwrap();
    s.substrate.sigma_h = sigma_h;
    s.substrate.seed = seed;
    s.slider.mount = mount;
    s
}

fn row(label: &str, e: &FrictionEstimate, ms: f64) {
    println!(
        "| {label} | {:.2} | {:.5} ± {:.5} | {:.5} | {:.5} | {:.5} | {:.3} | {:.3e} | {:.4} | {:.3} | {:.3} | {:.3} | {:.1} | {:.2} µm{} | {} | {:.0} |",
        n_to_mn(e.load),
        e.mu_est,
        e.mu_est_spread,
        e.mu_quasi_static,
        e.mu_coating,
        e.mu_corrugation,
        e.eta,
        e.barrier,
        n_to_mn(e.max_lateral_force),
        pa_to_gpa(e.p_max_mean),
        pa_to_gpa(e.p_max_max),
        e.failed_fraction,
        e.contacts_mean,
        m_to_um(e.length),
        if e.periodic { " (period)" } else { "" },
        e.samples,
        ms
    );
}

fn header() {
    println!("| configuration | W (mN) | μ_est ± spread | μ_qs | μ_coat | μ_PT | η | U0 (J) | max F_lat (mN) | mean P_max (GPa) | max P_max (GPa) | failed_fraction | mean contacts | path | samples | ms |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
}

/// (label, pattern, θ°, α° from the contact line, σ_h µm, seed)
const CONFIGS: &[(&str, &str, f64, f64, f64, u64)] = &[
    ("square-tri 0°, α 90°", "square-tri", 0.0, 90.0, 0.0, 1),
    ("square-tri 0°, α 0°", "square-tri", 0.0, 0.0, 0.0, 1),
    ("square-tri 10.2°, α 90°", "square-tri", 10.2, 90.0, 0.0, 1),
    ("tri-tri 30°, α 90°", "tri-tri", 30.0, 90.0, 0.0, 1),
    ("tri-tri 30°, α 0°", "tri-tri", 30.0, 0.0, 0.0, 1),
    ("tri-tri 0°, α 0°", "tri-tri", 0.0, 0.0, 0.0, 1),
    (
        "square-tri 0°, α 90°, σ_h 0.01 µm",
        "square-tri",
        0.0,
        90.0,
        0.01,
        1,
    ),
    (
        "tri-tri 30°, α 90°, σ_h 0.01 µm",
        "tri-tri",
        30.0,
        90.0,
        0.01,
        1,
    ),
];

fn main() {
    let convergence = std::env::args().any(|a| a == "--convergence");
    let loads = [0.35e-3, 1.4e-3, 2.1e-3, 3.86e-3];
    let p = FrictionParams::default();
    println!(
        "defaults: length {} µm, max period {} µm, step {} µm, K0 {} N/m, {} threads\n",
        m_to_um(p.length),
        m_to_um(p.max_period),
        m_to_um(p.step),
        p.k0,
        rayon::current_num_threads()
    );
    header();
    let mut total = 0.0;
    let mut count = 0;
    for &(label, pattern, th, al, sh, seed) in CONFIGS {
        let sc = scene(pattern, um_to_m(sh), seed, Mount::default());
        let solver = Solver::new(&sc).unwrap();
        let theta = deg_to_rad(th);
        let line = contact_line_direction(&sc, theta, &MapParams::default()).angle;
        for &w in &loads {
            let t = Instant::now();
            let e = estimate_friction(&solver, theta, line + deg_to_rad(al), w, &p).unwrap();
            let ms = t.elapsed().as_secs_f64() * 1e3;
            total += ms;
            count += 1;
            row(label, &e, ms);
        }
    }
    println!(
        "\nmean wall per estimate: {:.1} ms over {count}",
        total / count as f64
    );
    if !convergence {
        return;
    }
    println!("\nconvergence: default vs step/2, step/4, and (quasi-periodic paths) length ×2, length ×3 with step/2");
    println!("| configuration | W (mN) | variant | μ_est | μ_coat | μ_PT | η | rel. diff. μ_est vs finest |");
    println!("|---|---|---|---|---|---|---|---|");
    for &(label, pattern, th, al, sh, seed) in CONFIGS {
        let sc = scene(pattern, um_to_m(sh), seed, Mount::default());
        let solver = Solver::new(&sc).unwrap();
        let theta = deg_to_rad(th);
        let dir = contact_line_direction(&sc, theta, &MapParams::default()).angle + deg_to_rad(al);
        for &w in &[1.4e-3, 3.86e-3] {
            let variants = [
                ("default", p),
                (
                    "step/2",
                    FrictionParams {
                        step: p.step / 2.0,
                        ..p
                    },
                ),
                (
                    "step/4",
                    FrictionParams {
                        step: p.step / 4.0,
                        ..p
                    },
                ),
                (
                    "length ×2",
                    FrictionParams {
                        length: 2.0 * p.length,
                        ..p
                    },
                ),
                (
                    "length ×3, step/2",
                    FrictionParams {
                        length: 3.0 * p.length,
                        step: p.step / 2.0,
                        ..p
                    },
                ),
            ];
            let res: Vec<(&str, FrictionEstimate)> = variants
                .iter()
                .map(|(n, q)| (*n, estimate_friction(&solver, theta, dir, w, q).unwrap()))
                .collect();
            let finest = if res[0].1.periodic {
                res[2].1.mu_est
            } else {
                res[4].1.mu_est
            };
            for (n, e) in &res {
                if e.periodic && n.starts_with("length") {
                    continue;
                }
                println!(
                    "| {label} | {:.2} | {n} | {:.5} | {:.5} | {:.5} | {:.3} | {:+.2e} |",
                    n_to_mn(w),
                    e.mu_est,
                    e.mu_coating,
                    e.mu_corrugation,
                    e.eta,
                    e.mu_est / finest - 1.0
                );
            }
        }
    }
}
