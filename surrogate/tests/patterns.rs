//! Pattern geometry: lattices with a basis, outlines, site files, two sphere sizes.

use surrogate::solver::{Model, Pose, Solver};
use surrogate::units::m_to_um;
use surrogate::{Scene, SceneFile};

fn scene(toml: &str) -> Scene {
    SceneFile::from_toml(toml, "test.toml")
        .unwrap()
        .into_scene()
        .unwrap()
}

fn scene_err(toml: &str) -> String {
    SceneFile::from_toml(toml, "test.toml")
        .unwrap()
        .into_scene()
        .unwrap_err()
        .to_string()
}

fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("surrogate-patterns-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

/// (contacts, z, p_max) over a few θ and loads.
fn answers(s: &Scene) -> Vec<(usize, f64, f64)> {
    let solver = Solver::new(s).unwrap();
    let mut out = Vec::new();
    for theta in [0.0f64, 7.0, 30.0] {
        for w in [0.5e-3, 2e-3] {
            let eq = solver
                .solve(
                    Pose {
                        theta: theta.to_radians(),
                        shift: [0.0, 0.0],
                    },
                    w,
                    Model::Auto,
                )
                .unwrap();
            out.push((eq.contact_count(), eq.z, eq.p_max));
        }
    }
    out
}

const SMALL: &str = "[substrate]\nsize_um = [120, 120]\n";

#[test]
fn honeycomb_basis_equals_its_sites_as_a_file() {
    let hc = scene(&format!(
        "{SMALL}[slider]\nradius_um = 30\nsphere_diameter_um = 1.5\nlattice = {{ kind = 'honeycomb', spacing_um = 3.0 }}\n"
    ));
    let explicit = scene(&format!(
        "{SMALL}[slider]\nradius_um = 30\nsphere_diameter_um = 1.5\nlattice = {{ kind = 'triangular', spacing_um = 3.0, basis_um = [[0, 0], [1.5, {}]] }}\n",
        1.5 / 3f64.sqrt()
    ));
    assert_eq!(hc.slider_sites_local(), explicit.slider_sites_local());
    let sites = hc.slider_sites_local();
    assert!(sites.len() > 500, "{}", sites.len());
    let csv = tmp("honeycomb.csv");
    let mut text = String::from("x_um,y_um\n");
    for p in &sites {
        text += &format!("{},{}\n", m_to_um(p[0]), m_to_um(p[1]));
    }
    std::fs::write(&csv, text).unwrap();
    let from_file = scene(&format!(
        "{SMALL}[slider]\nsphere_diameter_um = 1.5\nsites = '{}'\n",
        csv.display()
    ));
    assert_eq!(from_file.slider_sites_local().len(), sites.len());
    assert_eq!(answers(&hc), answers(&from_file));
}

#[test]
fn polygon_holding_the_disc_sites_gives_the_disc() {
    let disc = scene(&format!("{SMALL}[slider]\nradius_um = 30\n"));
    // a 720-gon whose inscribed circle holds the 30 µm disc and whose corners stay short of the
    // next lattice site outside it
    let r = 30.0 / (std::f64::consts::PI / 720.0).cos() * (1.0 + 1e-12);
    let poly = scene(&format!(
        "{SMALL}[slider]\noutline = {{ kind = 'polygon', sides = 720, radius_um = {r} }}\n"
    ));
    assert_eq!(disc.slider_sites_local(), poly.slider_sites_local());
    assert_eq!(answers(&disc), answers(&poly));
}

#[test]
fn square_pad_on_square_substrate_is_commensurate() {
    let s = scene(&format!(
        "pattern = 'square-square'\n{SMALL}[slider]\ntilt = 'locked'\noutline = {{ kind = 'rectangle', size_um = [30, 21] }}\n"
    ));
    let n = s.slider_sites_local().len();
    assert_eq!(n, 11 * 7);
    let eq = Solver::new(&s)
        .unwrap()
        .solve(
            Pose {
                theta: 0.0,
                shift: [0.0, 0.0],
            },
            1e-3,
            Model::RigidZ,
        )
        .unwrap();
    assert_eq!(eq.contact_count(), n);
}

#[test]
fn two_sphere_sizes_follow_hertz_on_a_single_pair() {
    let csv = tmp("one.csv");
    std::fs::write(&csv, "x_um,y_um,diameter_um\n0,0,2.0\n").unwrap();
    let s = scene(&format!(
        "pattern = 'square-square'\n[substrate]\nsize_um = [120, 120]\nsphere_diameter_um = 3.0\n[slider]\ntilt = 'locked'\nsites = '{}'\n",
        csv.display()
    ));
    assert_eq!(s.slider_sphere_radius(), 1e-6);
    assert_eq!(s.sphere_radius, 1.5e-6);
    let w = 1e-4;
    let eq = Solver::new(&s)
        .unwrap()
        .solve(
            Pose {
                theta: 0.0,
                shift: [0.0, 0.0],
            },
            w,
            Model::RigidZ,
        )
        .unwrap();
    assert_eq!(eq.contact_count(), 1);
    let r_eff: f64 = 1.0 / (1.0 / 1e-6 + 1.0 / 1.5e-6);
    let e_star = s.material.e_star();
    let pi = std::f64::consts::PI;
    let p0 = (6.0 * w * e_star * e_star / (pi * pi * pi * r_eff * r_eff)).cbrt();
    assert!((eq.p_max / p0 - 1.0).abs() < 1e-9, "{} vs {p0}", eq.p_max);
    // the equal-sphere law would be off by (R_eff ratio)^(2/3)
    let p_equal = s_equal_p0(w, e_star);
    assert!((eq.p_max / p_equal - 1.0).abs() > 0.05);
}

fn s_equal_p0(w: f64, e_star: f64) -> f64 {
    let pi = std::f64::consts::PI;
    let r_eff = 0.75e-6;
    (6.0 * w * e_star * e_star / (pi * pi * pi * r_eff * r_eff)).cbrt()
}

#[test]
fn bad_geometry_is_named_with_its_line() {
    let csv = tmp("overlap.csv");
    std::fs::write(&csv, "x_um,y_um\n0,0\n10,0\n# comment\n11.5,0.5\n").unwrap();
    let e = scene_err(&format!("[slider]\nsites = '{}'\n", csv.display()));
    assert!(
        e.contains("slider.sites") && e.contains("lines 3 and 5") && e.contains("overlap"),
        "{e}"
    );
    let csv = tmp("missing.csv");
    std::fs::write(&csv, "x_um,y_um\n0,0\n10\n").unwrap();
    let e = scene_err(&format!("[slider]\nsites = '{}'\n", csv.display()));
    assert!(
        e.contains("line 3") && e.contains("missing column y_um"),
        "{e}"
    );
    let csv = tmp("nan.csv");
    std::fs::write(&csv, "x_um,y_um\n0,0\nNaN,7\n").unwrap();
    let e = scene_err(&format!("[substrate]\nsites = '{}'\n", csv.display()));
    assert!(
        e.contains("substrate.sites") && e.contains("line 3") && e.contains("x_um"),
        "{e}"
    );
    let e = scene_err(
        "[slider]\noutline = { kind = 'polygon', vertices_um = [[10, 10], [11, 10], [11, 11]] }\n",
    );
    assert!(
        e.contains("slider.outline") && e.contains("no slider site"),
        "{e}"
    );
    let e = scene_err("[slider]\nlattice = { kind = 'triangular', spacing_um = 3.0, basis_um = [[0, 0], [1, 0]] }\n");
    assert!(
        e.contains("slider.lattice.basis_um") && e.contains("overlap"),
        "{e}"
    );
    let e = scene_err("[slider]\noutline = { kind = 'polygon', vertices_um = [[0, 0], [1, 1]] }\n");
    assert!(e.contains("slider.outline"), "{e}");
}

#[test]
fn plain_scenes_are_unchanged_and_geometry_is_marked() {
    let p = Scene::preset("tri-tri").unwrap();
    assert!(p.geometry.is_plain());
    assert_eq!(scene("pattern = 'tri-tri'\n"), p);
    let k =
        scene("pattern = 'tri-tri'\n[slider]\nlattice = { kind = 'kagome', spacing_um = 6.0 }\n");
    assert_eq!(k.pattern, "tri-tri*");
    assert_eq!(k.geometry.slider_basis.len(), 3);
}
