//! `superlube landscape` and `superlube corrugation` end to end: columns, files, bad input.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};

#[test]
fn landscape_writes_csv_and_png() {
    let d = tmpdir("landscape");
    let (csv, png) = (d.join("dz.csv"), d.join("dz.png"));
    let out = bin()
        .args([
            "landscape",
            "--pattern",
            "square-tri",
            "--theta",
            "0",
            "--load-mn",
            "1.4",
            "--grid",
            "5",
        ])
        .arg("--out")
        .arg(&csv)
        .arg("--plot")
        .arg(&png)
        .output()
        .unwrap();
    assert_ok(&out);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next().unwrap(), "x_um,y_um,dz_nm");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 25);
    // Δz ≥ 0 with its minimum exactly 0; the grid spans the 3 × 3√3 µm cell.
    assert!(rows.iter().all(|r| r[2] >= 0.0));
    assert!(rows.iter().any(|r| r[2] == 0.0));
    let xmax = rows.iter().map(|r| r[0]).fold(0.0, f64::max);
    let ymax = rows.iter().map(|r| r[1]).fold(0.0, f64::max);
    assert!((xmax - 3.0).abs() < 1e-9 && (ymax - 3.0 * 3f64.sqrt()).abs() < 1e-6);
    let png = std::fs::read(&png).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn corrugation_columns_and_contact_line_result() {
    let out = bin()
        .args([
            "corrugation",
            "--pattern",
            "square-tri",
            "--theta",
            "0",
            "--load-mn",
            "1.4",
            "--alpha",
            "0,90",
            "--distance-um",
            "6",
            "--step-um",
            "0.1",
        ])
        .output()
        .unwrap();
    assert_ok(&out);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    // One corrugation schema for the command and the figure.
    assert_eq!(
        lines.next().unwrap(),
        "theta_deg,load_mN,line_deg,alpha_deg,direction_deg,corrugation_nm,max_lateral_force_mN"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 2);
    assert_eq!(&rows[0][..4], &[0.0, 1.4, 0.0, 0.0]);
    assert_eq!(rows[1][3], 90.0);
    // Along the contact line: tens of nm; across it: below 2 nm.
    assert!(rows[0][5] > 50.0 && rows[1][5] < 2.0, "{rows:?}");
}

#[test]
fn bad_input_names_the_field() {
    fails_naming(&["landscape", "--grid", "0"], "--grid");
    fails_naming(&["corrugation", "--alpha", "200"], "--alpha");
    fails_naming(&["corrugation", "--alpha", "-181,0"], "--alpha");
    fails_naming(&["landscape", "--substrate-um", "0x0"], "substrate.size_um");
    fails_naming(&["landscape", "--load-mn", "0"], "load");
    fails_naming(
        &["corrugation", "--alpha", "0", "--distance-um", "500"],
        "distance_um",
    );
    fails_naming(
        &["landscape", "--grid", "3", "--offset-um", "1000,0"],
        "offset",
    );
}
