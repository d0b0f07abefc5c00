//! `superlube screen` end to end: CSV header, reference row, per-contact list, bad input.

mod common;
use common::{assert_ok, bin, fails_naming};

const HEADER: &str = "pattern,theta_deg,load_mN,contacts,p_max_GPa,z_um,coating_failed";

#[test]
fn reference_row_and_header() {
    let out = bin()
        .args([
            "screen",
            "--pattern",
            "tri-tri",
            "--theta",
            "0,30",
            "--load-mn",
            "3.86",
        ])
        .output()
        .unwrap();
    assert_ok(&out);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert!(lines.next().unwrap().starts_with(&format!("{HEADER},")));
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(&row[..4], &["tri-tri", "0.0", "3.86", "3505"]);
    let p: f64 = row[4].parse().unwrap();
    assert!((p - 1.05).abs() < 0.021, "{p}");
    assert_eq!(row[6], "false");
    assert_eq!(text.lines().count(), 3);
}

#[test]
fn default_is_square_tri_and_contacts_out() {
    let dir = std::env::temp_dir().join(format!("superlube-screen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("s.csv");
    let cts = dir.join("c.csv");
    let out = bin()
        .args(["screen", "--theta", "0", "--load-mn", "2.1", "--out"])
        .arg(&csv)
        .arg("--contacts-out")
        .arg(&cts)
        .output()
        .unwrap();
    assert_ok(&out);
    let text = std::fs::read_to_string(&csv).unwrap();
    let row: Vec<String> = text
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(String::from)
        .collect();
    assert_eq!(row[0], "square-tri");
    let n: usize = row[3].parse().unwrap();
    let c = std::fs::read_to_string(&cts).unwrap();
    assert!(c.starts_with(
        "slider_index,substrate_index,x_um,y_um,z_um,overlap_nm,force_uN,p0_GPa,failed"
    ));
    assert_eq!(c.lines().count(), n + 1);
    let f: f64 = c
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(6).unwrap().parse::<f64>().unwrap())
        .sum();
    assert!(f > 2000.0, "{f} µN"); // normal forces ≥ vertical share of 2.1 mN
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_input_names_the_field() {
    fails_naming(&["screen", "--load-mn", "0"], "--load-mn");
    fails_naming(&["screen", "--load-mn", "NaN"], "--load-mn");
    fails_naming(&["screen", "--load-mn", "-1"], "--load-mn");
    fails_naming(&["screen", "--slider-radius-um=-5"], "slider.radius_um");
    // The space-separated form must reach the scene validation too (not a clap parse error).
    fails_naming(&["screen", "--slider-radius-um", "-5"], "slider.radius_um");
    fails_naming(&["screen", "--youngs-gpa", "-100"], "youngs_GPa");
    fails_naming(&["screen", "--pattern", "hex-tri"], "pattern");
    fails_naming(&["screen", "--model", "elastic"], "model");
    fails_naming(&["screen", "--theta", "0:30"], "--theta");
    fails_naming(&["screen", "--sigma-h-um", "2"], "sigma_h_um");
    fails_naming(
        &[
            "screen",
            "--theta",
            "0,1",
            "--load-mn",
            "1",
            "--contacts-out",
            "x.csv",
        ],
        "--contacts-out",
    );
}

/// Same inputs → byte-identical CSV whatever the number of rayon threads.
#[test]
fn output_independent_of_thread_count() {
    let run = |threads: &str| {
        let out = bin()
            .env("RAYON_NUM_THREADS", threads)
            .args([
                "screen",
                "--pattern",
                "square-tri",
                "--theta",
                "0:12:1.5",
                "--load-mn",
                "0.35,3.86",
                "--sigma-h-um",
                "0.002",
                "--seed",
                "3",
            ])
            .output()
            .unwrap();
        assert!(out.status.success());
        out.stdout
    };
    let one = run("1");
    assert_eq!(String::from_utf8_lossy(&one).lines().count(), 1 + 9 * 2);
    assert_eq!(one, run("3"));
}
