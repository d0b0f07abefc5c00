//! `superlube export-lammps` against LAMMPS itself (Debian's `lammps`, binary `lmp`; another
//! binary via `SUPERLUBE_LMP`):
//!
//! * the exported deck sets up and evaluates its forces (`-var nsteps 0`) for every mount and for
//!   the study's full scene, starting from the surrogate's contacts and P_max;
//! * a small scene (636 particles: 473 substrate, 81 slider, 81 control, 1 support) runs the
//!   whole protocol in `lmp` and in the Rust DEM (`superlube slide`, same flags, constant μ):
//!   equilibrium contacts equal, P_max within 0.5 %, friction within 5 % (see the test for why);
//!   the same with two sphere sizes and with per-site sizes;
//! * the `springs` mount resists an applied moment with the scene's rotational stiffness
//!   (`Scene::tilt_stiffness_at`), `free` does not, `locked` does not tilt.
//!
//! Without `lmp` these tests print that they are skipped and pass — unless
//! `SUPERLUBE_REQUIRE_LAMMPS=1` (CI sets it in `.ci/run`), which turns the skip into a failure.

mod common;
use common::lammps::*;

#[test]
fn exported_deck_sets_up_for_every_mount_and_the_study_scene() {
    let Some(lmp) = lmp() else { return };
    let base = tmpdir("nsteps0");
    let mut cases: Vec<(String, Vec<&str>)> = ["locked", "free", "springs"]
        .iter()
        .map(|m| {
            let mut a = SMALL.to_vec();
            // the small substrate holds 105 µs of sliding along this path (the path is checked)
            a.extend([
                "--tilt",
                m,
                "--theta",
                "10",
                "--load-mn",
                "0.05",
                "--slide-us",
                "20",
            ]);
            (m.to_string(), a)
        })
        .collect();
    // the study's scene with every default (square-tri, 3505 spheres, springs mount, 1.4 mN)
    cases.push(("study".into(), vec![]));
    for (name, args) in cases {
        let dir = base.join(&name);
        let meta = export(&dir, &args);
        let log = run_deck(&lmp, &dir, &[("nsteps", "0")]);
        let r = result(&log, "equilibrate");
        assert_eq!(r["step"], 0.0, "{name}");
        // The deck's observables at the start = the surrogate's equilibrium it starts from.
        let s = &meta["surrogate"];
        assert_eq!(
            r["contacts"],
            s["contacts"].as_f64().unwrap(),
            "{name}: contacts"
        );
        let (p, ps) = (r["p_max_GPa"], s["p_max_GPa"].as_f64().unwrap());
        assert!(
            (p - ps).abs() < 1e-9 * ps,
            "{name}: P_max {p} vs surrogate {ps}"
        );
        assert!(r["tilt_x_urad"].abs() < 1e-6, "{name}: untilted start");
        let atoms = meta["atoms"].as_f64().unwrap();
        assert!(
            log.contains(&format!("{atoms} atoms")),
            "{name}: atom count"
        );
        if name == "study" {
            assert_eq!(atoms, (12515 + 3 * 3505 + 1) as f64);
        }
    }
    let _ = std::fs::remove_dir_all(&base);
}

