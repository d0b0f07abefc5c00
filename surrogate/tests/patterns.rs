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

/// Closed-form Hertz p0 (Pa) of one contact carrying `w` (N) between spheres of radii `r1`,
/// `r2` (m): `(6 W E*² / (π³ R_eff²))^{1/3}`, `R_eff = r1 r2/(r1 + r2)`.
fn hertz_p0(w: f64, e_star: f64, r1: f64, r2: f64) -> f64 {
    let pi = std::f64::consts::PI;
    let r_eff = r1 * r2 / (r1 + r2);
    (6.0 * w * e_star * e_star / (pi * pi * pi * r_eff * r_eff)).cbrt()
}

fn rigid_z(s: &Scene, w: f64) -> surrogate::solver::Equilibrium {
    Solver::new(s)
        .unwrap()
        .solve(Pose::default(), w, Model::RigidZ)
        .unwrap()
}

/// Per-site sizes within one body's site file: a substrate file of a 4 µm and a 2 µm sphere
/// under a one-sphere (2 µm) slider. The one touching pair (the 4 µm sphere) follows Hertz
/// with its own R_eff = 1·2/3 µm: P_max = (6 W E*² / (π³ R_eff²))^{1/3} to 1e-9, and its contact
/// point lies halfway between the centres at the pair's own distance r_i + r_j − δ.
#[test]
fn per_site_sizes_follow_hertz_on_a_single_pair() {
    let sub = tmp("sub-two-sizes.csv");
    std::fs::write(&sub, "x_um,y_um,diameter_um\n0,0,4.0\n10,0,2.0\n").unwrap();
    let sl = tmp("sl-one.csv");
    std::fs::write(&sl, "x_um,y_um,diameter_um\n0,0,2.0\n").unwrap();
    let s = scene(&format!(
        "pattern = 'square-square'\n[substrate]\nsize_um = [60, 60]\nsites = '{}'\n[slider]\ntilt = 'locked'\nsites = '{}'\n",
        sub.display(),
        sl.display()
    ));
    assert_eq!(s.substrate_radii(), Some(&[2e-6, 1e-6][..]));
    assert_eq!(s.slider_radii(), None);
    let w = 1e-4;
    let eq = rigid_z(&s, w);
    assert_eq!(eq.contact_count(), 1);
    let c = eq.contacts[0];
    assert_eq!(c.substrate, 0);
    let p0 = hertz_p0(w, s.material.e_star(), 1e-6, 2e-6);
    assert!((eq.p_max / p0 - 1.0).abs() < 1e-9, "{} vs {p0}", eq.p_max);
    assert!((c.force_n / w - 1.0).abs() < 1e-9);
    // the 4 µm sphere's centre is 0.5 µm above the substrate's reference plane (R = 1.5 µm)
    let top = 0.5e-6 + 3e-6 - c.overlap;
    assert!((c.point[2] - 0.5 * (0.5e-6 + top)).abs() < 1e-15, "{c:?}");
}

/// Geometry convention: a two-sphere slider site file (2 µm and 4 µm, 9 µm apart) over the flat
/// triangular substrate (3 µm). The slider spheres hang with their tops on one plate, so the
/// 4 µm sphere reaches 2 µm further down and carries the whole small load alone (the 2 µm one is
/// out of contact); P_max is that pair's Hertz p0 (R_eff = 2·1.5/3.5 µm) and the slider's
/// reference plane (of 3 µm spheres) sits 4 µm − δ above the substrate's.
#[test]
fn big_slider_sphere_carries_a_small_load_alone() {
    let csv = tmp("sl-2-4.csv");
    std::fs::write(&csv, "x_um,y_um,diameter_um\n0,0,4.0\n9,0,2.0\n").unwrap();
    let s = scene(&format!(
        "pattern = 'tri-tri'\n[substrate]\nsize_um = [60, 60]\n[slider]\ntilt = 'locked'\nsites = '{}'\n",
        csv.display()
    ));
    assert_eq!(s.slider_radii(), Some(&[2e-6, 1e-6][..]));
    let w = 1e-4;
    let eq = rigid_z(&s, w);
    assert_eq!(eq.contact_count(), 1, "{:?}", eq.contacts);
    let c = eq.contacts[0];
    assert_eq!(c.slider, 0);
    let p0 = hertz_p0(w, s.material.e_star(), 2e-6, 1.5e-6);
    assert!((eq.p_max / p0 - 1.0).abs() < 1e-9, "{} vs {p0}", eq.p_max);
    assert!((eq.z - (4e-6 - c.overlap)).abs() < 1e-15, "{}", eq.z);
    // mirrored sizes: the big sphere (now second) carries it
    let csv = tmp("sl-4-2.csv");
    std::fs::write(&csv, "x_um,y_um,diameter_um\n0,0,2.0\n9,0,4.0\n").unwrap();
    let m = scene(&format!(
        "pattern = 'tri-tri'\n[substrate]\nsize_um = [60, 60]\n[slider]\ntilt = 'locked'\nsites = '{}'\n",
        csv.display()
    ));
    let eq2 = rigid_z(&m, w);
    assert_eq!(eq2.contact_count(), 1);
    assert_eq!(eq2.contacts[0].slider, 1);
    assert!((eq2.p_max / p0 - 1.0).abs() < 1e-9);
}

