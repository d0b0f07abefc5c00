//! Checks of the corrugation maps (issue 3): periodicity of the Δz landscape, symmetry of the
//! solver under a common symmetry of both lattices, corrugation along a ridge versus the
//! landscape, the square-on-triangle contact-line result at α = 0° vs 90°, bad input.

use surrogate::map::{
    compute_landscape, contact_line_direction, corrugation_direct, corrugation_from_landscape,
    path_profile, MapParams,
};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::Scene;

const W: f64 = 1.4e-3;

fn solver(pattern: &str) -> Solver {
    Solver::new(&Scene::preset(pattern).unwrap()).unwrap()
}

fn params(grid: usize) -> MapParams {
    MapParams {
        grid,
        ..MapParams::default()
    }
}

#[test]
fn landscape_is_periodic_over_the_cell() {
    for (pattern, theta) in [("square-tri", 0.0f64), ("tri-tri", 21.8)] {
        let s = solver(pattern);
        let l = compute_landscape(&s, theta.to_radians(), W, &params(7), &|| {}).unwrap();
        // The triangular substrate's rectangular cell: 3 µm × 3√3 µm.
        assert!((l.cell.a[0] - 3e-6).abs() < 1e-12 && l.cell.a[1].abs() < 1e-12);
        assert!(l.cell.b[0].abs() < 1e-12 && (l.cell.b[1] - 3e-6 * 3f64.sqrt()).abs() < 1e-12);
        // Opposite edges are the same physical configuration: equal to solver tolerance (the
        // force tolerance 1e-12·W moves z by far less than 1e-6 nm).
        assert!(
            l.edge_mismatch() < 1e-15,
            "{pattern}: edge mismatch {} m",
            l.edge_mismatch()
        );
        // …and the landscape is not trivially flat.
        assert!(l.range() > 1e-10, "{pattern}: range {}", l.range());
    }
}

/// The mirror y → −y maps the triangular substrate onto itself and a slider at θ onto the same
/// slider at −θ (both slider lattices are mirror-symmetric about x); for the triangular slider
/// the mirror about the 30° line also maps θ onto 60° − θ. Same contacts and P_max, computed
/// through different floating-point paths.
#[test]
fn symmetric_scenes_give_the_same_contacts_and_p_max() {
    for (pattern, thetas) in [
        ("tri-tri", vec![7.0f64, -7.0, 53.0]),
        ("square-tri", vec![12.4, -12.4, 102.4]),
    ] {
        let s = solver(pattern);
        let eqs: Vec<_> = thetas
            .iter()
            .map(|t| {
                s.solve(
                    Pose {
                        theta: t.to_radians(),
                        shift: [0.0, 0.0],
                    },
                    W,
                    Model::RigidZ,
                )
                .unwrap()
            })
            .collect();
        for e in &eqs[1..] {
            assert_eq!(e.contact_count(), eqs[0].contact_count(), "{pattern}");
            assert!(
                (e.p_max - eqs[0].p_max).abs() < 1e-9 * eqs[0].p_max,
                "{pattern}: {} vs {}",
                e.p_max,
                eqs[0].p_max
            );
            assert!((e.z - eqs[0].z).abs() < 1e-15);
        }
    }
    // The landscape of square-tri at θ = 0 is mirror-symmetric: Δz(x, y) = Δz(x, −y) (the
    // landscape solves with auto, which tilts against the mount's springs off the symmetric
    // poses; the mirror flips the tilt, not z).
    let s = solver("square-tri");
    let l = compute_landscape(&s, 0.0, W, &params(5), &|| {}).unwrap();
    for i in 0..5 {
        for j in 0..5 {
            let [x, y] = l.shift(i, j);
            let m = s
                .solve(
                    Pose {
                        theta: 0.0,
                        shift: [x, -y],
                    },
                    W,
                    Model::Auto,
                )
                .unwrap();
            assert!((m.z - l.z_at(i, j)).abs() < 1e-15, "({i},{j})");
        }
    }
}

/// square-tri, θ = 0, 1.4 mN: the contact lines run along x (α = 0). Along them the rows of the
/// square slider are commensurate with the substrate rows (both 3 µm) and the slider rides over
/// every bump: the corrugation is the landscape's full range (≈ 90 nm). Perpendicular (α = 90°)
/// the path runs along a ridge line of the landscape (constant x), where square (3 µm) and triangular (3√3/2 µm)
/// row spacings are incommensurate: corrugation below 2 nm, more than 40× smaller.
#[test]
fn square_tri_contact_line_alpha_0_vs_90() {
    let s = solver("square-tri");
    let p = MapParams::default();
    let line = contact_line_direction(s.scene(), 0.0, &p);
    assert!(line.angle.abs() < 1e-9, "contact line {}", line.angle);
    let short = MapParams {
        distance: 6e-6,
        step: 0.1e-6,
        ..p
    };
    let c = corrugation_direct(
        &s,
        0.0,
        W,
        line.angle,
        &[0.0, 90f64.to_radians()],
        &short,
        &|| {},
    )
    .unwrap();
    let (c0, c90) = (c[0].corrugation, c[1].corrugation);
    assert!(c0 > 50e-9 && c0 < 150e-9, "α = 0: {c0}");
    assert!(c90 < 2e-9, "α = 90°: {c90}");
    assert!(c0 > 40.0 * c90);
    // The static-friction barrier follows: larger along the line than across it.
    assert!(c[0].max_lateral_force > 5.0 * c[1].max_lateral_force);
}

