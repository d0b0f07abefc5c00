//! `superlube design --vary` (issue 36): scene fields as design variables. A varied field gives
//! the rows of a scene file written with that value; bad input is refused naming `--vary`
//! before any work; recipes that cannot be made are refused naming the field, or skipped and
//! counted with `--skip-invalid`.

mod common;
use common::{assert_ok, bin, fails_naming, run_small, tmpdir, SMALL_SCENE};
use std::path::Path;

/// On the small scene (a 15 µm slider on a 60 µm substrate): a few θ and loads (fast).
const SMALL: [&str; 6] = [
    "--theta",
    "0:15:3",
    "--load-mn",
    "0.01,0.03,0.06,0.09",
    "--theta-tol-deg",
    "0",
];

fn design(extra: &[&str], out: &Path) -> std::process::Output {
    run_small(
        "design",
        &[&SMALL, &["--direction-tol-deg", "0", "--no-dem"], extra],
        out,
    )
}

/// The rows of a CSV without the column `drop` (the pattern's name).
fn rows_without(path: &Path, drop: &str) -> Vec<Vec<String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let k = r.headers().unwrap().iter().position(|c| c == drop);
    r.records()
        .map(|x| {
            x.unwrap()
                .iter()
                .enumerate()
                .filter(|(i, _)| Some(*i) != k)
                .map(|(_, v)| v.to_string())
                .collect()
        })
        .collect()
}

#[test]
fn a_varied_field_gives_the_rows_of_the_scene_file_written_with_it() {
    let d = tmpdir("recipe-rows");
    let o = design(
        &[
            "--vary",
            "slider.sphere_diameter_um=2.5",
            "--vary",
            "slider.material.youngs_GPa=50",
        ],
        &d.join("vary"),
    );
    assert_ok(&o);
    let name = "square-tri+slider.sphere_diameter_um=2.5+slider.material.youngs_GPa=50";
    let recipe = d.join("vary/recipes").join(format!("{name}.toml"));
    assert!(recipe.exists(), "the recipe's scene file");
    // the same recipe written by hand (the flags above override the file's slider radius and
    // substrate as they override the preset)
    let file = d.join("written.toml");
    std::fs::write(
        &file,
        "pattern = 'square-tri'\n[slider]\nsphere_diameter_um = 2.5\n[slider.material]\nyoungs_GPa = 50\n",
    )
    .unwrap();
    let f = file.to_str().unwrap();
    let out = d.join("file");
    let o2 = bin()
        .arg("design")
        .args(&SMALL_SCENE[2..])
        .args(SMALL)
        .args([
            "--scene",
            f,
            "--direction-tol-deg",
            "0",
            "--no-dem",
            "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert_ok(&o2);
    for (a, b) in [
        (format!("screen_{name}.csv"), "screen_written.csv"),
        (format!("friction_{name}.csv"), "friction_written.csv"),
    ] {
        assert_eq!(
            std::fs::read(d.join("vary").join(&a)).unwrap(),
            std::fs::read(out.join(b)).unwrap(),
            "{a}"
        );
    }
    assert_eq!(
        rows_without(&d.join("vary/ranking.csv"), "pattern"),
        rows_without(&out.join("ranking.csv"), "pattern")
    );
    let pats = std::fs::read_to_string(d.join("vary/patterns.csv")).unwrap();
    assert!(pats.contains(name), "{pats}");
    // outside the study's 3 µm / 100 GPa: flagged
    let log = String::from_utf8_lossy(&o.stderr);
    let report = std::fs::read_to_string(d.join("vary/report.md")).unwrap();
    assert!(
        report.contains("outside the validated range")
            || log.contains("outside the validated range"),
        "{log}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn bad_vary_input_is_refused_naming_the_flag() {
    let d = tmpdir("recipe-bad");
    let out = d.join("o");
    let o = out.to_str().unwrap();
    let base = ["design", "--pattern", "square-tri", "--no-dem", "--out", o];
    for (v, what) in [
        ("slider.diameter_um=2,3", "diameter_um"),
        ("slider.tilt=1", "slider.tilt"),
        ("slider.sphere_diameter_um=", "empty"),
        ("slider.sphere_diameter_um", "FIELD=LIST"),
    ] {
        fails_naming(&[&base[..], &["--vary", v]].concat(), "--vary");
        fails_naming(&[&base[..], &["--vary", v]].concat(), what);
    }
    // overlapping spheres: refused naming the field and value, or skipped and counted
    let grid = ["--vary", "slider.sphere_diameter_um=2.5,3.5"];
    fails_naming(
        &[&base[..], &grid].concat(),
        "slider.sphere_diameter_um = 3.5",
    );
    assert!(!out.join("report.md").exists());
    let o = design(&[&grid[..], &["--skip-invalid"]].concat(), &out);
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(log.contains("1 of 2 recipes skipped"), "{log}");
    let _ = std::fs::remove_dir_all(&d);
}
