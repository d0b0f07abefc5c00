//! One scene resolution and validation for every command (issue 7, items 2 and 3): the scene
//! file's θ is honoured by every command, flags override the file, a slider that does not fit
//! on the substrate is refused by every command before any work, and an overhanging slider is
//! reported by every command in its log and in its sidecar.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};

/// `landscape` and `corrugation` honour `slider.theta_deg` of a scene file (they used the
/// θ = 0 landscape: 94.8 nm range instead of 5.7 nm at 10.2°), and `--theta` overrides it.
#[test]
fn scene_file_theta_is_honoured_by_the_map_commands() {
    let d = tmpdir("scene-theta");
    let toml = d.join("s.toml");
    std::fs::write(
        &toml,
        "pattern = 'square-tri'\n[slider]\ntheta_deg = 10.2\n",
    )
    .unwrap();
    let run = |args: &[&str]| {
        let out = bin().args(args).output().unwrap();
        assert_ok(&out);
        String::from_utf8(out.stdout).unwrap()
    };
    let t = toml.to_str().unwrap();
    let range = |csv: &str| {
        csv.lines()
            .skip(1)
            .map(|l| l.split(',').nth(2).unwrap().parse::<f64>().unwrap())
            .fold(0.0, f64::max)
    };
    let from_file = run(&["landscape", "--scene", t, "--grid", "7"]);
    let from_flag = run(&[
        "landscape",
        "--pattern",
        "square-tri",
        "--theta",
        "10.2",
        "--grid",
        "7",
    ]);
    let overridden = run(&["landscape", "--scene", t, "--theta", "0", "--grid", "7"]);
    assert_eq!(from_file, from_flag);
    assert!(range(&from_file) < 10.0, "θ = 10.2°: {}", range(&from_file));
    assert!(range(&overridden) > 30.0, "θ = 0: {}", range(&overridden));
    let corr = |extra: &[&str]| {
        let mut a = vec![
            "corrugation",
            "--alpha",
            "0",
            "--distance-um",
            "3",
            "--step-um",
            "0.5",
        ];
        a.extend(extra);
        run(&a)
    };
    let from_file = corr(&["--scene", t]);
    assert_eq!(from_file, corr(&["--theta", "10.2"]));
    assert!(
        from_file.lines().nth(1).unwrap().starts_with("10.2,1.4,"),
        "{from_file}"
    );
    assert!(corr(&["--scene", t, "--theta", "0"])
        .lines()
        .nth(1)
        .unwrap()
        .starts_with("0.0,1.4,"));
    std::fs::remove_dir_all(&d).ok();
}

/// A slider far larger than the substrate is refused by every command, naming the field, before
/// any work (screen used to answer 1 contact at 21.8 GPa).
#[test]
fn every_command_refuses_a_slider_that_does_not_fit() {
    let bad = [
        "--substrate-um",
        "2x2",
        "--slider-radius-um",
        "15",
        "--load-mn",
        "10",
    ];
    for cmd in ["screen", "landscape", "corrugation", "equilibrate", "slide"] {
        let mut a = vec![cmd];
        a.extend(bad);
        if cmd == "screen" {
            a.extend(["--theta", "0"]);
        }
        fails_naming(&a, "slider.radius_um");
    }
}

