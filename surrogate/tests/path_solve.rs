//! The continued path solve (`Solver::solve_along_loads`: pair lists with a height skin, warm
//! starts from the previous sample) against a fresh solve at every sample, and its determinism.
//! `docs/validation/path-solve.md` says why and what it costs.
use surrogate::solver::{Equilibrium, Model, Pose, Solver, StraightPath};
use surrogate::Scene;

const DEG: f64 = std::f64::consts::PI / 180.0;

fn small(pattern: &str, sigma_h: f64) -> Scene {
    sized(pattern, sigma_h, 20e-6)
}

fn sized(pattern: &str, sigma_h: f64, radius: f64) -> Scene {
    let mut s = Scene::preset(pattern).unwrap();
    s.slider.radius = radius;
    s.substrate.size = [4.0 * radius + 20e-6, 4.0 * radius + 20e-6];
    s.substrate.sigma_h = sigma_h;
    s
}

fn contact_set(eq: &Equilibrium) -> Vec<(u32, u32)> {
    eq.contacts
        .iter()
        .map(|c| (c.slider, c.substrate))
        .collect()
}

/// Asserts that `a` (continued) and `b` (fresh) are the same equilibrium to the solver's
/// tolerances: height within 1e-8 of the deepest overlap, tilts within 1e-6 of it at the rim,
/// P_max within 1e-8, the same contacts (but for grazing ones, overlap below 1e-6 of the deepest).
fn assert_same(a: &Equilibrium, b: &Equilibrium, rim: f64, what: &str) {
    let depth = b.contacts.iter().map(|c| c.overlap).fold(0.0, f64::max);
    assert!(depth > 0.0, "{what}: no contact");
    assert!(
        (a.z - b.z).abs() <= 1e-8 * depth,
        "{what}: z {} vs {}",
        a.z,
        b.z
    );
    for k in 0..2 {
        assert!(
            (a.tilt[k] - b.tilt[k]).abs() * rim <= 1e-6 * depth,
            "{what}: tilt {:?} vs {:?}",
            a.tilt,
            b.tilt
        );
    }
    assert!((a.p_max - b.p_max).abs() <= 1e-8 * b.p_max, "{what}: P_max");
    let firm = |e: &Equilibrium| -> Vec<(u32, u32)> {
        e.contacts
            .iter()
            .filter(|c| c.overlap > 1e-6 * depth)
            .map(|c| (c.slider, c.substrate))
            .collect()
    };
    assert_eq!(firm(a), firm(b), "{what}: contacts");
    // a continued path stays on the tilt model once a sample escalated; where a fresh solve
    // finds the untilted state balanced, the tilt model's answer is that state (checked above)
    assert!(
        a.model == b.model || (a.model == Model::RigidTilt && b.model == Model::RigidZ),
        "{what}: model {:?} vs {:?}",
        a.model,
        b.model
    );
    for e in [a, b] {
        assert!(
            e.residual_rel() <= 2e-12,
            "{what}: force residual {}",
            e.residual
        );
    }
}

/// A commensurate path (tri-tri 0° along x), an incommensurate one (square-tri 10.2° at 13°, on
/// a rough substrate: every pose escalates to the tilt model) and a stick-slip one (square-tri
/// 0° along x, the study's stick-slip case): continued and fresh agree at every sample and load;
/// on the incommensurate path the contact set changes at every sample.
#[test]
fn continued_path_equals_fresh_solves() {
    let s: Vec<f64> = (0..=30).map(|k| k as f64 * 0.2e-6).collect();
    let loads = [0.2e-3, 0.6e-3];
    for (name, sc, theta, dir) in [
        ("commensurate", small("tri-tri", 0.0), 0.0, 0.0),
        (
            "incommensurate",
            sized("square-tri", 0.01e-6, 40e-6),
            10.2 * DEG,
            13.0 * DEG,
        ),
        ("stick-slip", sized("square-tri", 0.0, 40e-6), 0.0, 0.0),
    ] {
        let solver = Solver::new(&sc).unwrap();
        let path = StraightPath {
            theta,
            origin: [0.13e-6, -0.07e-6],
            e: [dir.cos(), dir.sin()],
            s: &s,
            segment: 0.5e-6,
        };
        let along = solver.solve_along_loads(path, &loads, Model::Auto, |_, _, eq| eq);
        let rim = sc.slider.radius;
        for (j, r) in along.iter().enumerate() {
            let eqs = r.as_ref().unwrap();
            assert_eq!(eqs.len(), s.len());
            let mut changes = 0;
            for (k, (si, eq)) in s.iter().zip(eqs).enumerate() {
                let pose = Pose {
                    theta,
                    shift: [
                        path.origin[0] + si * path.e[0],
                        path.origin[1] + si * path.e[1],
                    ],
                };
                let fresh = solver.solve(pose, loads[j], Model::Auto).unwrap();
                assert_same(eq, &fresh, rim, &format!("{name} load {j} sample {k}"));
                if k > 0 && contact_set(eq) != contact_set(&eqs[k - 1]) {
                    changes += 1;
                }
            }
            if name != "incommensurate" {
                // rows of spheres move in step: the set changes where they cross to new sites
                assert!(changes >= 1, "{name}: the contact set never changes");
            } else {
                assert_eq!(changes, s.len() - 1, "{name}: a contact set repeats");
            }
        }
    }
}

/// Each load's equilibria do not depend on which other loads share the path, nor on the number
/// of threads (the chunks are cut by the path, not by the threads).
#[test]
fn path_solve_is_deterministic() {
    let sc = small("square-tri", 0.002e-6);
    let solver = Solver::new(&sc).unwrap();
    let s: Vec<f64> = (0..=80).map(|k| k as f64 * 0.05e-6).collect();
    let path = StraightPath {
        theta: 7.3 * DEG,
        origin: [0.0, 0.0],
        e: [(82.5 * DEG).cos(), (82.5 * DEG).sin()],
        s: &s,
        segment: 0.5e-6,
    };
    let loads = [0.35e-3, 1.75e-3, 3.86e-3];
    let run = |threads: usize, loads: &[f64]| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                solver
                    .solve_along_loads(path, loads, Model::Auto, |_, _, eq| eq)
                    .into_iter()
                    .map(|r| format!("{:?}", r.unwrap()))
                    .collect::<Vec<_>>()
            })
    };
    let one = run(1, &loads);
    assert_eq!(one, run(2, &loads));
    for (j, w) in loads.iter().enumerate() {
        assert_eq!(one[j], run(2, &[*w]).pop().unwrap(), "load {j} alone");
    }
}