/// A path along y through x = 0 stays on the landscape's ridge line x = 0 (Δz is largest there at
/// θ = 0; α = 90°): its heights
/// at the grid spacing are the landscape column x = 0, and its corrugation over one period is that
/// column's variation.
#[test]
fn corrugation_along_a_ridge_is_the_landscape_variation() {
    let s = solver("square-tri");
    let n = 9;
    let l = compute_landscape(&s, 0.0, W, &params(n), &|| {}).unwrap();
    let ly = l.cell.b[1];
    let path = MapParams {
        distance: ly,
        step: ly / (n - 1) as f64,
        ..MapParams::default()
    };
    let prof = path_profile(&s, 0.0, W, 90f64.to_radians(), &path, &|| {}).unwrap();
    assert_eq!(prof.z.len(), n);
    for (j, z) in prof.z.iter().enumerate() {
        assert!((z - l.z_at(0, j)).abs() < 1e-14, "j = {j}");
    }
    let col: Vec<f64> = (0..n).map(|j| l.z_at(0, j)).collect();
    let var = col.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - col.iter().cloned().fold(f64::INFINITY, f64::min);
    assert!((prof.corrugation() - var).abs() < 1e-14);
    // The interpolated landscape reproduces it too (fast path), within 0.2 nm.
    let fast = corrugation_from_landscape(&l, 0.0, &[90f64.to_radians()], &path).unwrap();
    assert!((fast[0].corrugation - var).abs() < 0.2e-9);
}

#[test]
fn bad_input_names_the_field() {
    let s = solver("square-tri");
    let e = compute_landscape(&s, 0.0, W, &params(0), &|| {}).unwrap_err();
    assert!(e.to_string().contains("grid"), "{e}");
    let e = corrugation_direct(&s, 0.0, W, 0.0, &[200f64.to_radians()], &params(51), &|| {})
        .unwrap_err();
    assert!(e.to_string().contains("alpha_deg"), "{e}");
    // A slider that leaves the substrate along the path.
    let long = MapParams {
        distance: 500e-6,
        ..MapParams::default()
    };
    let e = path_profile(&s, 0.0, W, 0.0, &long, &|| {}).unwrap_err();
    assert!(e.to_string().contains("distance_um"), "{e}");
    // No substrate under the slider at all: the landscape refuses the offset.
    let mut sc = Scene::preset("square-tri").unwrap();
    sc.slider.offset = [1e-3, 0.0];
    if let Ok(s) = Solver::new(&sc) {
        let e = compute_landscape(&s, 0.0, W, &params(3), &|| {}).unwrap_err();
        assert!(e.to_string().contains("offset"), "{e}");
    }
}

/// The path's pulling force is the derivative of the enthalpy V = U_Hertz + W·z along the path
/// (locked mount: no tilt energy), checked by central differences on a fine path across a ridge
/// of the square-tri θ = 0 landscape (skipping the valley, where the contacts change partners
/// and F_pull jumps from −F_max to +F_max within one step). Before this check the contact sum used half the
/// lateral centre offset and reported half the force.
#[test]
fn pulling_force_is_the_enthalpy_slope() {
    let mut sc = Scene::preset("square-tri").unwrap();
    sc.slider.mount = surrogate::Mount::Locked;
    let s = Solver::new(&sc).unwrap();
    let p = MapParams {
        distance: 1.5e-6,
        step: 0.01e-6,
        ..MapParams::default()
    };
    let pr = path_profile(&s, 0.0, W, 0.0, &p, &|| {}).unwrap();
    let v = |j: usize| pr.energy[j] + W * pr.z[j];
    let fmax = pr.max_pull();
    assert!(fmax > 1e-4, "{fmax}");
    let mut checked = 0;
    for k in 1..pr.s.len() - 1 {
        let jump =
            (pr.f_pull[k + 1] - pr.f_pull[k]).abs() + (pr.f_pull[k] - pr.f_pull[k - 1]).abs();
        if jump > 0.1 * fmax {
            continue;
        }
        checked += 1;
        let dv = (v(k + 1) - v(k - 1)) / (pr.s[k + 1] - pr.s[k - 1]);
        assert!(
            (pr.f_pull[k] - dv).abs() < 0.01 * fmax,
            "s = {} µm: F_pull {} vs dV/ds {dv}",
            pr.s[k] * 1e6,
            pr.f_pull[k]
        );
    }
    assert!(checked > 140, "{checked}");
}
