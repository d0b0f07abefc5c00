//! Flags that carry their unit, and inputs refused in plain words naming the flag or field:
//! `--theta-deg` (old `--theta` a hidden alias with a note), θ's range, a slider too small for
//! its spheres, `--vary` on an unknown field, a missing file, a negative seed, a locked mount
//! with the tilting solver.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};

/// The rows of `screen` on the study's square-tri scene at one θ given with `flag`.
fn screen_rows(flag: &str) -> (String, String) {
    let out = bin()
        .args(["screen", "--pattern", "square-tri", flag, "7.3"])
        .args(["--load-mn", "0.35,1.4"])
        .output()
        .unwrap();
    assert_ok(&out);
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn theta_deg_and_the_old_theta_give_identical_rows() {
    let (new, new_log) = screen_rows("--theta-deg");
    let (old, old_log) = screen_rows("--theta");
    assert_eq!(new.lines().count(), 3, "{new}");
    assert!(new.lines().nth(1).unwrap().starts_with("square-tri,7.3,"));
    assert_eq!(new, old);
    assert!(
        old_log.contains("`superlube screen --theta` is now `--theta-deg`"),
        "{old_log}"
    );
    assert!(!new_log.contains("note:"), "{new_log}");
}

#[test]
fn theta_out_of_range_is_refused_naming_the_flag() {
    for cmd in ["screen", "landscape", "friction", "corrugation"] {
        fails_naming(
            &[cmd, "--theta-deg", "400", "--load-mn", "1"],
            "`--theta-deg`",
        );
    }
    fails_naming(
        &["slide", "--theta-deg", "0,400", "--out-dir", "/tmp/x"],
        "`--theta-deg`",
    );
    fails_naming(&["design", "--theta-deg", "-361"], "`--theta-deg`");
    let d = tmpdir("units-theta-file");
    let scene = d.join("theta.toml");
    std::fs::write(&scene, "pattern = 'tri-tri'\n[slider]\ntheta_deg = 400\n").unwrap();
    fails_naming(
        &[
            "landscape",
            "--scene",
            scene.to_str().unwrap(),
            "--load-mn",
            "1",
        ],
        "`slider.theta_deg`",
    );
    std::fs::remove_dir_all(&d).ok();
    // a full turn either way is a valid orientation
    let out = bin()
        .args(["screen", "--pattern", "tri-tri", "--theta-deg", "360"])
        .args(["--load-mn", "1"])
        .output()
        .unwrap();
    assert_ok(&out);
}

/// Metres typed into the µm field: a slider disc of 1e-4 µm holds one sphere; refused naming
/// the field (scene file) or the flag, with the sphere count. A few spheres: a warning.
#[test]
fn a_slider_too_small_for_its_spheres_is_refused_naming_the_field() {
    let d = tmpdir("units-small-slider");
    let scene = d.join("metres.toml");
    std::fs::write(
        &scene,
        "pattern = 'tri-tri'\n[slider]\nradius_um = 1e-4\ntheta_deg = 0\n",
    )
    .unwrap();
    let out = bin()
        .args(["screen", "--scene"])
        .arg(&scene)
        .args(["--load-mn", "1"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("`slider.radius_um`") && err.contains("holds 1 sphere"),
        "{err}"
    );
    fails_naming(
        &["screen", "--slider-radius-um", "1e-4", "--load-mn", "1"],
        "`--slider-radius-um`",
    );
    let out = bin()
        .args(["screen", "--pattern", "tri-tri", "--slider-radius-um", "2"])
        .args(["--theta-deg", "0", "--load-mn", "1"])
        .output()
        .unwrap();
    assert_ok(&out);
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(
        log.contains("warning: the slider holds only 1 sphere") && log.contains("slider.radius_um"),
        "{log}"
    );
    std::fs::remove_dir_all(&d).ok();
}

/// `--vary` on a field the scene file does not have: the flag once, the field, the fields
/// accepted there, and no text of a file the user never wrote.
#[test]
fn vary_on_an_unknown_field_names_it_once_with_what_is_accepted() {
    let out = bin()
        .args(["design", "--no-dem", "--vary", "nonexistent.field=1,2"])
        .args(["--out-dir", "/tmp/superlube-units-vary-never-written"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.matches("--vary").count(), 1, "{err}");
    assert!(
        err.contains("`nonexistent.field`") && err.contains("expected one of `pattern`"),
        "{err}"
    );
    assert!(
        !err.contains("TOML parse error") && !err.contains("cannot read scene file"),
        "{err}"
    );
}

#[test]
fn missing_files_and_bad_seeds_read_plainly() {
    let out = bin()
        .args(["screen", "--scene", "/nonexistent/superlube-x.toml"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("`--scene`") && err.contains("no such file") && !err.contains("os error"),
        "{err}"
    );
    let out = bin()
        .args([
            "screen",
            "--slider-sites",
            "/nonexistent/superlube-sites.csv",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no such file") && !err.contains("os error"),
        "{err}"
    );
    let out = bin().args(["screen", "--seed", "-1"]).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--seed") && err.contains("whole number") && !err.contains("invalid digit"),
        "{err}"
    );
}

#[test]
fn a_locked_mount_with_the_tilting_solver_names_the_current_flags() {
    let out = bin()
        .args(["screen", "--solver", "rigid-tilt", "--tilt", "locked"])
        .args(["--theta-deg", "0", "--load-mn", "1"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("`--solver`") && err.contains("`--tilt`") && !err.contains("`model`"),
        "{err}"
    );
}

/// The stderr of a command line that must fail (before any work: it returns at once).
fn refusal(args: &[&str]) -> String {
    let out = bin().args(args).output().unwrap();
    assert!(!out.status.success(), "{args:?} should fail");
    String::from_utf8_lossy(&out.stderr).to_string()
}

/// Unit slips in flags are refused with the flag and value as typed, the unit, and the value
/// the slip most likely meant (docs/inputs.md).
#[test]
fn implausible_flags_are_refused_with_the_likely_slip() {
    let friction = [
        "friction",
        "--pattern",
        "square-tri",
        "--theta-deg",
        "10.2",
        "--alpha-deg",
        "90",
        "--load-mn",
        "3.86",
    ];
    let with = |extra: &[&str]| {
        let mut v = friction.to_vec();
        v.extend_from_slice(extra);
        refusal(&v)
    };
    // P_crit typed in MPa, E typed in Pa
    let e = with(&["--p-crit-gpa", "4000"]);
    assert!(
        e.contains("`--p-crit-gpa 4000`") && e.contains("GPa") && e.contains("did you mean 4 GPa"),
        "{e}"
    );
    let e = with(&["--youngs-gpa", "1e11"]);
    assert!(
        e.contains("`--youngs-gpa 100000000000`") && e.contains("did you mean 100 GPa"),
        "{e}"
    );
    // σ_h typed in nm
    let e = with(&["--sigma-h-um", "10"]);
    assert!(
        e.contains("`--sigma-h-um 10`") && e.contains("did you mean 0.01 µm"),
        "{e}"
    );
    // a load in µN, a speed in µm/s, a slide in ns … each names its flag and unit
    let e = refusal(&["screen", "--pattern", "tri-tri", "--load-mn", "350000"]);
    assert!(
        e.contains("`--load-mn 350000`") && e.contains("mN") && e.contains("µN"),
        "{e}"
    );
    let e = refusal(&["slide", "--pattern", "tri-tri", "--speed-m-s", "100000"]);
    assert!(
        e.contains("`--speed-m-s 100000`") && e.contains("m/s"),
        "{e}"
    );
    let e = refusal(&["slide", "--pattern", "tri-tri", "--dt-us", "5"]);
    assert!(e.contains("`--dt-us 5`") && e.contains("µs"), "{e}");
    // the study's own values all pass (friction on square-tri at 3.86 mN runs elsewhere)
}

/// The same slips in a scene file are refused naming the field, in the file's units.
#[test]
fn implausible_scene_fields_are_refused_naming_the_field() {
    let d = tmpdir("units-plausible-file");
    for (body, field, meant) in [
        (
            "[coating]\np_crit_GPa = 4000\n",
            "coating.p_crit_GPa",
            "4 GPa",
        ),
        (
            "[material]\nyoungs_GPa = 1e11\n",
            "material.youngs_GPa",
            "100 GPa",
        ),
        (
            "[material]\ndensity_g_cm3 = 2200\n",
            "material.density_g_cm3",
            "2.2 g/cm³",
        ),
        ("sphere_diameter_um = 3e-6\n", "sphere_diameter_um", "3 µm"),
    ] {
        let scene = d.join("s.toml");
        std::fs::write(&scene, format!("pattern = 'tri-tri'\n{body}")).unwrap();
        let e = refusal(&[
            "screen",
            "--scene",
            scene.to_str().unwrap(),
            "--load-mn",
            "1",
        ]);
        assert!(
            e.contains(&format!("`{field}`")) && e.contains(&format!("did you mean {meant}")),
            "{body}: {e}"
        );
    }
}

/// Contradictory options are refused before any work, naming both; a mistyped `--alpha-deg`
/// on `yield` is pointed at `--direction-deg`.
#[test]
fn contradictions_are_refused() {
    let y = ["yield", "--pattern", "tri-tri", "--direction-deg", "0"];
    let with = |extra: &[&str]| {
        let mut v = y.to_vec();
        v.extend_from_slice(extra);
        v.extend_from_slice(&["--out-dir", "/tmp/superlube-never-written"]);
        refusal(&v)
    };
    let e = with(&["--no-dem", "--dem-check", "5"]);
    assert!(e.contains("--no-dem") && e.contains("--dem-check"), "{e}");
    let e = with(&["--theta-tol-deg", "0.1", "--theta-sigma-deg", "0.05"]);
    assert!(
        e.contains("--theta-tol-deg") && e.contains("--theta-sigma-deg"),
        "{e}"
    );
    let e = with(&["--direction-tol-deg", "0.5", "--direction-sigma-deg", "0.2"]);
    assert!(
        e.contains("--direction-tol-deg") && e.contains("--direction-sigma-deg"),
        "{e}"
    );
    let e = refusal(&["yield", "--pattern", "tri-tri", "--alpha-deg", "90"]);
    assert!(
        e.contains("--direction-deg") && !e.contains("'--theta-deg'"),
        "{e}"
    );
    assert!(!std::path::Path::new("/tmp/superlube-never-written").exists());
}

/// An error the solver computes in SI reaches the user in mN.
#[test]
fn a_load_that_cannot_be_carried_is_given_in_mn() {
    // a one-sphere-wide slider on soft spheres: the largest load crushes them
    let e = refusal(&[
        "screen",
        "--pattern",
        "tri-tri",
        "--youngs-gpa",
        "0.0001",
        "--slider-radius-um",
        "1.5",
        "--theta-deg",
        "0",
        "--load-mn",
        "9000",
    ]);
    assert!(!e.contains(" N cannot") && !e.contains("e-"), "{e}");
}