/// Every model on a slider of three sizes (3, 2.996 and 2.992 µm, the first as empty cells: the
/// body's size) on the sites of the triangular substrate, shifted off-top, under a springs mount:
/// the loads balance, each contact's overlap is its pair's own `r_i + r_j − |x_i − x_j|` from
/// the two centres (slider centre `R − r_i` above the reference plane) and its p0 its own
/// R_eff's, every size touches, and the grid and BVH searches give the same answer.
#[test]
fn every_model_uses_each_pairs_own_radius_sum() {
    let csv = tmp("three-sizes.csv");
    let mut text = String::from("x_um,y_um,diameter_um\n");
    let d = ["", "2.996", "2.992"];
    for j in -2i32..=2 {
        for i in -2i32..=2 {
            let x = 6.0 * i as f64 + 3.0 * j as f64;
            let y = 3.0 * 3f64.sqrt() * j as f64;
            text += &format!("{x},{y},{}\n", d[(i + 2 * j).rem_euclid(3) as usize]);
        }
    }
    std::fs::write(&csv, text).unwrap();
    let s = scene(&format!(
        "pattern = 'tri-tri'\n[substrate]\nsize_um = [60, 60]\nsigma_h_um = 0.002\n[slider]\nsites = '{}'\n",
        csv.display()
    ));
    let radii = s.slider_radii().unwrap().to_vec();
    let sub = s.substrate_spheres();
    let w = 2e-3;
    let pose = Pose {
        theta: 0.0,
        shift: [0.2e-6, 0.1e-6],
    };
    let mut solver = Solver::new(&s).unwrap();
    for model in [
        Model::Auto,
        Model::RigidZ,
        Model::RigidTilt,
        Model::Compliant,
    ] {
        let eq = solver.solve(pose, w, model).unwrap();
        let mut touching: Vec<f64> = eq
            .contacts
            .iter()
            .map(|c| radii[c.slider as usize])
            .collect();
        touching.sort_by(f64::total_cmp);
        touching.dedup();
        assert_eq!(touching.len(), 3, "{model:?}: sizes touching {touching:?}");
        assert!(eq.residual_rel() < 1e-9, "{model:?}: {}", eq.residual_rel());
        let fz: f64 = eq.contacts.iter().map(|c| c.force_z).sum();
        assert!((fz / w - 1.0).abs() < 1e-9, "{model:?}");
        for c in &eq.contacts {
            let b = sub[c.substrate as usize];
            let top = [
                2.0 * c.point[0] - b[0],
                2.0 * c.point[1] - b[1],
                2.0 * c.point[2] - b[2],
            ];
            let dist =
                ((top[0] - b[0]).powi(2) + (top[1] - b[1]).powi(2) + (top[2] - b[2]).powi(2))
                    .sqrt();
            let sum = radii[c.slider as usize] + 1.5e-6;
            assert!(
                (sum - dist - c.overlap).abs() < 1e-6 * c.overlap + 1e-15,
                "{model:?}: overlap {} vs {}",
                c.overlap,
                sum - dist
            );
            let r_eff = radii[c.slider as usize] * 1.5e-6 / sum;
            let p0 = 2.0 * s.material.e_star() / std::f64::consts::PI * (c.overlap / r_eff).sqrt();
            assert!((c.p0 / p0 - 1.0).abs() < 1e-12, "{model:?}");
        }
        if model == Model::RigidZ {
            // slider centre of sphere i: z + (R − r_i) with R = 1.5 µm
            for c in &eq.contacts {
                let b = sub[c.substrate as usize];
                let zs = 2.0 * c.point[2] - b[2];
                let r = radii[c.slider as usize];
                assert!((zs - (eq.z + 1.5e-6 - r)).abs() < 1e-15, "{zs} {}", eq.z);
            }
        }
    }
    let grid = solver.solve(pose, w, Model::Auto).unwrap();
    solver.search = surrogate::solver::SearchKind::Bvh;
    assert_eq!(solver.solve(pose, w, Model::Auto).unwrap(), grid);
}

