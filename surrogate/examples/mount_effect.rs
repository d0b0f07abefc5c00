//! How much the slider mount (locked | springs K1 = 10⁶ N/m | free) changes the screen's answers
//! (issue 7, point 1). Prints markdown tables:
//! (a) the study's screens (tri-tri and square-tri, θ = 0:30:0.1, W = 0.35, 1.4, 2.1, 3.86 mN);
//! (b) σ_h = 0.002 and 0.01 µm, seeds 1–3, both patterns, same loads, θ = 0:30:1;
//! (c) the offset and edge examples.
//! Every solve uses `Model::Auto` (rigid-z, escalating to rigid-tilt where the mount tilts and
//! the rigid-z answer leaves a moment).
//!
//! Run: `cargo run --release -p surrogate --example mount_effect`
use rayon::prelude::*;
use surrogate::solver::{Equilibrium, Model, Pose, Solver};
use surrogate::{Mount, Scene};

const LOADS: [f64; 4] = [0.35e-3, 1.4e-3, 2.1e-3, 3.86e-3];
const MOUNTS: [(&str, Mount); 3] = [
    ("locked", Mount::Locked),
    ("springs", Mount::Springs { k1: 1e6 }),
    ("free", Mount::Free),
];

/// (contacts, P_max in Pa, coating failed, model) per (θ, W) row.
type Row = (usize, f64, bool, Model);

fn sweep(scene: &Scene, thetas: &[f64]) -> Vec<Row> {
    let s = Solver::new(scene).unwrap();
    let per: Vec<Vec<Row>> = thetas
        .par_iter()
        .map(|&t| {
            let p = Pose {
                theta: t.to_radians(),
                shift: [0.0, 0.0],
            };
            s.solve_loads(p, &LOADS, Model::Auto)
                .into_iter()
                .map(|r| {
                    let e: Equilibrium = r.unwrap();
                    (e.contact_count(), e.p_max, e.coating_failed(), e.model)
                })
                .collect()
        })
        .collect();
    per.into_iter().flatten().collect()
}

#[derive(Default)]
struct Diff {
    rows: usize,
    max_dp: f64,
    sum_dp: f64,
    max_rel: f64,
    sum_rel: f64,
    contact_rows: usize,
    max_dc: usize,
    flips: usize,
    identical: usize,
}

impl Diff {
    fn add(&mut self, a: &[Row], b: &[Row]) {
        for (x, y) in a.iter().zip(b) {
            let dp = (x.1 - y.1).abs();
            self.rows += 1;
            self.max_dp = self.max_dp.max(dp);
            self.sum_dp += dp;
            self.max_rel = self.max_rel.max(dp / x.1);
            self.sum_rel += dp / x.1;
            if x.0 != y.0 {
                self.contact_rows += 1;
                self.max_dc = self.max_dc.max(x.0.abs_diff(y.0));
            }
            self.flips += (x.2 != y.2) as usize;
            self.identical += (x.0 == y.0 && x.1 == y.1) as usize;
        }
    }
    fn print(&self, what: &str) {
        let n = self.rows.max(1) as f64;
        println!(
            "| {what} | {} | {} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {} | {} | {} |",
            self.rows,
            self.identical,
            self.max_dp / 1e9,
            self.sum_dp / n / 1e9,
            100.0 * self.max_rel,
            100.0 * self.sum_rel / n,
            self.contact_rows,
            self.max_dc,
            self.flips
        );
    }
}