/// A slider hanging over the substrate edge is allowed but reported: in the log and in the
/// sidecar's `warnings`.
#[test]
fn every_command_reports_the_edge_overhang() {
    let d = tmpdir("scene-edge");
    let scene = [
        "--pattern",
        "square-tri",
        "--slider-radius-um",
        "9",
        "--substrate-um",
        "40x40",
        "--offset-um",
        "14,0",
        "--load-mn",
        "0.02",
    ];
    let cases: [(&str, &[&str]); 2] = [
        ("screen", &["--theta", "0,10"]),
        ("equilibrate", &["--equilibrate-us", "0.01", "--rigid-z"]),
    ];
    // A slide must keep the disc over the substrate along its whole path (the DEM would let the
    // slider run off the edge): refused before any work, naming the flags to change.
    let out = bin()
        .arg("slide")
        .args(scene)
        .args([
            "--equilibrate-us",
            "0.01",
            "--relax-us",
            "0.01",
            "--slide-us",
            "0.01",
            "--rigid-z",
        ])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("does not fit at its start") && err.contains("--offset-um"),
        "slide: {err}"
    );
    for (cmd, extra) in cases {
        let csv = d.join(format!("{cmd}.csv"));
        let out = bin()
            .arg(cmd)
            .args(scene)
            .args(extra)
            .arg("--out")
            .arg(&csv)
            .output()
            .unwrap();
        assert_ok(&out);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("warning:") && err.contains("over the edge"),
            "{cmd}: {err}"
        );
        let meta: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(d.join(format!("{cmd}.csv.meta.json"))).unwrap(),
        )
        .unwrap();
        let w = meta["warnings"].as_array().unwrap();
        assert!(
            w.iter()
                .any(|w| w.as_str().unwrap().contains("over the edge")),
            "{cmd}: {meta}"
        );
    }
    // The map commands refuse such a scene (a landscape would not be periodic) after the warning.
    let cases: [(&str, &[&str], &str); 2] = [
        ("landscape", &["--grid", "3"], "offset_um"),
        (
            "corrugation",
            &["--alpha", "0", "--distance-um", "3"],
            "distance_um",
        ),
    ];
    for (cmd, extra, field) in cases {
        let csv = d.join(format!("{cmd}.csv"));
        let out = bin()
            .arg(cmd)
            .args(scene)
            .args(extra)
            .arg("--out")
            .arg(&csv)
            .output()
            .unwrap();
        assert!(!out.status.success());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("over the edge") && err.contains(field),
            "{cmd}: {err}"
        );
        // Refused before any row: no output, no partial file left behind.
        let left: Vec<_> = std::fs::read_dir(&d)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .filter(|n| n.starts_with(cmd))
            .collect();
        assert!(left.is_empty(), "{cmd}: {left:?}");
    }
    std::fs::remove_dir_all(&d).ok();
}

/// The geometry flags describe the same scene as the scene-file fields they stand for: a
/// honeycomb pad with its own sphere size, and a site file, give the screen rows of the
/// equivalent scene file (up to the file-name column); bad values name the flag or the field.
#[test]
fn geometry_flags_give_the_scene_files_rows() {
    let dir = common::tmpdir("scene-geometry-flags");
    let screen = |args: &[&str]| -> String {
        let out = common::bin()
            .current_dir(&dir)
            .args(["screen", "--theta", "0,7", "--load-mn", "0.35,1.4"])
            .args(args)
            .output()
            .unwrap();
        common::assert_ok(&out);
        String::from_utf8(out.stdout).unwrap()
    };
    std::fs::write(
        dir.join("pad.toml"),
        "[slider]\nlattice = { kind = 'honeycomb', spacing_um = 4.5 }\noutline = { kind = 'rectangle', size_um = [120, 80] }\nsphere_diameter_um = 2.5\n[substrate]\nsphere_diameter_um = 3.0\n",
    )
    .unwrap();
    let file = screen(&["--scene", "pad.toml"]);
    let flags = screen(&[
        "--slider-lattice",
        "honeycomb:4.5",
        "--outline",
        "rectangle:120x80",
        "--slider-sphere-diameter-um",
        "2.5",
        "--substrate-sphere-diameter-um",
        "3",
    ]);
    assert_eq!(file, flags);
    assert!(file.lines().count() == 5, "{file}");
    // a site file by flag, and over a scene file's lattice (the flag replaces it)
    std::fs::write(
        dir.join("s.csv"),
        "x_um,y_um\n0,0\n3,0\n-3,0\n0,3\n0,-3\n3,3\n-3,-3\n3,-3\n-3,3\n",
    )
    .unwrap();
    std::fs::write(dir.join("sites.toml"), "[slider]\nsites = 's.csv'\n").unwrap();
    let file = screen(&["--scene", "sites.toml"]);
    assert_eq!(file, screen(&["--slider-sites", "s.csv"]));
    assert_eq!(
        file,
        screen(&[
            "--scene",
            "pad.toml",
            "--slider-sites",
            "s.csv",
            "--slider-sphere-diameter-um",
            "3",
            "--substrate-sphere-diameter-um",
            "3",
        ])
    );
    let fails = |args: &[&str], what: &str| {
        let mut a = vec!["screen", "--theta", "0"];
        a.extend_from_slice(args);
        common::fails_naming(&a, what);
    };
    fails(&["--slider-lattice", "hexagonal:3"], "--slider-lattice");
    fails(&["--slider-lattice", "rectangular:3"], "--slider-lattice");
    fails(&["--slider-lattice", "square:x"], "--slider-lattice");
    fails(&["--slider-lattice", "square:1"], "slider.lattice");
    fails(&["--outline", "rectangle:120"], "--outline");
    fails(&["--outline", "polygon:2.5:90"], "--outline");
    fails(
        &["--slider-sphere-diameter-um", "0"],
        "slider.sphere_diameter_um",
    );
    fails(&["--slider-sites", "/nonexistent/s.csv"], "slider.sites");
    std::fs::remove_dir_all(&dir).ok();
}

