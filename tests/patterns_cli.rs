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

/// A site file whose `diameter_um` column gives every sphere the same size, or leaves some cells
/// empty (the body's `sphere_diameter_um`), screens byte-identically to the same sites without
/// the column and `sphere_diameter_um` set; differing diameters change the rows.
#[test]
fn equal_site_diameters_screen_as_one_size() {
    let dir = tmpdir("patterns-equal-diameters");
    let basis = dir.join("basis.toml");
    std::fs::write(
        &basis,
        "[substrate]\nsize_um = [120, 120]\n[slider]\nradius_um = 30\nsphere_diameter_um = 1.5\nlattice = { kind = 'honeycomb', spacing_um = 3.0 }\n",
    )
    .unwrap();
    let sites = surrogate::SceneFile::read(&basis)
        .unwrap()
        .into_scene()
        .unwrap()
        .slider_sites_local();
    let write = |name: &str, header: &str, cell: &dyn Fn(usize) -> &'static str| {
        let mut csv = format!("{header}\n");
        for (i, p) in sites.iter().enumerate() {
            csv += &format!("{},{}{}\n", m_to_um(p[0]), m_to_um(p[1]), cell(i));
        }
        std::fs::write(dir.join(name), csv).unwrap();
    };
    write("plain.csv", "x_um,y_um", &|_| "");
    write("equal.csv", "x_um,y_um,diameter_um", &|_| ",1.5");
    write("mixed.csv", "x_um,y_um,diameter_um", &|i| {
        if i % 3 == 0 {
            ","
        } else {
            ",1.5"
        }
    });
    write("varied.csv", "x_um,y_um,diameter_um", &|i| {
        if i % 3 == 0 {
            ",1.2"
        } else {
            ",1.5"
        }
    });
    let scene = |name: &str, csv: &str, size: &str| {
        let f = dir.join(name);
        std::fs::write(
            &f,
            format!("[substrate]\nsize_um = [120, 120]\n[slider]\nradius_um = 30\n{size}sites = '{csv}'\n"),
        )
        .unwrap();
        screen(&f)
    };
    let reference = scene("plain.toml", "plain.csv", "sphere_diameter_um = 1.5\n");
    assert_eq!(reference.lines().count(), 7);
    assert_eq!(reference, scene("equal.toml", "equal.csv", ""));
    assert_eq!(
        reference,
        scene("mixed.toml", "mixed.csv", "sphere_diameter_um = 1.5\n")
    );
    let varied = scene("varied.toml", "varied.csv", "sphere_diameter_um = 1.5\n");
    assert_eq!(varied.lines().count(), 7);
    assert_ne!(reference, varied);
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

