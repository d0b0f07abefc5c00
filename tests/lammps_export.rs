//! `superlube export-lammps`'s files: the data file is the Rust scene (positions, per-site and
//! per-body sphere sizes, materials) and deterministic; bad input is refused naming the flag.
//! Runs in LAMMPS are in `tests/lammps_run.rs`, `lammps-check` in `tests/lammps_check.rs`; the
//! helpers in `tests/common/lammps.rs`.
//!
//! Without `lmp` the tests that need it print that they are skipped and pass — unless
//! `SUPERLUBE_REQUIRE_LAMMPS=1` (CI sets it in `.ci/run`), which turns the skip into a failure.

mod common;
use common::lammps::*;

#[test]
fn export_is_the_rust_scene_and_is_deterministic() {
    // No LAMMPS needed. σ_h > 0, θ and an offset: the data file holds the Rust scene's own
    // sites in its order, with its seeded heights (one source of truth, no re-implementation).
    let dir = tmpdir("scene");
    let mut args = SMALL.to_vec();
    args.extend([
        "--theta",
        "7",
        "--offset-um",
        "1.2,-0.7",
        "--sigma-h-um",
        "0.01",
        "--seed",
        "5",
        "--load-mn",
        "0.1",
        "--slide-us",
        "0",
    ]);
    let meta = export(&dir.join("a"), &args);
    export(&dir.join("b"), &args);
    for f in ["scene.data", "in.superlube.lmp", "README.md"] {
        // the recorded command line names the output directory: leave it out
        let read = |d: &str| {
            std::fs::read_to_string(dir.join(d).join(f))
                .unwrap()
                .replace(dir.join(d).to_str().unwrap(), "DIR")
        };
        assert!(
            read("a") == read("b"),
            "{f} differs between two identical exports"
        );
    }
    let mut scene = surrogate::Scene::preset("square-tri").unwrap();
    scene.slider.radius = 15e-6;
    scene.substrate.size = [66e-6, 54e-6];
    scene.slider.offset = [1.2e-6, -0.7e-6];
    scene.substrate.sigma_h = 0.01e-6;
    scene.substrate.seed = 5;
    let sub = scene.substrate_spheres();
    let sl = scene.slider_sites_at(7f64.to_radians(), [0.0, 0.0]);
    let atoms = data_atoms(&dir.join("a/scene.data"));
    assert_eq!(atoms.len(), sub.len() + 3 * sl.len() + 1);
    assert!(sub.iter().any(|p| p[2] != 0.0));
    for (k, p) in sub.iter().enumerate() {
        let (id, ty, x) = atoms[k];
        assert_eq!((id, ty), (k as u64 + 1, 1));
        for d in 0..3 {
            assert!(
                (x[d] - p[d] * 1e6).abs() < 1e-12,
                "substrate {k}: {x:?} vs {p:?}"
            );
        }
    }
    let first = meta["ids"]["slider"]["first"].as_u64().unwrap() as usize;
    for (k, s) in sl.iter().enumerate() {
        let (_, ty, x) = atoms[first - 1 + k];
        assert_eq!(ty, 2);
        assert!((x[0] - s[0] * 1e6).abs() < 1e-12 && (x[1] - s[1] * 1e6).abs() < 1e-12);
    }
    let deck = std::fs::read_to_string(dir.join("a/in.superlube.lmp")).unwrap();
    assert!(
        deck.contains("cannot") && deck.contains("P_crit"),
        "the deck must state the constant-μ limitation"
    );
    assert!(
        !deck.contains("# ---- 3. slide"),
        "--slide-us 0: no sliding phase"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Per-site sphere sizes (a slider site file with 4 µm, 2 µm, 2 µm and 3 µm spheres; no LAMMPS
/// needed): `export-lammps` writes each slider atom's own diameter (the substrate's stays 3 µm)
/// and export.json each one's radius; slider sphere i's two control spheres sit its anchor
/// offset R − r_i higher (so its ties keep their rest lengths); the deck damps each sphere with
/// its own mass and takes P_max per (slider size, substrate size) class.
#[test]
fn export_of_per_site_sizes_writes_each_atoms_diameter() {
    let dir = tmpdir("per-site-sizes");
    std::fs::write(
        dir.join("sites.csv"),
        "x_um,y_um,diameter_um\n0,0,4\n9,0,2\n0,9,2\n-9,0,\n",
    )
    .unwrap();
    let scene = dir.join("varied.toml");
    std::fs::write(
        &scene,
        "pattern = 'square-tri'\n[substrate]\nsize_um = [60, 60]\n[slider]\nsites = 'sites.csv'\n",
    )
    .unwrap();
    let out_dir = dir.join("out");
    let s = scene.to_str().unwrap();
    let meta = export(
        &out_dir,
        &[
            "--scene",
            s,
            "--line-deg",
            "0",
            "--load-mn",
            "0.05",
            "--slide-us",
            "10",
        ],
    );
    let radii: Vec<f64> = meta["slider_radii_um"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(radii, [2.0, 1.0, 1.0, 1.5]);
    let diameters = data_diameters(&out_dir.join("scene.data"));
    let of = |t: u32| -> Vec<f64> {
        diameters
            .iter()
            .filter(|(k, _)| *k == t)
            .map(|(_, d)| *d)
            .collect()
    };
    assert_eq!(of(2), [4.0, 2.0, 2.0, 3.0]);
    assert!(of(1).iter().all(|&d| d == 3.0) && !of(1).is_empty());
    // lateral control sphere i at the layer's height plus R − r_i
    let lateral: Vec<f64> = data_atoms(&out_dir.join("scene.data"))
        .iter()
        .filter(|a| a.1 == 4)
        .map(|a| a.2[2])
        .collect();
    for (z, r) in lateral.iter().zip(&radii) {
        let want = lateral[3] + (1.5 - r);
        assert!((z - want).abs() < 1e-9, "lateral control z {z} vs {want}");
    }
    let deck = std::fs::read_to_string(out_dir.join("in.superlube.lmp")).unwrap();
    assert!(deck.contains("fix             dsl slider addforce v_dslx v_dsly v_dslz"));
    assert!(
        deck.contains("group           pc2_0 union sl2 sb0"),
        "three slider sizes"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn export_of_two_sphere_sizes_writes_each_bodys_diameter() {
    // No LAMMPS needed. Each substrate atom has the substrate's diameter, each slider atom the
    // slider's (LAMMPS `granular` takes R_eff and the contact distance from the two atoms);
    // export.json records both radii and R_eff = R_sl R_sb/(R_sl + R_sb); the deck's P_max
    // uses the contact distance R_sl + R_sb and the substrate's drag is scaled by its mass.
    let dir = tmpdir("two-sizes");
    let scene = two_size_scene(&dir);
    let args = [
        "--scene",
        scene.to_str().unwrap(),
        "--theta",
        "0",
        "--load-mn",
        "0.05",
        "--slide-us",
        "0",
    ];
    let meta = export(&dir.join("a"), &args);
    let d = data_diameters(&dir.join("a/scene.data"));
    let of = |ty: u32| -> Vec<f64> {
        let mut v: Vec<f64> = d.iter().filter(|a| a.0 == ty).map(|a| a.1).collect();
        v.dedup();
        v
    };
    assert_eq!(of(1), [3.0], "substrate diameters");
    assert_eq!(of(2), [2.0], "slider diameters");
    assert_eq!(
        d.iter().filter(|a| a.0 == 2).count() as u64,
        meta["ids"]["slider"]["count"].as_u64().unwrap()
    );
    assert_eq!(meta["sphere_radius_um"].as_f64(), Some(1.5));
    assert_eq!(meta["slider_sphere_radius_um"].as_f64(), Some(1.0));
    assert!((meta["r_eff_um"].as_f64().unwrap() - 0.6).abs() < 1e-12);
    let deck = std::fs::read_to_string(dir.join("a/in.superlube.lmp")).unwrap();
    let line = |start: &str| -> &str { deck.lines().find(|l| l.starts_with(start)).unwrap() };
    assert!(
        line("variable        pmax_GPa").contains("(c_dmin<2.5)*(2.5-c_dmin)"),
        "{}",
        line("variable        pmax_GPa")
    );
    // γ_substrate/γ_slider = m_b/m_s = (3/2)³
    let visc: Vec<&str> = line("fix             visc").split_whitespace().collect();
    let k = visc.iter().position(|w| *w == "scale").unwrap();
    assert_eq!(visc[k + 1], "1");
    assert!((visc[k + 2].parse::<f64>().unwrap() - 3.375).abs() < 1e-12);
    // one size: no slider radius of its own, no substrate scale, every sphere 3 µm
    let one = export(&dir.join("b"), &[SMALL, &args[2..]].concat());
    assert!(one.get("slider_sphere_radius_um").is_none(), "{one}");
    let d = data_diameters(&dir.join("b/scene.data"));
    assert!(d.iter().filter(|a| a.0 <= 2).all(|a| a.1 == 3.0));
    let deck = std::fs::read_to_string(dir.join("b/in.superlube.lmp")).unwrap();
    assert!(!deck.contains("scale 1 "));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn export_lammps_refuses_bad_input_naming_the_flag() {
    let dir = tmpdir("bad");
    let file = dir.join("a-file");
    std::fs::write(&file, "x").unwrap();
    let under_file = file.join("sub");
    let out_dir = dir.join("out");
    let o = out_dir.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--out", file.to_str().unwrap()], "--out"),
        (vec!["--out", under_file.to_str().unwrap()], "--out"),
        (
            vec!["--out", o, "--equilibrate-us", "-1"],
            "--equilibrate-us",
        ),
        (
            vec!["--out", o, "--equilibrate-us", "0"],
            "--equilibrate-us",
        ),
        (vec!["--out", o, "--relax-us", "-1"], "--relax-us"),
        (vec!["--out", o, "--slide-us", "-5"], "--slide-us"),
        (vec!["--out", o, "--speed-m-s", "-0.1"], "--speed-m-s"),
        (vec!["--out", o, "--speed-m-s", "0"], "--speed-m-s"),
        (vec!["--out", o, "--dt-us", "0"], "--dt-us"),
        (vec!["--out", o, "--sample-us", "nan"], "--sample-us"),
        (vec!["--out", o, "--dump-us", "-1"], "--dump-us"),
        (vec!["--out", o, "--mu", "-0.1"], "--mu"),
        (vec!["--out", o, "--load-mn", "0"], "--load-mn"),
        (vec!["--out", o, "--alpha", "400"], "--alpha"),
        (vec!["--out", o, "--line-deg", "inf"], "--line-deg"),
        (vec!["--out", o, "--theta", "nan"], "--theta"),
        (vec!["--out", o, "--tilt", "wobbly"], "tilt"),
    ];
    for (args, flag) in cases {
        let out = bin().arg("export-lammps").args(&args).output().unwrap();
        assert!(!out.status.success(), "{args:?} should fail");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(flag), "{args:?}: `{err}` does not name {flag}");
        assert!(!out_dir.exists(), "{args:?}: wrote output before refusing");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Per-body materials: the slider–substrate pair's own `pair_coeff 1 2` gives LAMMPS the Hertz
/// E* of both bodies (`E/(2(1 − ν²))` of its modulus at the slider's ν is
/// `1/((1 − ν1²)/E1 + (1 − ν2²)/E2)`) and k_t = 8G*; export.json records that E*; each body's
/// atoms carry its own density. With `lmp`, the deck sets up and starts at the surrogate's
/// equilibrium (contacts, P_max).
#[test]
fn export_of_per_body_materials_writes_the_pairs_moduli() {
    let dir = tmpdir("materials");
    let scene = dir.join("m.toml");
    std::fs::write(
        &scene,
        "pattern = 'square-tri'\n[slider]\nradius_um = 15\n[slider.material]\nyoungs_GPa = 50\npoisson = 0.25\n\
         [substrate]\nsize_um = [66, 54]\n[substrate.material]\ndensity_g_cm3 = 3.0\n",
    )
    .unwrap();
    let args = [
        "--scene",
        scene.to_str().unwrap(),
        "--theta",
        "10",
        "--load-mn",
        "0.05",
        "--slide-us",
        "0",
    ];
    let meta = export(&dir.join("a"), &args);
    let e_star = 1.0 / ((1.0 - 0.25 * 0.25) / 50.0 + (1.0 - 0.3 * 0.3) / 100.0);
    let got = meta["e_star_GPa"].as_f64().unwrap();
    assert!((got / e_star - 1.0).abs() < 1e-12, "{got} vs {e_star}");
    let deck = std::fs::read_to_string(dir.join("a/in.superlube.lmp")).unwrap();
    let pair: Vec<&str> = deck
        .lines()
        .find(|l| l.starts_with("pair_coeff      1 2 "))
        .expect("a pair_coeff of the slider-substrate pair")
        .split_whitespace()
        .collect();
    // hertz/material E e nu …: E in 1e3 Pa (LAMMPS micro units)
    let (e, nu) = (
        pair[4].parse::<f64>().unwrap(),
        pair[6].parse::<f64>().unwrap(),
    );
    assert_eq!(nu, 0.25);
    assert!((e / (2.0 * (1.0 - nu * nu)) * 1e-6 / e_star - 1.0).abs() < 1e-12);
    let g = |e: f64, nu: f64| e / (2.0 * (1.0 + nu));
    let g_star = 1.0 / ((2.0 - 0.25) / g(50.0, 0.25) + (2.0 - 0.3) / g(100.0, 0.3));
    let k = pair.iter().position(|w| *w == "mindlin").unwrap();
    let k_t = pair[k + 1].parse::<f64>().unwrap() * 1e-6;
    assert!((k_t / (8.0 * g_star) - 1.0).abs() < 1e-12, "{k_t}");
    // one material: no pair line
    let one = dir.join("b");
    export(&one, &[SMALL, &args[2..]].concat());
    let deck1 = std::fs::read_to_string(one.join("in.superlube.lmp")).unwrap();
    assert!(!deck1.contains("pair_coeff      1 2 "));
    if let Some(lmp) = lmp() {
        let log = run_deck(&lmp, &dir.join("a"), &[("nsteps", "0")]);
        let r = result(&log, "equilibrate");
        let s = &meta["surrogate"];
        assert_eq!(r["contacts"], s["contacts"].as_f64().unwrap());
        let (p, ps) = (r["p_max_GPa"], s["p_max_GPa"].as_f64().unwrap());
        assert!((p - ps).abs() < 1e-9 * ps, "P_max {p} vs surrogate {ps}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
