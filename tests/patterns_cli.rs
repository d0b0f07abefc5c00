//! `superlube patterns` and pattern geometry through the command line: a honeycomb as a basis
//! and as a site file screen identically; generated candidates run on their own; bad input is
//! named before any work.

mod common;
use common::{assert_ok, bin, fails_naming, tmpdir};
use surrogate::units::m_to_um;

fn screen(scene: &std::path::Path) -> String {
    let out = bin()
        .args([
            "screen",
            "--theta",
            "0,13,30",
            "--load-mn",
            "0.35,2.1",
            "--scene",
        ])
        .arg(scene)
        .output()
        .unwrap();
    assert_ok(&out);
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn honeycomb_basis_and_site_file_give_identical_screen_rows() {
    let dir = tmpdir("patterns-honeycomb");
    let basis = dir.join("basis.toml");
    std::fs::write(
        &basis,
        "[substrate]\nsize_um = [120, 120]\n[slider]\nradius_um = 30\nsphere_diameter_um = 1.5\nlattice = { kind = 'honeycomb', spacing_um = 3.0 }\n",
    )
    .unwrap();
    // the same sites, written as a site file (shortest decimals in µm)
    let scene = surrogate::SceneFile::read(&basis)
        .unwrap()
        .into_scene()
        .unwrap();
    let mut csv = String::from("x_um,y_um\n");
    for p in scene.slider_sites_local() {
        csv += &format!("{},{}\n", m_to_um(p[0]), m_to_um(p[1]));
    }
    std::fs::write(dir.join("honeycomb.csv"), csv).unwrap();
    let file = dir.join("file.toml");
    std::fs::write(
        &file,
        "[substrate]\nsize_um = [120, 120]\n[slider]\nradius_um = 30\nsphere_diameter_um = 1.5\nsites = 'honeycomb.csv'\n",
    )
    .unwrap();
    let (a, b) = (screen(&basis), screen(&file));
    assert_eq!(a.lines().count(), 7);
    assert_eq!(a, b);
}

#[test]
fn directional_candidates_are_written_and_run_on_their_own() {
    let dir = tmpdir("patterns-directional");
    let out = bin()
        .args([
            "patterns",
            "--family",
            "directional",
            "--max-pq",
            "2",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_ok(&out);
    let index = std::fs::read_to_string(dir.join("index.csv")).unwrap();
    let mut lines = index.lines();
    assert!(lines.next().unwrap().starts_with(
        "pattern_id,scene_file,lattice,basis,outline,spheres,commensurate_direction_deg,p_q,contact_line_spacing_um,contact_type"
    ));
    let first: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(first[0], "p001");
    assert_eq!(first[9], "directional");
    assert!(dir.join("index.csv.meta.json").exists());
    let rows = screen(&dir.join(first[1]));
    assert_eq!(rows.lines().count(), 7);
}

#[test]
fn bad_input_is_named() {
    fails_naming(
        &[
            "patterns",
            "--family",
            "rectangular:a=1,b=2",
            "--out",
            "/tmp/x",
        ],
        "--family",
    );
    fails_naming(
        &["patterns", "--family", "hexagonal", "--out", "/tmp/x"],
        "--family",
    );
    let dir = tmpdir("patterns-bad");
    let f = dir.join("bad.toml");
    std::fs::write(
        &f,
        "[slider]\noutline = { kind = 'rectangle', size_um = [0, 80] }\n",
    )
    .unwrap();
    fails_naming(
        &["screen", "--scene", f.to_str().unwrap()],
        "slider.outline",
    );
    let idx = dir.join("index.csv");
    std::fs::write(&idx, "pattern_id,lattice\np001,square\n").unwrap();
    fails_naming(
        &["design", "--no-dem", "--patterns", idx.to_str().unwrap()],
        "--patterns",
    );
}

/// `--normalize spheres`: every candidate's outline holds about the base slider's sphere count
/// (within the step one lattice row makes), while `area` keeps the outline and lets it vary.
#[test]
fn normalize_spheres_gives_every_candidate_the_base_sphere_count() {
    let count = |normalize: &str| -> Vec<(String, usize)> {
        let dir = tmpdir(&format!("patterns-normalize-{normalize}"));
        let out = bin()
            .args([
                "patterns",
                "--family",
                "presets:s=3:6:3",
                "--slider-radius-um",
                "20",
            ])
            .args(["--normalize", normalize, "--out"])
            .arg(&dir)
            .output()
            .unwrap();
        assert_ok(&out);
        let index = std::fs::read_to_string(dir.join("index.csv")).unwrap();
        let v = index
            .lines()
            .skip(1)
            .map(|l| {
                let f: Vec<&str> = l.split(',').collect();
                (f[2].to_string(), f[5].parse().unwrap())
            })
            .collect();
        std::fs::remove_dir_all(&dir).ok();
        v
    };
    let area = count("area");
    let spheres = count("spheres");
    assert!(area.len() >= 4, "{area:?}");
    // the base is square-tri's 3 µm square lattice: its first candidate (s = 3) keeps its count
    let base = area
        .iter()
        .find(|(l, _)| l == "square")
        .expect("a square preset")
        .1;
    for (l, n) in &spheres {
        assert!(
            (*n as f64 - base as f64).abs() <= 0.05 * base as f64,
            "{l}: {n} spheres against the base's {base} ({spheres:?})"
        );
    }
    let (lo, hi) = (
        area.iter().map(|x| x.1).min().unwrap(),
        area.iter().map(|x| x.1).max().unwrap(),
    );
    assert!(hi as f64 > 1.3 * lo as f64, "area: {area:?}");
}

/// `design --patterns`: `patterns.csv` puts each candidate's geometry and the index's facts
/// beside its best design.
#[test]
fn design_over_patterns_writes_each_patterns_geometry_and_best_design() {
    let dir = tmpdir("patterns-design");
    let small = ["--slider-radius-um", "15", "--substrate-um", "60x60"];
    let o = bin()
        .args(["patterns", "--family", "directional", "--max-pq", "2"])
        .args(small)
        .arg("--out")
        .arg(dir.join("c"))
        .output()
        .unwrap();
    assert_ok(&o);
    let o = bin()
        .args(["design", "--no-dem", "--theta", "0:30:2", "--patterns"])
        .arg(dir.join("c/index.csv"))
        .args(["--theta-tol", "0", "--direction-tol", "0"])
        .args(small)
        .args(["--load-mn", "0.01,0.03,0.06", "--out"])
        .arg(dir.join("d"))
        .output()
        .unwrap();
    assert_ok(&o);
    let index = std::fs::read_to_string(dir.join("c/index.csv")).unwrap();
    let mut r = csv::Reader::from_path(dir.join("d/patterns.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), index.lines().count() - 1);
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    for row in &rows {
        assert_eq!(&row[col("contact_type")], "directional");
        assert!(!row[col("p_q")].is_empty());
        let spheres: f64 = row[col("spheres")].parse().unwrap();
        let w: f64 = row[col("superlubric_to_mN")].parse().unwrap();
        let per: f64 = row[col("load_per_sphere_uN")].parse().unwrap();
        assert!(
            (per - w * 1e3 / spheres).abs() <= 1e-6 * per.max(1e-9),
            "{row:?}"
        );
    }
    // The report compares the patterns in one table: a row per pattern, its spheres beside it.
    let report = std::fs::read_to_string(dir.join("d/report.md")).unwrap();
    let table = report
        .split("## Patterns compared")
        .nth(1)
        .expect("a 'Patterns compared' section")
        .split("\n## ")
        .next()
        .unwrap();
    for row in &rows {
        let line = format!(
            "| {} | {} | {} |",
            &row[col("pattern")],
            &row[col("outline")],
            &row[col("spheres")]
        );
        assert!(table.contains(&line), "{line} not in\n{table}");
    }
    // The limit against the family's parameter, and the contact maps of the best (at most 3)
    // patterns: the ones with the highest robust limit in patterns.csv.
    assert!(dir.join("d/patterns.png").exists());
    assert!(table.contains("](patterns.png)"));
    let best = rows
        .iter()
        .map(|r| r[col("superlubric_to_mN")].parse::<f64>().unwrap())
        .fold(0.0, f64::max);
    let maps: Vec<&str> = table
        .split("](contacts_")
        .skip(1)
        .map(|t| t.split(".png)").next().unwrap())
        .collect();
    assert!(!maps.is_empty() && maps.len() <= 3, "{maps:?}");
    let first = rows.iter().find(|r| &r[col("pattern")] == maps[0]).unwrap();
    assert_eq!(
        first[col("superlubric_to_mN")].parse::<f64>().unwrap(),
        best
    );
    for m in &maps {
        assert!(dir.join(format!("d/contacts_{m}.png")).exists(), "{m}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `design --family SPEC` generates the candidates into OUT/patterns/ and designs them exactly
/// as `patterns` + `design --patterns` would; a bad family is refused before anything is written.
#[test]
fn design_family_generates_and_designs_the_candidates() {
    let dir = tmpdir("design-family");
    let small = ["--slider-radius-um", "15", "--substrate-um", "60x60"];
    let design = [
        "design",
        "--no-dem",
        "--theta",
        "0:30:2",
        "--load-mn",
        "0.01,0.03",
    ];
    let tol0 = ["--theta-tol", "0", "--direction-tol", "0"];
    let family = "rectangular:a=3:3.5:0.5,b=3";
    let o = bin()
        .args(design)
        .args(["--family", family])
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("f"))
        .output()
        .unwrap();
    assert_ok(&o);
    let o = bin()
        .args(["patterns", "--family", family])
        .args(small)
        .arg("--out-dir")
        .arg(dir.join("c"))
        .output()
        .unwrap();
    assert_ok(&o);
    let o = bin()
        .args(design)
        .arg("--patterns")
        .arg(dir.join("c/index.csv"))
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("p"))
        .output()
        .unwrap();
    assert_ok(&o);
    let read = |p: &str| std::fs::read_to_string(dir.join(p)).unwrap();
    assert_eq!(read("f/patterns/index.csv"), read("c/index.csv"));
    // another family into the same folder is refused, its candidates untouched
    let before = read("f/patterns/index.csv");
    let o = bin()
        .args(design)
        .args(["--family", "rectangular:a=3.5,b=3"])
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("f"))
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("`--family`"));
    assert_eq!(read("f/patterns/index.csv"), before);
    assert_eq!(read("f/patterns.csv"), read("p/patterns.csv"));
    assert_eq!(read("f/ranking.csv"), read("p/ranking.csv"));
    let o = bin()
        .args(design)
        .args(["--family", "bogus"])
        .arg("--out-dir")
        .arg(dir.join("bad"))
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("`--family`"));
    assert!(!dir.join("bad").exists());
    std::fs::remove_dir_all(&dir).ok();
}