/// A site file whose diameters all equal the body's size, given as a column, as a column with
/// empty cells, or by `sphere_diameter_um` alone, gives the same scene answers (one size: the
/// geometry without per-site sizes); mixed cells take the body's size.
#[test]
fn equal_and_empty_diameter_cells_are_the_one_size_scene() {
    let base = scene(&format!("{SMALL}[slider]\nradius_um = 12\n"));
    let sites = base.slider_sites_local();
    let write = |name: &str, cell: &dyn Fn(usize) -> String| {
        let csv = tmp(name);
        let mut text = String::from("x_um,y_um,diameter_um\n");
        for (i, p) in sites.iter().enumerate() {
            text += &format!("{},{},{}\n", m_to_um(p[0]), m_to_um(p[1]), cell(i));
        }
        std::fs::write(&csv, text).unwrap();
        csv
    };
    let all = write("all-3.csv", &|_| "3.0".into());
    let mixed = write("mixed-3.csv", &|i| {
        if i % 2 == 0 {
            "3".into()
        } else {
            String::new()
        }
    });
    let plain = tmp("plain.csv");
    let mut text = String::from("x_um,y_um\n");
    for p in &sites {
        text += &format!("{},{}\n", m_to_um(p[0]), m_to_um(p[1]));
    }
    std::fs::write(&plain, text).unwrap();
    let of = |csv: &std::path::Path, extra: &str| {
        scene(&format!(
            "{SMALL}[slider]\nradius_um = 12\n{extra}sites = '{}'\n",
            csv.display()
        ))
    };
    let reference = answers(&of(&plain, "sphere_diameter_um = 3.0\n"));
    assert_eq!(answers(&base), reference);
    for s in [
        of(&all, ""),
        of(&mixed, ""),
        of(&mixed, "sphere_diameter_um = 3.0\n"),
    ] {
        assert!(!s.has_site_sizes());
        assert_eq!(answers(&s), reference);
    }
    // mixed cells with another body size: the empty cells take 2 µm, the others stay 3 µm
    let s = of(&mixed, "sphere_diameter_um = 2.0\n");
    let r = s.slider_radii().unwrap();
    assert_eq!((r[0], r[1]), (1.5e-6, 1e-6));
}

/// Per-site diameters are checked before any work, naming the field, the file and the line:
/// zero, negative and NaN diameters, and spheres closer than their own radius sum r_i + r_j
/// (a 4 µm and a 2 µm sphere 2.9 µm apart); touching ones (3 µm apart) are accepted.
#[test]
fn bad_per_site_diameters_are_named_with_their_line() {
    for (cell, why) in [
        ("0", "must be positive"),
        ("-2", "must be positive"),
        ("NaN", "not a finite"),
    ] {
        let csv = tmp("bad-d.csv");
        std::fs::write(
            &csv,
            format!("x_um,y_um,diameter_um\n0,0,2\n# c\n10,0,{cell}\n"),
        )
        .unwrap();
        let e = scene_err(&format!("[slider]\nsites = '{}'\n", csv.display()));
        assert!(
            e.contains("slider.sites")
                && e.contains("line 4")
                && e.contains("diameter_um")
                && e.contains(why),
            "{e}"
        );
    }
    let csv = tmp("close.csv");
    std::fs::write(&csv, "x_um,y_um,diameter_um\n0,0,4\n2.9,0,2\n20,0,3\n").unwrap();
    let e = scene_err(&format!("[substrate]\nsites = '{}'\n", csv.display()));
    assert!(
        e.contains("substrate.sites")
            && e.contains("lines 2 and 3")
            && e.contains("overlap")
            && e.contains("radius sum 3"),
        "{e}"
    );
    std::fs::write(&csv, "x_um,y_um,diameter_um\n0,0,4\n3,0,2\n20,0,3\n").unwrap();
    let s = scene(&format!("[substrate]\nsites = '{}'\n", csv.display()));
    assert!(s.has_site_sizes());
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
