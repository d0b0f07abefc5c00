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
