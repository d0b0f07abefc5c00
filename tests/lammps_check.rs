//! `superlube lammps-check` reads the contact dump of an exported deck's LAMMPS run and agrees
//! with the deck's own time series, finding the contacts above P_crit.
//!
//! Without `lmp` this test prints that it is skipped and passes — unless
//! `SUPERLUBE_REQUIRE_LAMMPS=1` (CI sets it in `.ci/run`), which turns the skip into a failure.

mod common;
use common::lammps::*;

#[test]
fn lammps_check_reads_a_dump_and_finds_contacts_above_p_crit() {
    // No LAMMPS needed: a hand-written dump of the exported small scene, with pair distances
    // chosen for known pressures p0 = (2E*/π)√(δ/R_eff), E* = 54.945 GPa, R_eff = 0.75 µm.
    let dir = tmpdir("check");
    let meta = export(
        &dir,
        &[
            SMALL,
            &["--load-mn", "0.1", "--p-crit-gpa", "3", "--slide-us", "20"],
        ]
        .concat(),
    );
    let sl = meta["ids"]["slider"]["first"].as_u64().unwrap();
    let sb = meta["ids"]["substrate"]["first"].as_u64().unwrap();
    let pref = 2.0 * meta["e_star_GPa"].as_f64().unwrap() / std::f64::consts::PI;
    let dist = |p0: f64| 3.0 - 0.75 * (p0 / pref).powi(2);
    let frame = |step: u64, pairs: &[(u64, u64, f64)]| {
        let mut s = format!(
            "ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ENTRIES\n{}\nITEM: BOX BOUNDS ss ss ss\n-1 1\n-1 1\n-1 1\nITEM: ENTRIES c_cpl c_cpa[1] c_cpa[2]\n",
            pairs.len()
        );
        for (a, b, d) in pairs {
            s += &format!("{d:.17} {a} {b}\n");
        }
        s
    };
    let dump = frame(0, &[(sl, sb + 3, dist(1.0)), (sb + 7, sl + 2, dist(2.0))])
        + &frame(
            100,
            &[
                (sl + 4, sb, dist(3.5)),
                (sl + 1, sb + 1, dist(1.0)),
                (sl, sb, dist(3.2)),
            ],
        )
        + &frame(200, &[]);
    std::fs::write(dir.join("contacts.dump"), &dump).unwrap();
    let out = bin()
        .args(["lammps-check"])
        .arg(dir.join("contacts.dump"))
        .arg("--failed-out")
        .arg(dir.join("failed.csv"))
        .output()
        .unwrap();
    assert_ok("lammps-check", &out);
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<Vec<String>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    assert_eq!(
        text.lines().next().unwrap(),
        "step,t_us,phase,contacts,p_max_GPa,failed_contacts"
    );
    assert_eq!(rows.len(), 3);
    assert_eq!((rows[0][3].as_str(), rows[0][5].as_str()), ("2", "0"));
    assert!((rows[0][4].parse::<f64>().unwrap() - 2.0).abs() < 1e-9);
    assert_eq!((rows[1][3].as_str(), rows[1][5].as_str()), ("3", "2"));
    assert!((rows[1][4].parse::<f64>().unwrap() - 3.5).abs() < 1e-9);
    assert_eq!(
        (rows[2][3].as_str(), rows[2][4].parse::<f64>().unwrap()),
        ("0", 0.0)
    );
    let failed = std::fs::read_to_string(dir.join("failed.csv")).unwrap();
    let f: Vec<&str> = failed.lines().collect();
    assert_eq!(f[0], "step,t_us,slider_index,substrate_index,p0_GPa");
    // sorted by slider index: (0, 0) at 3.2 GPa, then (4, 0) at 3.5 GPa
    let fields = |l: &str| {
        l.split(',')
            .map(|v| v.parse::<f64>().unwrap())
            .collect::<Vec<_>>()
    };
    assert_eq!(f.len(), 3, "{failed}");
    let (a, b) = (fields(f[1]), fields(f[2]));
    assert_eq!(
        (a[0], a[2], a[3], b[2], b[3]),
        (100.0, 0.0, 0.0, 4.0, 0.0),
        "{failed}"
    );
    assert!(
        (a[4] - 3.2).abs() < 1e-9 && (b[4] - 3.5).abs() < 1e-9,
        "{failed}"
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("INVALID") && err.contains("1 of 3 frames"),
        "{err}"
    );

    // bad input: a non-pair, a truncated dump, a missing export.json
    let bad = frame(0, &[(sl, sl + 1, 2.99)]);
    std::fs::write(dir.join("bad.dump"), bad).unwrap();
    let out = bin()
        .arg("lammps-check")
        .arg(dir.join("bad.dump"))
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a slider–substrate pair"));
    std::fs::write(dir.join("cut.dump"), &dump[..dump.len() / 2]).unwrap();
    let out = bin()
        .arg("lammps-check")
        .arg(dir.join("cut.dump"))
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("cut.dump line"));
    let other = tmpdir("check-nometa");
    std::fs::write(other.join("contacts.dump"), &dump).unwrap();
    let out = bin()
        .arg("lammps-check")
        .arg(other.join("contacts.dump"))
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--meta"));
    let out = bin()
        .arg("lammps-check")
        .arg(other.join("missing.dump"))
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("DUMP"));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&other);
}