/// The Rust and LAMMPS runs of one small scene, started together (two processes).
#[test]
fn lammps_and_the_rust_dem_agree_on_a_small_scene() {
    let Some(lmp) = lmp() else { return };
    let dir = tmpdir("cross");
    // Locked mount (the simplest common ground), θ = 0, pulled perpendicular to the
    // contact lines (α = 90°), W = 0.05 mN, constant μ = 0.5 (contact sliding dominates the
    // friction, not the small slider's corrugation), 0.5 m/s so that 5 µs of sliding cover
    // 2.5 µm: the spring loads up for ≈ 1.3 µs, then the slider slides with stick-slip and the
    // friction window (the last 2/3, as `slide`) holds only sliding. dt = 2e-5 µs (0.3 × the
    // stable step) so that every phase is a whole number of samples. P_crit = 2 GPa (only
    // lammps-check reads it: constant μ) so that the check below has failed contacts to find.
    let mut args = SMALL.to_vec();
    args.extend([
        "--tilt",
        "locked",
        "--theta",
        "0",
        "--alpha",
        "90",
        "--load-mn",
        "0.05",
        "--mu",
        "0.5",
        "--p-crit-gpa",
        "2",
        "--equilibrate-us",
        "1",
        "--relax-us",
        "0.5",
        "--slide-us",
        "5",
        "--speed-m-s",
        "0.5",
        "--dt-us",
        "2e-5",
        "--sample-us",
        "0.05",
    ]);
    let meta = export(&dir, &[args.as_slice(), &["--dump-us", "0.05"]].concat());
    let t0 = std::time::Instant::now();
    let (log, lammps_s) = run_side_by_side(&lmp, &dir, &args);
    eprintln!(
        "LAMMPS run: {lammps_s:.1} s, both runs: {:.1} s",
        t0.elapsed().as_secs_f64()
    );

    // Equilibrium (end of the 1 µs equilibration, the same step in both).
    let rows = csv(&dir.join("rust.csv"));
    let eq = rows
        .iter()
        .find(|r| (r["t_us"] - 1.0).abs() < 1e-9)
        .expect("rust sample at 1 µs");
    let l = result(&log, "equilibrate");
    assert_eq!(l["step"], 50_000.0);
    // Contacts equal: same start, same forces; no pair of this scene is near touching
    // (a borderline pair would be the only excuse for a difference).
    assert_eq!(l["contacts"], eq["contacts"], "equilibrium contacts");
    // P_max within 0.5 %: p0 ∝ √δ, so 0.5 % is 1 % of the largest overlap; the models differ
    // by the bond form of the ties (their lateral stiffness T/L ≈ 0.1 % of k_xy here) and the
    // Tsuji fit of the damping (inverted to 1e-12): far below that.
    let (pl, pr) = (l["p_max_GPa"], eq["p_max_GPa"]);
    assert!(
        (pl - pr).abs() < 0.005 * pr,
        "P_max LAMMPS {pl} vs Rust {pr} GPa"
    );

    let lrows = csv(&dir.join("timeseries.csv"));
    assert_ramp_agrees(&rows, &lrows, 10);

    // Friction: the mean spring force over the last 2/3 of sliding, the same samples in both.
    let rj = json(&dir.join("rust.json"));
    let fr = rj["friction_mN"].as_f64().unwrap();
    let (a, b) = (1.5 + 5.0 / 3.0, 6.5);
    let w: Vec<f64> = lrows
        .iter()
        .filter(|r| r["t_us"] >= a - 1e-9 && r["t_us"] <= b + 1e-9)
        .map(|r| r["spring_force_mN"])
        .collect();
    assert!(w.len() > 60, "{} LAMMPS samples in the window", w.len());
    let fl = w.iter().sum::<f64>() / w.len() as f64;
    let deck_mean = deck_friction(&log);
    eprintln!(
        "equilibrium: contacts {} / {}, P_max {pl} / {pr} GPa; friction LAMMPS {fl} mN (deck {deck_mean}) / Rust {fr} mN",
        l["contacts"], eq["contacts"]
    );
    // 5 %: both integrate the same equations from the same state, but after each slip event the
    // two trajectories separate at round-off level and the stick-slip cycles drift apart; the
    // window mean then differs by the cycles’ phase (measured 0.3 % on this scene) plus the
    // model differences above (< 0.3 %). A sign or factor error in the pulling spring, the
    // friction cap, the damping frame (its drag is 6 % of the friction here) or the tie stiffnesses
    // shows as more than 5 %.
    assert!(
        fr > 0.3 * 0.5 * 0.05,
        "the slider must slide against friction: {fr} mN"
    );
    assert!(
        (fl - fr).abs() < 0.05 * fr,
        "friction LAMMPS {fl} vs Rust {fr} mN"
    );
    assert!(
        (deck_mean - fl).abs() < 1e-6 * fl + 1e-12,
        "deck mean {deck_mean} vs window {fl}"
    );

    // lammps-check on the same run: its own P_max and contacts from the dump agree with the
    // deck's time series at every common step, and it finds the contacts above P_crit = 2 GPa.
    let out = bin()
        .arg("lammps-check")
        .arg(dir.join("contacts.dump"))
        .arg("--out")
        .arg(dir.join("check.csv"))
        .arg("--failed-out")
        .arg(dir.join("failed.csv"))
        .output()
        .unwrap();
    assert_ok("lammps-check", &out);
    let summary = String::from_utf8_lossy(&out.stderr);
    let frames = csv(&dir.join("check.csv"));
    let dt = meta["dt_us"].as_f64().unwrap();
    let st = &meta["steps"];
    let total = ["equilibrate", "relax", "slide"]
        .iter()
        .map(|k| st[k].as_u64().unwrap())
        .sum::<u64>();
    assert_eq!(
        frames.len() as u64,
        total / st["dump_every"].as_u64().unwrap() + 1,
        "frames"
    );
    let mut matched = 0;
    let mut failed_frames = 0;
    for f in &frames {
        let t = f["step"] * dt;
        if frame_matches(f, t, &lrows) {
            assert_eq!(f["failed_contacts"] > 0.0, f["p_max_GPa"] > 2.0);
            matched += 1;
        }
        failed_frames += (f["failed_contacts"] > 0.0) as usize;
    }
    assert!(matched >= 130, "{matched} frames matched the time series");
    assert!(
        failed_frames > 0,
        "P_crit = 2 GPa must be exceeded somewhere"
    );
    assert!(summary.contains("INVALID"), "{summary}");
    let failed = csv(&dir.join("failed.csv"));
    assert!(failed
        .iter()
        .all(|c| c["p0_GPa"] > 2.0 && c["slider_index"] < 81.0));
    assert_eq!(
        failed.len() as f64,
        frames.iter().map(|f| f["failed_contacts"]).sum::<f64>()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Two sphere sizes through LAMMPS (2 µm slider spheres on the 3 µm substrate; ≈ 6 s of
/// `lmp`): the same protocol as the one-size cross-check, shorter (0.5 µs equilibration, 2.5 µs
/// of sliding at 1 m/s). Equilibrium contacts equal and P_max within 0.5 %, the spring force
/// while it loads up within 0.5 % (measured: 10⁻⁵), friction within 5 % (measured 1.5 %), and
/// `lammps-check` (contact distance R_sl + R_sb, R_eff of the pair from export.json) agrees
/// with the deck's own time series at every common frame.
#[test]
fn lammps_and_the_rust_dem_agree_with_two_sphere_sizes() {
    let Some(lmp) = lmp() else { return };
    let dir = tmpdir("cross-two");
    let scene = two_size_scene(&dir);
    let args = [
        "--scene",
        scene.to_str().unwrap(),
        "--tilt",
        "locked",
        "--theta",
        "0",
        "--alpha",
        "90",
        "--load-mn",
        "0.05",
        "--mu",
        "0.5",
        "--p-crit-gpa",
        "2",
        "--equilibrate-us",
        "0.5",
        "--relax-us",
        "0.2",
        "--slide-us",
        "2.5",
        "--speed-m-s",
        "1",
        "--dt-us",
        "2e-5",
        "--sample-us",
        "0.05",
    ];
    let meta = export(&dir, &[&args[..], &["--dump-us", "0.05"]].concat());
    assert_eq!(meta["slider_sphere_radius_um"].as_f64(), Some(1.0));
    let (log, _) = run_side_by_side(&lmp, &dir, &args);

    let rows = csv(&dir.join("rust.csv"));
    let eq = rows
        .iter()
        .find(|r| (r["t_us"] - 0.5).abs() < 1e-9)
        .expect("rust sample at 0.5 µs");
    let l = result(&log, "equilibrate");
    assert_eq!(l["step"], 25_000.0);
    assert_eq!(l["contacts"], eq["contacts"], "equilibrium contacts");
    let (pl, pr) = (l["p_max_GPa"], eq["p_max_GPa"]);
    assert!(
        (pl - pr).abs() < 0.005 * pr,
        "P_max LAMMPS {pl} vs Rust {pr} GPa"
    );
    let lrows = csv(&dir.join("timeseries.csv"));
    assert_ramp_agrees(&rows, &lrows, 5);
    assert_friction_agrees("two sizes", &dir, &log, (pl, pr));

    assert_check_matches(&dir, &meta, &lrows, 60);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn springs_mount_resists_a_moment_with_the_scene_stiffness() {
    let Some(lmp) = lmp() else { return };
    let base = tmpdir("tilt");
    // The slider at θ = 10°, lifted 1 µm off the substrate and unloaded (no contacts), with a
    // vertical force F on one control site and −F spread evenly over the layer: a pure moment
    // M = r × F about the centre of mass.
    let theta = 10f64.to_radians();
    let mut scene = surrogate::Scene::preset("square-tri").unwrap();
    scene.slider.radius = 15e-6;
    scene.substrate.size = [66e-6, 54e-6];
    let sites = scene.slider_sites_at(theta, [0.0, 0.0]);
    let n = sites.len();
    let c = sites.iter().fold([0.0; 2], |a, s| {
        [a[0] + s[0] / n as f64, a[1] + s[1] / n as f64]
    });
    let k = (0..n)
        .max_by(|&i, &j| {
            let f = |s: &[f64; 2]| s[0] + 0.5 * s[1];
            f(&sites[i]).total_cmp(&f(&sites[j]))
        })
        .unwrap();
    let r = [sites[k][0] - c[0], sites[k][1] - c[1]];
    let force = 1e-6; // N
    let moment = [r[1] * force, -r[0] * force]; // N·m about x and y
    let kt = scene.tilt_stiffness_at(theta); // springs, K1 = 1e6 N/m (the default mount)
    let det = kt[0][0] * kt[1][1] - kt[0][1] * kt[1][0];
    let expected = [
        (kt[1][1] * moment[0] - kt[0][1] * moment[1]) / det * 1e6,
        (kt[0][0] * moment[1] - kt[1][0] * moment[0]) / det * 1e6,
    ]; // µrad
    let mut tilts = Vec::new();
    for mount in ["springs", "free", "locked"] {
        let dir = base.join(mount);
        let mut args = SMALL.to_vec();
        args.extend([
            "--tilt",
            mount,
            "--theta",
            "10",
            "--load-mn",
            "0.05",
            "--equilibrate-us",
            "1.5",
            "--relax-us",
            "0",
            "--slide-us",
            "0",
            "--dt-us",
            "2e-5",
            "--sample-us",
            "0.01",
        ]);
        let meta = export(&dir, &args);
        let ids = &meta["ids"];
        let id = |kind: &str| ids[kind]["first"].as_u64().unwrap() + k as u64;
        let f_nn = force * 1e9;
        std::fs::write(
            dir.join("probe.lmp"),
            format!(
                "unfix load\ngroup lifted union slider ctrl\ndisplace_atoms lifted move 0 0 1.0 units box\n\
                 group probe id {} {}\nfix probe_all ctrl addforce 0.0 0.0 {}\nfix probe_one probe addforce 0.0 0.0 {}\n",
                id("control_axial"),
                id("control_lateral"),
                -f_nn / (2 * n) as f64,
                f_nn / 2.0
            ),
        )
        .unwrap();
        let log = run_deck(&lmp, &dir, &[("extra", "probe.lmp")]);
        assert_eq!(
            result(&log, "equilibrate")["contacts"],
            0.0,
            "{mount}: lifted"
        );
        let rows = csv(&dir.join("timeseries.csv"));
        // mean over 0.5–1.5 µs: the undamped tilt oscillation (period ≪ 1 µs) averages out
        let w: Vec<_> = rows.iter().filter(|r| r["t_us"] > 0.5).collect();
        let mean = |col: &str| w.iter().map(|r| r[col]).sum::<f64>() / w.len() as f64;
        let last = rows.last().unwrap();
        tilts.push((
            mount,
            [mean("tilt_x_urad"), mean("tilt_y_urad")],
            [last["tilt_x_urad"], last["tilt_y_urad"]],
        ));
    }
    let norm = |t: [f64; 2]| t[0].hypot(t[1]);
    let (_, springs, _) = tilts[0];
    eprintln!("springs tilt {springs:?} µrad, expected K_t⁻¹M = {expected:?} µrad");
    for i in 0..2 {
        assert!(
            (springs[i] - expected[i]).abs() < 0.02 * norm(expected),
            "springs tilt {springs:?} vs K_t⁻¹M {expected:?} µrad"
        );
    }
    let (_, _, free_end) = tilts[1];
    assert!(
        norm(free_end) > 1e3 * norm(expected),
        "free mount must keep tilting: {free_end:?}"
    );
    // and in the direction of the moment (tilt ∥ M for a free body with isotropic inertia, roughly)
    assert!(free_end[0] * moment[0] + free_end[1] * moment[1] > 0.0);
    let (_, locked, locked_end) = tilts[2];
    assert!(
        norm(locked) < 1e-6 && norm(locked_end) < 1e-6,
        "locked tilted: {locked:?}"
    );
    let _ = std::fs::remove_dir_all(&base);
}

/// Per-site sizes through LAMMPS (≈ 11 s of `lmp`): a 15 µm square-lattice slider from a site
/// file whose spheres alternate between 3 µm and 2.998 µm (both sizes in contact), the
/// protocol of the two-size cross-check. Equilibrium contacts equal and P_max within 0.5 %
/// (measured: 10⁻⁵), the spring force while it loads up within 0.5 %, friction within 5 %
/// (measured 10⁻⁴), and `lammps-check` (each pair's own radii from export.json) agrees with
/// the deck's own time series at every common frame.
#[test]
fn lammps_and_the_rust_dem_agree_with_per_site_sizes() {
    let Some(lmp) = lmp() else { return };
    let dir = tmpdir("cross-sites");
    let mut csv_text = String::from("x_um,y_um,diameter_um\n");
    for i in -5i32..=5 {
        for j in -5i32..=5 {
            if i * i + j * j <= 25 {
                let d = if (i + j) % 2 != 0 { "2.998" } else { "" };
                csv_text.push_str(&format!("{},{},{d}\n", 3 * i, 3 * j));
            }
        }
    }
    std::fs::write(dir.join("sq.csv"), csv_text).unwrap();
    let scene = dir.join("sq.toml");
    std::fs::write(
        &scene,
        "pattern = 'square-tri'\n[substrate]\nsize_um = [66, 54]\n[slider]\nsites = 'sq.csv'\n",
    )
    .unwrap();
    let args = [
        "--scene",
        scene.to_str().unwrap(),
        "--tilt",
        "locked",
        "--theta",
        "0",
        "--line-deg",
        "0",
        "--alpha",
        "90",
        "--load-mn",
        "0.05",
        "--mu",
        "0.5",
        "--p-crit-gpa",
        "2",
        "--equilibrate-us",
        "0.5",
        "--relax-us",
        "0.2",
        "--slide-us",
        "2.5",
        "--speed-m-s",
        "1",
        "--dt-us",
        "2e-5",
        "--sample-us",
        "0.05",
    ];
    let meta = export(&dir, &[&args[..], &["--dump-us", "0.05"]].concat());
    assert_eq!(meta["slider_radii_um"].as_array().unwrap().len(), 81);
    let (log, _) = run_side_by_side(&lmp, &dir, &args);

    let rows = csv(&dir.join("rust.csv"));
    let eq = rows
        .iter()
        .find(|r| (r["t_us"] - 0.5).abs() < 1e-9)
        .expect("rust sample at 0.5 µs");
    let l = result(&log, "equilibrate");
    assert_eq!(l["contacts"], eq["contacts"], "equilibrium contacts");
    let (pl, pr) = (l["p_max_GPa"], eq["p_max_GPa"]);
    assert!(
        (pl - pr).abs() < 0.005 * pr,
        "P_max LAMMPS {pl} vs Rust {pr} GPa"
    );
    assert!(
        (l["z_um"] - eq["z_um"]).abs() < 1e-6,
        "z {} vs {}",
        l["z_um"],
        eq["z_um"]
    );
    let lrows = csv(&dir.join("timeseries.csv"));
    assert_ramp_agrees(&rows, &lrows, 5);
    assert_friction_agrees("per-site sizes", &dir, &log, (pl, pr));
    assert_check_matches(&dir, &meta, &lrows, 60);
    let _ = std::fs::remove_dir_all(&dir);
}
