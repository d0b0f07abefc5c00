//! Unit tests of the pattern-candidate workflow.

use super::*;

fn params(family: &str) -> PatternParams {
    PatternParams {
        family: parse_family(family, |v, _| {
            Ok(
                match v
                    .split(':')
                    .map(|x| x.parse::<f64>().unwrap())
                    .collect::<Vec<_>>()[..]
                {
                    [a] => vec![a],
                    [a, b, s] => (0..=((b - a) / s + 1e-9) as usize)
                        .map(|k| a + k as f64 * s)
                        .collect(),
                    _ => panic!(),
                },
            )
        })
        .unwrap(),
        family_text: family.into(),
        max_pq: 3,
        max_order: 4.0,
    }
}

#[test]
fn contact_types_of_known_pairs() {
    let s = 3e-6;
    let (sq, tri) = (Lattice::square(s), Lattice::triangular(s));
    assert_eq!(
        classify(&sq, &[], 0.0, &sq, &[], 4.0),
        ContactType::Interlocked
    );
    assert_eq!(
        classify(&tri, &[], 0.0, &tri, &[], 4.0),
        ContactType::Interlocked
    );
    // square on triangle at θ = 0: the rows along x coincide (every second substrate G
    // along x), nothing across: lubric across the rows (90°), as the study's contact lines
    assert_eq!(
        classify(&sq, &[], 0.0, &tri, &[], 4.0),
        ContactType::Directional { lubric_deg: 90.0 }
    );
    // twisted by an irrational-looking angle: lubric
    assert_eq!(
        classify(&tri, &[], 0.3, &tri, &[], 4.0),
        ContactType::Lubric
    );
}

#[test]
fn directional_candidates_have_contact_lines_along_their_row() {
    let scene = Scene::preset("square-tri").unwrap();
    let cands = candidates(&scene, &params("directional")).unwrap();
    assert!(cands.len() >= 3, "{}", cands.len());
    for c in &cands {
        let m = c.commensurate.as_ref().unwrap();
        let mut s = scene.clone();
        s.slider.lattice = c.lattice;
        let cl = contact_line_direction(&s, 0.0, &MapParams::default());
        let diff = (cl.angle.to_degrees() - m.direction_deg).rem_euclid(180.0);
        assert!(!(1e-6..=180.0 - 1e-6).contains(&diff), "{c:?} {cl:?}");
        assert!(cl.spacing.is_finite() && cl.spacing > 0.0);
        // period along the row is p/q substrate row periods (3 µm at 0°, 3√3 µm at 30°)
        let d_u = if m.direction_deg == 0.0 {
            3e-6
        } else {
            3e-6 * 3f64.sqrt()
        };
        let a = c.lattice.a1[0].hypot(c.lattice.a1[1]);
        assert!((a / d_u - m.p as f64 / m.q as f64).abs() < 1e-9, "{c:?}");
        assert!(matches!(c.contact, ContactType::Directional { .. }));
    }
}

