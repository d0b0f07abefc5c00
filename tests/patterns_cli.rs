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