fn header() {
    println!("| comparison | rows | identical rows | max abs ΔP_max (GPa) | mean abs ΔP_max (GPa) | max abs ΔP_max (%) | mean abs ΔP_max (%) | rows with other contact number | max abs Δcontacts | coating verdict flips |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
}

fn with_mount(s: &Scene, m: Mount) -> Scene {
    let mut s = s.clone();
    s.slider.mount = m;
    s
}

fn compare(groups: &[(String, Vec<Scene>)], thetas: &[f64]) {
    header();
    for (name, scenes) in groups {
        let res: Vec<Vec<Vec<Row>>> = MOUNTS
            .iter()
            .map(|(_, m)| {
                scenes
                    .iter()
                    .map(|s| sweep(&with_mount(s, *m), thetas))
                    .collect()
            })
            .collect();
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            let mut d = Diff::default();
            for (a, b) in res[i].iter().zip(&res[j]) {
                d.add(a, b);
            }
            d.print(&format!("{name}: {} vs {}", MOUNTS[j].0, MOUNTS[i].0));
        }
        for (k, (mname, _)) in MOUNTS.iter().enumerate() {
            let esc: usize = res[k]
                .iter()
                .flatten()
                .filter(|r| r.3 != Model::RigidZ)
                .count();
            let n: usize = res[k].iter().map(|v| v.len()).sum();
            println!("|   {name}, {mname}: auto escalated to rigid-tilt in {esc} of {n} rows | | | | | | | | | |");
        }
    }
}

fn main() {
    let t0 = std::time::Instant::now();
    println!("(a) study screens, θ = 0:30:0.1, W = 0.35, 1.4, 2.1, 3.86 mN, default placement\n");
    let thetas: Vec<f64> = (0..=300).map(|k| k as f64 * 0.1).collect();
    let groups: Vec<(String, Vec<Scene>)> = ["tri-tri", "square-tri"]
        .iter()
        .map(|p| (p.to_string(), vec![Scene::preset(p).unwrap()]))
        .collect();
    compare(&groups, &thetas);

    println!("\n(b) σ_h scenes, seeds 1–3, θ = 0:30:1, same loads, default placement\n");
    let thetas: Vec<f64> = (0..=30).map(|k| k as f64).collect();
    let mut groups = Vec::new();
    for p in ["tri-tri", "square-tri"] {
        for sh in [0.002e-6, 0.01e-6] {
            let scenes = (1..=3)
                .map(|seed| {
                    let mut s = Scene::preset(p).unwrap();
                    s.substrate.sigma_h = sh;
                    s.substrate.seed = seed;
                    s
                })
                .collect();
            groups.push((format!("{p}, σ_h = {} µm", sh * 1e6), scenes));
        }
    }
    compare(&groups, &thetas);

    println!("\n(c) the issue's examples\n");
    println!("| example | mount | model used | contacts | P_max (GPa) | coating | tilt (µrad) |");
    println!("|---|---|---|---|---|---|---|");
    let mut ex1 = Scene::preset("tri-tri").unwrap();
    ex1.slider.offset = [1e-6, 0.4e-6];
    let mut ex2 = Scene::preset("square-tri").unwrap();
    ex2.substrate.size = [60e-6, 60e-6];
    ex2.slider.radius = 15e-6;
    ex2.slider.offset = [25e-6, 0.0];
    for (name, sc, theta, w) in [
        (
            "tri-tri, offset (1, 0.4) µm, θ = 30°, 2.1 mN",
            &ex1,
            30.0f64,
            2.1e-3,
        ),
        (
            "square-tri, radius 15 µm at (25, 0) µm on 60×60 µm, θ = 0, 0.1 mN",
            &ex2,
            0.0,
            0.1e-3,
        ),
        (
            "square-tri, radius 15 µm at (25, 0) µm on 60×60 µm, θ = 0, 1.4 mN",
            &ex2,
            0.0,
            1.4e-3,
        ),
    ] {
        for (mname, m) in MOUNTS {
            let s = Solver::new(&with_mount(sc, m)).unwrap();
            let p = Pose {
                theta: theta.to_radians(),
                shift: [0.0, 0.0],
            };
            let e = s.solve(p, w, Model::Auto).unwrap();
            println!(
                "| {name} | {mname} | {} | {} | {:.4} | {} | ({:.3}, {:.3}) |",
                e.model.name(),
                e.contact_count(),
                e.p_max / 1e9,
                if e.coating_failed() {
                    "failed"
                } else {
                    "intact"
                },
                e.tilt[0] * 1e6,
                e.tilt[1] * 1e6
            );
        }
    }
    eprintln!("wall {:.1} s", t0.elapsed().as_secs_f64());
}