/// The same candidates checked on the contacts themselves, not on the moiré estimate that made
/// them: at θ = 0 and 1.4 mN the equilibrium's contact points, Fourier-analysed
/// (S(k) = |Σ exp(i k·r)|² over the contacts, k over every direction and over wavelengths from
/// 1.5 slider lattice periods to 60 µm more), peak at k across the stated direction: the
/// contacts form lines along the commensurate row. (The peak's wavelength, 11–62 µm here, is
/// not the index's first-shell `contact_line_spacing_um`: docs/commands/patterns.md.)
#[test]
fn directional_candidates_make_contact_lines_along_their_row_at_equilibrium() {
    use surrogate::solver::{Model, Pose, Solver};
    let scene = Scene::preset("square-tri").unwrap();
    let cands = candidates(&scene, &params("directional")).unwrap();
    assert!(cands.len() >= 3, "{}", cands.len());
    for c in &cands {
        let m = c.commensurate.as_ref().unwrap();
        let mut s = scene.clone();
        s.slider.lattice = c.lattice;
        let eq = Solver::new(&s)
            .unwrap()
            .solve(
                Pose {
                    theta: 0.0,
                    shift: [0.0, 0.0],
                },
                surrogate::units::mn_to_n(1.4),
                Model::Auto,
            )
            .unwrap();
        let pts: Vec<[f64; 2]> = eq
            .contacts
            .iter()
            .map(|k| [k.point[0], k.point[1]])
            .collect();
        assert!(pts.len() >= 20, "{c:?}: {} contacts", pts.len());
        // the strongest Fourier component of the contact positions longer than the slider's
        // own lattice periods (whose reciprocal vectors every set of sites shares)
        let l_min = 1.5
            * c.lattice.a1[0]
                .hypot(c.lattice.a1[1])
                .max(c.lattice.a2[0].hypot(c.lattice.a2[1]));
        let mut peak = (0.0f64, 0.0f64, 0.0f64); // (S, direction of k in degrees, wavelength m)
        for ia in 0..360 {
            let phi = deg_to_rad(ia as f64 * 0.5);
            for il in 0..=300 {
                let lambda = l_min + um_to_m(0.2 * il as f64);
                let (kx, ky) = (2.0 * PI / lambda * phi.cos(), 2.0 * PI / lambda * phi.sin());
                let (re, im) = pts.iter().fold((0.0, 0.0), |(re, im), p| {
                    let a = kx * p[0] + ky * p[1];
                    (re + a.cos(), im + a.sin())
                });
                let sk = re * re + im * im;
                if sk > peak.0 {
                    peak = (sk, ia as f64 * 0.5, lambda);
                }
            }
        }
        // k across the row: the lines run along it
        let across = (peak.1 - (m.direction_deg + 90.0)).rem_euclid(180.0);
        assert!(
            across.min(180.0 - across) <= 2.0,
            "{c:?}: peak k at {}° (row at {}°)",
            peak.1,
            m.direction_deg
        );
    }
}

/// The pre-screen order: lubric, then directional, then interlocked, then unclassified;
/// index order within a class.
#[test]
fn prescreen_order_puts_lubric_first_and_keeps_index_order_within_a_class() {
    let facts: Vec<(String, CandidateFacts)> = [
        ("p1", "interlocked"),
        ("p2", "directional"),
        ("p3", "lubric"),
        ("p4", "directional"),
        ("p5", ""),
        ("p6", "lubric"),
    ]
    .iter()
    .map(|(id, t)| {
        (
            id.to_string(),
            CandidateFacts {
                contact_type: t.to_string(),
                ..Default::default()
            },
        )
    })
    .collect();
    let files: Vec<std::path::PathBuf> = (1..=6)
        .map(|k| std::path::PathBuf::from(format!("c/p{k}.toml")))
        .collect();
    let got: Vec<String> = prescreen_order(files, &facts)
        .iter()
        .map(|f| f.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(got, ["p3", "p6", "p2", "p4", "p1", "p5"]);
}

#[test]
fn families_parse_and_bad_ones_are_named() {
    let scene = Scene::preset("square-tri").unwrap();
    let r = candidates(&scene, &params("rectangular:a=3,b=2.6:6:0.05")).unwrap();
    // b < 3 µm overlaps the 3 µm spheres: 2.6..2.95 left out
    assert_eq!(r.len(), 61);
    let p = candidates(&scene, &params("presets:s=3")).unwrap();
    assert_eq!(
        p.iter().map(|c| c.kind.as_str()).collect::<Vec<_>>(),
        ["triangular", "square"]
    );
    let e = candidates(&scene, &params("rectangular:a=1,b=2"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("‹family›") && e.contains("overlap"), "{e}");
    let e = parse_family("hexagonal", |_, _| Ok(vec![]))
        .unwrap_err()
        .to_string();
    assert!(e.contains("‹family›"), "{e}");
    let e = parse_family("rectangular:a=3", |_, _| Ok(vec![3.0]))
        .unwrap_err()
        .to_string();
    assert!(e.contains("b=…"), "{e}");
}