/// `--fair count`: every candidate's outline holds about the base slider's sphere count
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
        .args(["--theta-tol-deg", "0", "--direction-tol-deg", "0"])
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
    // best first: ranks 1, 2, …, the robust limit never rising down the table
    let limits: Vec<f64> = rows
        .iter()
        .map(|r| r[col("superlubric_to_mN")].parse().unwrap())
        .collect();
    assert!(limits.windows(2).all(|w| w[0] >= w[1]), "{limits:?}");
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[col("rank")], (k + 1).to_string());
    }
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
    // the fairness rule, from the index's sidecar (`--fair area`, the default)
    assert!(
        table.contains("Compared at **equal slider area**: the candidates were made with `superlube patterns --fair area`"),
        "{table}"
    );
    for row in &rows {
        let line = format!(
            "| {} | {} | {} | {} |",
            &row[col("rank")],
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
    let tol0 = ["--theta-tol-deg", "0", "--direction-tol-deg", "0"];
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
    assert!(
        String::from_utf8_lossy(&o.stderr)
            .contains("candidates in the contact-type pre-screen's order"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    fails_naming(
        &[
            "design",
            "--no-dem",
            "--normalize",
            "spheres",
            "--out-dir",
            "/tmp/x",
        ],
        "--family",
    );
    // --normalize spheres: candidates of (about) the base slider's sphere count, and the report
    // says that this is the rule of the comparison
    let o = bin()
        .args([
            "design",
            "--no-dem",
            "--theta",
            "0:30:10",
            "--load-mn",
            "0.01",
        ])
        .args(["--family", "presets:s=3:3.5:0.5", "--normalize", "spheres"])
        .args(small)
        .args(tol0)
        .arg("--out-dir")
        .arg(dir.join("n"))
        .output()
        .unwrap();
    assert_ok(&o);
    let index = std::fs::read_to_string(dir.join("n/patterns/index.csv")).unwrap();
    let spheres: Vec<f64> = index
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(5).unwrap().parse().unwrap())
        .collect();
    assert!(spheres.len() >= 3, "{index}");
    let (lo, hi) = spheres
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    assert!(hi <= 1.1 * lo, "{spheres:?}");
    let report = std::fs::read_to_string(dir.join("n/report.md")).unwrap();
    assert!(
        report.contains("Compared at **equal sphere count**: the candidates were made with `superlube patterns --fair count`"),
        "{report}"
    );
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

/// The three geometries of the smoke tests, each a scene file in `dir` with a 15 µm slider
/// (3 µm spheres on both bodies, so that the DEM takes them): a honeycomb basis, a polygon
/// outline, a slider site file. Returns (name, scene file, its slider sphere count).
fn geometries(dir: &std::path::Path) -> Vec<(&'static str, std::path::PathBuf, usize)> {
    let sub = "[substrate]\nsize_um = [100, 100]\n";
    let mut csv = String::from("x_um,y_um\n");
    // an irregular pad: a 3.5 µm grid with a vacancy and one row shifted
    for i in -3i32..=3 {
        for j in -3i32..=3 {
            if (i, j) != (1, 2) {
                let x = 3.5 * i as f64 + if j == 0 { 1.0 } else { 0.0 };
                csv += &format!("{x},{}\n", 3.5 * j as f64);
            }
        }
    }
    std::fs::write(dir.join("pad.csv"), csv).unwrap();
    let scenes = [
        (
            "basis",
            format!("pattern = 'tri-tri'\n{sub}[slider]\nradius_um = 15\nlattice = {{ kind = 'honeycomb', spacing_um = 6.0 }}\n"),
        ),
        (
            "outline",
            format!("pattern = 'square-tri'\n{sub}[slider]\noutline = {{ kind = 'polygon', vertices_um = [[-15, -12], [15, -12], [18, 6], [0, 15], [-15, 6]] }}\n"),
        ),
        (
            "sites",
            format!("pattern = 'square-tri'\n{sub}[slider]\nsites = 'pad.csv'\n"),
        ),
    ];
    scenes
        .iter()
        .map(|(name, text)| {
            let f = dir.join(format!("{name}.toml"));
            std::fs::write(&f, text).unwrap();
            let n = surrogate::SceneFile::read(&f)
                .unwrap()
                .into_scene()
                .unwrap()
                .slider_sites_local()
                .len();
            (*name, f, n)
        })
        .collect()
}

/// The screen's contacts of `scene` at θ = 0 and `load` mN.
fn screen_contacts(scene: &std::path::Path, load: &str) -> usize {
    let out = bin()
        .args(["screen", "--theta", "0", "--load-mn", load, "--scene"])
        .arg(scene)
        .output()
        .unwrap();
    assert_ok(&out);
    let mut r = csv::Reader::from_reader(&out.stdout[..]);
    let h = r.headers().unwrap().clone();
    let c = h.iter().position(|x| x == "contacts").unwrap();
    r.records().next().unwrap().unwrap()[c].parse().unwrap()
}

fn json(path: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `landscape`, `corrugation` and `friction` run on a basis, an outline and a site file: one
/// row per grid point / α / load, and each result differs from the base preset's (the geometry
/// is used, not the preset the scene starts from). A site-file slider has no lattice for the
/// contact-line estimate: without `--line-deg` the commands that take α refuse it, naming it.
#[test]
fn maps_and_friction_run_on_bases_outlines_and_site_files() {
    let dir = tmpdir("geometry-maps");
    let run = |args: &[&str], scene: &std::path::Path, line: bool, out: &std::path::Path| {
        let mut c = bin();
        c.args(args).arg("--scene").arg(scene).arg("--out").arg(out);
        if line && args[0] != "landscape" {
            c.args(["--line-deg", "0"]);
        }
        let o = c.output().unwrap();
        assert_ok(&o);
        assert!(crate_sidecar(out).exists(), "{}", out.display());
        std::fs::read_to_string(out).unwrap()
    };
    let landscape = [
        "landscape",
        "--theta",
        "0",
        "--load-mn",
        "0.05",
        "--grid",
        "4",
    ];
    let corrugation = [
        "corrugation",
        "--theta",
        "0",
        "--load-mn",
        "0.05",
        "--alpha",
        "0,90",
        "--distance-um",
        "3",
        "--step-um",
        "0.5",
    ];
    let friction = [
        "friction",
        "--theta",
        "0",
        "--load-mn",
        "0.02,0.05",
        "--alpha",
        "0",
    ];
    for (name, scene, _) in geometries(&dir) {
        let sites = name == "sites";
        let base = dir.join(format!("{name}-base.toml"));
        let text = std::fs::read_to_string(&scene).unwrap();
        // the base preset with a plain 15 µm disc slider
        let plain = text.split("[slider]").next().unwrap();
        std::fs::write(&base, format!("{plain}[slider]\nradius_um = 15\n")).unwrap();
        for (args, rows) in [
            (&landscape[..], 16),
            (&corrugation[..], 2),
            (&friction[..], 2),
        ] {
            let out = dir.join(format!("{name}-{}.csv", args[0]));
            let got = run(args, &scene, sites, &out);
            assert_eq!(got.lines().count(), rows + 1, "{name} {}: {got}", args[0]);
            let plain = run(
                args,
                &base,
                sites,
                &dir.join(format!("{name}-{}-base.csv", args[0])),
            );
            assert_ne!(got, plain, "{name} {}: the geometry is not used", args[0]);
            if sites && args[0] != "landscape" {
                let o = bin()
                    .args(args)
                    .arg("--scene")
                    .arg(&scene)
                    .output()
                    .unwrap();
                assert!(!o.status.success(), "{name} {}", args[0]);
                let e = String::from_utf8_lossy(&o.stderr);
                assert!(e.contains("`--line-deg`") && e.contains("pad.csv"), "{e}");
            }
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

fn crate_sidecar(p: &std::path::Path) -> std::path::PathBuf {
    let mut s = p.as_os_str().to_owned();
    s.push(".meta.json");
    s.into()
}

/// `equilibrate`, `slide` (about 1 µs) and `export-lammps` run on a basis, an outline and a
/// site file: the DEM starts from the surrogate's contacts of the same scene (the screen's), and
/// the export's data holds one slider sphere per site of the scene.
#[test]
fn dem_tiers_and_export_run_on_bases_outlines_and_site_files() {
    let dir = tmpdir("geometry-dem");
    let dem = [
        "--theta",
        "0",
        "--load-mn",
        "0.05",
        "--equilibrate-us",
        "0.3",
        "--rigid-z",
    ];
    for (name, scene, n) in geometries(&dir) {
        let line: &[&str] = if name == "sites" {
            &["--line-deg", "0"]
        } else {
            &[]
        };
        let contacts = screen_contacts(&scene, "0.05");
        assert!(contacts > 0 && contacts <= n, "{name}: {contacts} of {n}");
        let js = dir.join(format!("{name}-eq.json"));
        let o = bin()
            .arg("equilibrate")
            .args(dem)
            .arg("--scene")
            .arg(&scene)
            .arg("--out")
            .arg(dir.join(format!("{name}-eq.csv")))
            .arg("--json")
            .arg(&js)
            .output()
            .unwrap();
        assert_ok(&o);
        assert_eq!(
            json(&js)["surrogate_contacts"].as_u64(),
            Some(contacts as u64),
            "{name}"
        );
        let js = dir.join(format!("{name}-slide.json"));
        let o = bin()
            .arg("slide")
            .args(dem)
            .args([
                "--relax-us",
                "0.2",
                "--slide-us",
                "0.5",
                "--speed-m-s",
                "1",
                "--prune",
            ])
            .args(["--alpha", "0"])
            .args(line)
            .arg("--scene")
            .arg(&scene)
            .arg("--out")
            .arg(dir.join(format!("{name}-slide.csv")))
            .arg("--json")
            .arg(&js)
            .output()
            .unwrap();
        assert_ok(&o);
        let j = json(&js);
        assert!(
            j["mean_contacts"].as_f64().unwrap() <= n as f64,
            "{name}: {j}"
        );
        let out = dir.join(format!("{name}-lammps"));
        let o = bin()
            .args([
                "export-lammps",
                "--theta",
                "0",
                "--load-mn",
                "0.05",
                "--slide-us",
                "1",
            ])
            .args(line)
            .arg("--scene")
            .arg(&scene)
            .arg("--out-dir")
            .arg(&out)
            .output()
            .unwrap();
        assert_ok(&o);
        let e = json(&out.join("export.json"));
        assert_eq!(
            e["ids"]["slider"]["count"].as_u64(),
            Some(n as u64),
            "{name}"
        );
        if name == "sites" {
            let o = bin()
                .args(["slide", "--theta", "0", "--load-mn", "0.05", "--scene"])
                .arg(&scene)
                .output()
                .unwrap();
            assert!(!o.status.success());
            assert!(String::from_utf8_lossy(&o.stderr).contains("`--line-deg`"));
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Without `--theta`, a pattern whose symmetry cannot be derived (a substrate from a site file)
/// is screened over the whole 0–360° at the wide-domain step, and the log and the report say
/// so; a `--theta` that covers only part of the domain is named, with the part not screened.
#[test]
fn design_screens_the_whole_domain_without_theta_and_names_a_partial_one() {
    let dir = tmpdir("design-domain");
    let mut csv = String::from("x_um,y_um\n");
    for j in -9i32..=9 {
        for i in -10i32..=10 {
            let x = 3.2 * i as f64 + if j % 2 == 0 { 0.0 } else { 1.6 };
            let y = 2.8 * j as f64;
            if x.abs() <= 30.0 {
                csv += &format!("{x},{y}\n");
            }
        }
    }
    std::fs::write(dir.join("sub.csv"), csv).unwrap();
    let scene = dir.join("free.toml");
    std::fs::write(
        &scene,
        "pattern = 'tri-tri'\n[slider]\nradius_um = 6\n[substrate]\nsize_um = [60, 60]\nsites = 'sub.csv'\n",
    )
    .unwrap();
    let design = |theta: Option<&str>, out: &str| {
        let mut c = bin();
        c.args(["design", "--no-dem", "--load-mn", "0.005,0.01"])
            .args(["--theta-tol-deg", "0", "--direction-tol-deg", "0"])
            .args([
                "--max-top",
                "2",
                "--per-level",
                "1",
                "--alpha-step-deg",
                "45",
            ])
            .args(["--alpha-refine-deg", "none", "--scan-distance-um", "2"])
            .args(["--scan-step-um", "0.5", "--scene"])
            .arg(&scene)
            .arg("--out-dir")
            .arg(dir.join(out));
        if let Some(t) = theta {
            c.args(["--theta", t]);
        }
        let o = c.output().unwrap();
        assert_ok(&o);
        let log = String::from_utf8_lossy(&o.stderr).into_owned();
        let report = std::fs::read_to_string(dir.join(out).join("report.md")).unwrap();
        let mut r = csv::Reader::from_path(dir.join(out).join("screen_free.csv")).unwrap();
        let h = r.headers().unwrap().clone();
        let c = h.iter().position(|x| x == "theta_deg").unwrap();
        let mut thetas: Vec<f64> = r
            .records()
            .map(|x| x.unwrap()[c].parse().unwrap())
            .collect();
        thetas.dedup();
        (log, report, thetas)
    };
    let (log, report, thetas) = design(None, "whole");
    let step = 0.25;
    assert_eq!(thetas.len(), (360.0 / step) as usize, "{log}");
    assert_eq!(thetas[0], 0.0);
    assert_eq!(*thetas.last().unwrap(), 360.0 - step);
    for note in [&log, &report] {
        assert!(
            note.contains("no `--theta-deg` given: the whole domain at 0.25°"),
            "{note}"
        );
        assert!(!note.contains("not screened"), "{note}");
    }
    let (log, report, thetas) = design(Some("0:30:1"), "part");
    assert_eq!(thetas.len(), 31);
    let gap = "the θ list does not cover the domain [0°, 360°): 30°–360° not screened";
    assert!(log.contains(gap), "{log}");
    assert!(report.contains(&format!("**{gap}")), "{report}");
    std::fs::remove_dir_all(&dir).ok();
}

/// With more than three patterns and a tolerance, `design` takes the patterns best nominal
/// design first and does not search the tolerance boxes of candidates that cannot enter the
/// best three: the best three limits are those of each pattern designed alone, and a pattern
/// left out is marked as an upper bound (`robust_exact = false`) that its own robust limit
/// does not exceed.
#[test]
fn design_over_many_patterns_searches_only_those_that_can_win() {
    let dir = tmpdir("patterns-floor");
    let small = ["--slider-radius-um", "15", "--substrate-um", "60x60"];
    let o = bin()
        .args(["patterns", "--family", "rectangular:a=3:4:0.5,b=3:3.5:0.5"])
        .args(small)
        .arg("--out-dir")
        .arg(dir.join("c"))
        .output()
        .unwrap();
    assert_ok(&o);
    let design = [
        "design",
        "--no-dem",
        "--theta",
        "0:30:3",
        "--load-mn",
        "0.02,0.05,0.1,0.2",
    ];
    let o = bin()
        .args(design)
        .arg("--patterns")
        .arg(dir.join("c/index.csv"))
        .args(small)
        .arg("--out-dir")
        .arg(dir.join("m"))
        .output()
        .unwrap();
    assert_ok(&o);
    let log = String::from_utf8_lossy(&o.stderr);
    assert!(
        log.contains("each at its nominal orientation first"),
        "{log}"
    );
    // each pattern alone: its exact robust limit (rank 1 of its ranking.csv)
    let first = |path: &std::path::Path, col: &str| -> String {
        let mut r = csv::Reader::from_path(path).unwrap();
        let h = r.headers().unwrap().clone();
        let i = h.iter().position(|c| c == col).unwrap();
        let row = r.records().next().unwrap().unwrap();
        row[i].to_string()
    };
    let mut r = csv::Reader::from_path(dir.join("m/patterns.csv")).unwrap();
    let h = r.headers().unwrap().clone();
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    let rows: Vec<(String, f64, bool)> = r
        .records()
        .map(|x| {
            let x = x.unwrap();
            (
                x[col("pattern")].to_string(),
                x[col("superlubric_to_mN")].parse().unwrap(),
                x[col("robust_exact")].parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(rows.len(), 6);
    let mut alone = Vec::new();
    for (name, _, _) in &rows {
        let out = dir.join(format!("s_{name}"));
        let o = bin()
            .args(design)
            .arg("--scene")
            .arg(dir.join(format!("c/{name}.toml")))
            .args(small)
            .arg("--out-dir")
            .arg(&out)
            .output()
            .unwrap();
        assert_ok(&o);
        assert_eq!(first(&out.join("ranking.csv"), "robust_exact"), "true");
        alone.push(
            first(&out.join("ranking.csv"), "superlubric_to_mN")
                .parse::<f64>()
                .unwrap(),
        );
    }
    // the best three: exact, and the three best limits of the patterns designed alone
    let mut best: Vec<f64> = alone.clone();
    best.sort_by(|a, b| b.total_cmp(a));
    for (k, (name, w, exact)) in rows.iter().take(3).enumerate() {
        assert!(exact, "rank {} ({name}) is not exact: {rows:?}", k + 1);
        assert_eq!(*w, best[k], "rank {}: {rows:?} vs alone {alone:?}", k + 1);
    }
    let third = rows[2].1;
    let mut left_out = 0;
    for ((name, w, exact), a) in rows.iter().zip(&alone) {
        if *exact {
            assert_eq!(w, a, "{name}: {rows:?} vs alone {alone:?}");
        } else {
            // an upper bound at most the third best, and above its own robust limit
            assert!(*w <= third && a <= w, "{name}: {rows:?} vs alone {alone:?}");
            left_out += 1;
        }
    }
    assert!(left_out > 0, "no pattern was left out: {rows:?}");
    let report = std::fs::read_to_string(dir.join("m/report.md")).unwrap();
    assert!(report.contains("was not searched"), "{report}");
    std::fs::remove_dir_all(&dir).ok();
}
