//! Cross-checks against the committed LAMMPS peer outputs in `dem/lammps/reference/` (no LAMMPS
//! needed; see docs/commands/export-lammps.md).
//!
//! * the Hertz law of `surrogate` against the contact forces LAMMPS computed along an undamped
//!   two-sphere collision (`collision_v0.2_undamped.csv`, 100+ contact samples);
//! * the closed-form Hertz contact duration against the LAMMPS one (`collision_summary.csv`);
//! * the study scenes of `surrogate::Scene` (sphere counts, rigid-z contacts, P_max and height)
//!   against the values an independent Python re-implementation of the scene wrote
//!   (`rigid_z_python.csv`, frozen: that generator, `gen_scene.py`, was replaced by
//!   `superlube export-lammps`, which writes the Rust scene itself);
//! * `#[ignore]`d: export the study scene and run LAMMPS on it (`dem/lammps/run_peer.sh`, needs
//!   `lmp`), and check its equilibrium against the surrogate. The exported deck's own checks
//!   against LAMMPS run in CI: `tests/lammps_export.rs`.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::{units, Material, Scene};

fn reference(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("dem/lammps/reference")
        .join(name)
}

/// Rows of a small CSV file as column-name → text maps.
fn read_csv(path: &Path) -> Vec<HashMap<String, String>> {
    let text = std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    let mut lines = text.lines();
    let head: Vec<String> = lines
        .next()
        .expect("header")
        .split(',')
        .map(str::to_string)
        .collect();
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            head.iter()
                .cloned()
                .zip(l.split(',').map(str::to_string))
                .collect()
        })
        .collect()
}

fn num(row: &HashMap<String, String>, col: &str) -> f64 {
    row.get(col)
        .unwrap_or_else(|| panic!("missing column {col}"))
        .parse()
        .unwrap_or_else(|e| panic!("column {col}: {e}"))
}

#[test]
fn surrogate_hertz_force_matches_lammps_collision() {
    let hertz = surrogate::contact::Hertz::equal_spheres(1.5e-6, &Material::default());
    let rows = read_csv(&reference("collision_v0.2_undamped.csv"));
    let mut checked = 0;
    for r in &rows {
        let delta = units::um_to_m(num(r, "overlap_um"));
        let lammps = num(r, "contact_force_uN") * units::UN;
        // Skip the first/last nanometre fraction where the overlap is a difference of nearly
        // equal positions (relative round-off above 1e-9).
        if delta > 1e-12 {
            let ours = hertz.force(delta);
            let rel = (ours - lammps).abs() / lammps;
            assert!(
                rel < 1e-8,
                "delta={delta:e} m: surrogate {ours:e} N vs LAMMPS {lammps:e} N (rel {rel:e})"
            );
            checked += 1;
        }
    }
    assert!(checked > 80, "only {checked} contact samples");
}

#[test]
fn lammps_collision_duration_is_hertzian() {
    let rows = read_csv(&reference("collision_summary.csv"));
    let undamped = rows
        .iter()
        .find(|r| r["case"] == "v0.2_undamped")
        .expect("undamped case");
    // Closed form, recomputed here: t_c = 2.94328 δ_max / v (∫₀¹(1−x^{5/2})^{−1/2}dx = B(2/5,1/2)/(5/2)), δ_max from energy balance.
    let h = surrogate::contact::Hertz::equal_spheres(1.5e-6, &Material::default());
    let m = Material::default().sphere_mass(1.5e-6);
    let v = num(undamped, "v_rel_m_s");
    let d_max = (15.0 * (m / 2.0) * v * v / (16.0 * h.e_star * h.r_eff.sqrt())).powf(0.4);
    let t_c = 2.0 * d_max / v * 1.471_637_592_162_352_3;
    let t_lammps = num(undamped, "t_contact_us") * units::US;
    assert!(
        (t_lammps - t_c).abs() / t_c < 1e-5,
        "LAMMPS {t_lammps:e} s vs Hertz {t_c:e} s"
    );
    assert!((num(undamped, "restitution") - 1.0).abs() < 1e-6);
    // The damped cases lose energy, and their restitution does not depend on the speed.
    let e: Vec<f64> = rows
        .iter()
        .filter(|r| r["gamma_n"] != "0")
        .map(|r| num(r, "restitution"))
        .collect();
    assert_eq!(e.len(), 2);
    assert!(e.iter().all(|&e| e > 0.5 && e < 0.95));
    assert!((e[0] - e[1]).abs() < 1e-3, "restitution {e:?}");
}

#[test]
fn surrogate_scene_matches_the_lammps_generator() {
    for r in read_csv(&reference("rigid_z_python.csv")) {
        let pattern = &r["pattern"];
        let theta = num(&r, "theta_deg").to_radians();
        let load = units::mn_to_n(num(&r, "load_mN"));
        let scene = Scene::preset(pattern).unwrap().with_theta(theta);
        assert_eq!(
            scene.substrate_spheres().len() as f64,
            num(&r, "substrate_spheres")
        );
        assert_eq!(scene.slider_sites().len() as f64, num(&r, "slider_spheres"));
        let eq = Solver::new(&scene)
            .unwrap()
            .solve(
                Pose {
                    theta,
                    shift: [0.0, 0.0],
                },
                load,
                Model::RigidZ,
            )
            .unwrap();
        let case = format!("{pattern} θ={} W={}", r["theta_deg"], r["load_mN"]);
        assert_eq!(
            eq.contact_count() as f64,
            num(&r, "contacts"),
            "{case}: contacts"
        );
        let p_py = num(&r, "p_max_GPa") * units::GPA;
        assert!(
            (eq.p_max - p_py).abs() / p_py < 1e-6,
            "{case}: P_max {} vs {p_py}",
            eq.p_max
        );
        let z_py = units::um_to_m(num(&r, "z_um"));
        assert!((eq.z - z_py).abs() < 1e-13, "{case}: z {} vs {z_py}", eq.z);
    }
}

/// Runs LAMMPS (needs `lmp` and python3): `cargo test --test lammps_peer -- --ignored`.
#[test]
#[ignore = "needs LAMMPS (apt-get install lammps); ~10 s"]
fn lammps_equilibrium_matches_surrogate() {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("dem/lammps/run_peer.sh");
    let out = std::process::Command::new("bash")
        .arg(script)
        .env("STEPS", "200")
        .env("RANKS", "1")
        .env("MOUNT", "locked")
        .env("SUPERLUBE", env!("CARGO_BIN_EXE_superlube"))
        .output()
        .expect("run run_peer.sh");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let row = text
        .lines()
        .find(|l| l.starts_with("lammps,"))
        .expect("a result row");
    let f: Vec<&str> = row.split(',').collect();
    let (contacts, p_max_gpa): (usize, f64) = (f[8].parse().unwrap(), f[9].parse().unwrap());
    let scene = Scene::preset("square-tri").unwrap();
    let eq = Solver::new(&scene)
        .unwrap()
        .solve(
            Pose {
                theta: 0.0,
                shift: [0.0, 0.0],
            },
            1.4e-3,
            Model::RigidZ,
        )
        .unwrap();
    assert_eq!(contacts, eq.contact_count());
    assert!((p_max_gpa * 1e9 - eq.p_max).abs() / eq.p_max < 0.02);
}