/// Runs `superlube screen` in `dir` on the scene file `toml` (a small slider, one θ and load).
fn screen_scene(dir: &std::path::Path, toml: &str) -> std::process::Output {
    std::fs::write(dir.join("s.toml"), toml).unwrap();
    common::bin()
        .current_dir(dir)
        .args([
            "screen",
            "--scene",
            "s.toml",
            "--theta",
            "0",
            "--load-mn",
            "0.35",
        ])
        .args(["--slider-radius-um", "12", "--substrate-um", "60x60"])
        .output()
        .unwrap()
}

/// A refusal in the user's units and syntax: names `field`, no Rust debug form (`{ `), no
/// metres (`e-6`, `e-5`), no float noise (`99999`, `00000`).
fn refused_readably(out: &std::process::Output, field: &str) -> String {
    assert!(!out.status.success(), "should be refused");
    let e = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(e.contains(field), "`{e}` does not name {field}");
    for bad in ["{ ", "e-6", "e-5", "99999", "00000", "Polygon", "Rectangle"] {
        assert!(!e.contains(bad), "`{e}` contains `{bad}`");
    }
    e
}

/// Touching spheres typed to 6 decimals are accepted (issue 34): the honeycomb basis
/// `[2.598076, 1.5]` at 5.196152 µm puts its spheres 2.99999982 µm apart (diameter 3 µm),
/// within the relative 1e-6 of contact; a basis 1 % too close is refused naming both sites and
/// the overlap in nm.
#[test]
fn six_decimal_touching_basis_screens_and_a_real_overlap_is_refused() {
    let dir = common::tmpdir("scene-touching-basis");
    let honeycomb = "[slider]\nlattice = { kind = 'triangular', spacing_um = 5.196152, basis_um = [[0, 0], [2.598076, 1.5]] }\n";
    let out = screen_scene(&dir, honeycomb);
    common::assert_ok(&out);
    let rows = String::from_utf8(out.stdout).unwrap();
    assert_eq!(rows.lines().count(), 2, "{rows}");
    // 2.97 µm apart: 30 nm overlap (1 %)
    let out = screen_scene(
        &dir,
        "[slider]\nlattice = { kind = 'triangular', spacing_um = 6, basis_um = [[0, 0], [2.97, 0]] }\n",
    );
    let e = refused_readably(&out, "slider.lattice.basis_um");
    assert!(
        e.contains("basis_um[1] = [0, 0]") && e.contains("basis_um[2] = [2.97, 0]"),
        "{e}"
    );
    assert!(
        e.contains("overlap by 30 nm") && e.contains("2.97 µm apart"),
        "{e}"
    );
    // a refused basis prints what was typed: 1.485, not 1.4849999999999999
    let out = screen_scene(
        &dir,
        "[slider]\nlattice = { kind = 'triangular', spacing_um = 3, basis_um = [[0, 0], [1.485, 0]] }\n",
    );
    let e = refused_readably(&out, "slider.lattice.basis_um");
    assert!(
        e.contains("[[0, 0], [1.485, 0]]") && e.contains("1515 nm"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Outline refusals print the outline as the scene file's fields in µm, or the flag as typed.
#[test]
fn outline_refusals_speak_the_users_syntax() {
    let dir = common::tmpdir("scene-outline-refusals");
    for (outline, shown) in [
        (
            "{ kind = 'polygon', vertices_um = [[0, 0], [10, 6], [10, 0], [0, 4]] }",
            "vertices_um = [[0, 0], [10, 6], [10, 0], [0, 4]]",
        ),
        (
            "{ kind = 'polygon', sides = 2, radius_um = 50 }",
            "sides = 2, radius_um = 50",
        ),
        (
            "{ kind = 'rectangle', size_um = [0, 10] }",
            "size_um = [0, 10]",
        ),
    ] {
        let out = screen_scene(&dir, &format!("[slider]\noutline = {outline}\n"));
        let e = refused_readably(&out, "slider.outline");
        assert!(e.contains(shown), "{e}");
    }
    for spec in ["rectangle:0x10", "polygon:2:50", "disc:-1"] {
        let out = common::bin()
            .args(["screen", "--theta", "0", "--outline", spec])
            .output()
            .unwrap();
        let e = refused_readably(&out, &format!("--outline {spec}"));
        assert!(!e.contains("slider.outline"), "{e}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
