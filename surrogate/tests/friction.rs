//! The surrogate friction estimate (issue 8, point 1, "Checks"): constant μ on a path whose
//! contacts all lie in the sliding plane and whose corrugation is below the stick-slip threshold
//! gives μ exactly; μ_est grows when P_max crosses P_crit; never NaN on the screen's hard cases;
//! the square-on-triangle design point (θ = 0) against its high-corrugation direction.

use surrogate::friction::{estimate_friction, lattice_period, FrictionEstimate, FrictionParams};
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::solver::Solver;
use surrogate::{Coating, Lattice, Material, Mount, Scene, SliderSpec, SubstrateSpec};

const DEG: f64 = std::f64::consts::PI / 180.0;

fn finite(e: &FrictionEstimate) {
    for (name, v) in [
        ("mu_est", e.mu_est),
        ("mu_coating", e.mu_coating),
        ("mu_corrugation", e.mu_corrugation),
        ("mu_quasi_static", e.mu_quasi_static),
        ("mu_est_spread", e.mu_est_spread),
        ("eta", e.eta),
        ("barrier", e.barrier),
        ("max_lateral_force", e.max_lateral_force),
        ("p_max_mean", e.p_max_mean),
        ("p_max_max", e.p_max_max),
        ("failed_fraction", e.failed_fraction),
        ("contacts_mean", e.contacts_mean),
        ("k_spring", e.k_spring),
        ("window", e.window),
    ] {
        assert!(v.is_finite() && v >= 0.0, "{name} = {v}");
    }
    assert!(
        (e.mu_quasi_static - e.mu_coating - e.mu_corrugation).abs() <= 1e-12 * e.mu_quasi_static
    );
    if e.eta <= 1.0 {
        // steady sliding: the quasi-static value, exactly
        assert_eq!(e.mu_est, e.mu_quasi_static);
        assert_eq!(e.mu_est_spread, 0.0);
    }
    assert!(e.failed_fraction <= 1.0);
    assert!(e.samples >= 2 && e.length > 0.0);
}

/// A slider of five spheres (square lattice, spacing 3 µm, radius 3 µm: the centre and its four
/// neighbours) over rails: substrate rows 3 µm apart in y, each a row of spheres 0.5 µm apart in
/// x. Every slider sphere rides on the rail under it (the neighbouring rails are 3 µm = 2R away:
/// never a candidate pair), so every contact normal lies in the vertical x–z plane, and pulled
/// along x every contact rubs with exactly its vertical force: `F_n·√(1 − (e·n)²) = F_n·n_z =
/// F_z`. The rails do corrugate the path (the spheres dip between rail spheres, period 0.5 µm),
/// but at a load of 5 µN the curvature of that ripple is far below the pulling spring
/// (η < 1): no stick-slip, no corrugation friction. With μ1 = μ2 = μ the estimate must be
/// μ·ΣF_z/W = μ to round-off.
fn rail_scene(mu: f64) -> Scene {
    Scene {
        pattern: "rail".into(),
        slider: SliderSpec {
            lattice: Lattice::square(3e-6),
            radius: 3e-6,
            theta: 0.0,
            offset: [0.0, 0.0],
            mount: Mount::default(),
        },
        substrate: SubstrateSpec {
            lattice: Lattice::rectangular(0.5e-6, 3e-6),
            size: [40e-6, 14e-6],
            sigma_h: 0.0,
            seed: 1,
        },
        sphere_radius: 1.5e-6,
        material: Material::default(),
        body_materials: Default::default(),
        coating: Coating {
            p_crit: 4e9,
            mu1: mu,
            mu2: mu,
        },
        geometry: Default::default(),
    }
}

#[test]
fn constant_mu_in_plane_contacts_below_threshold_gives_mu_exactly() {
    for mu in [0.01, 0.3] {
        let sc = rail_scene(mu);
        let s = Solver::new(&sc).unwrap();
        assert_eq!(s.slider_count(), 5);
        let e = estimate_friction(&s, 0.0, 0.0, 5e-6, &FrictionParams::default()).unwrap();
        finite(&e);
        // one rail period along x, solved every ≤ 0.05 µm
        assert!(e.periodic && (e.length - 0.5e-6).abs() < 1e-15, "{e:?}");
        assert!(e.barrier > 0.0, "the rails corrugate the path");
        assert!(e.eta < 1.0 && e.eta > 0.0, "η = {}", e.eta);
        assert_eq!(e.mu_corrugation, 0.0);
        assert_eq!(e.slips, 0);
        assert!(
            (e.mu_est - mu).abs() <= 1e-12 * mu,
            "μ_est {} vs μ {mu}",
            e.mu_est
        );
    }
    // The same rails at a load where the ripple's curvature beats the spring: stick-slip, and
    // the estimate rises above μ.
    let s = Solver::new(&rail_scene(0.01)).unwrap();
    let e = estimate_friction(&s, 0.0, 0.0, 5e-4, &FrictionParams::default()).unwrap();
    finite(&e);
    assert!(
        e.eta > 1.0 && e.mu_corrugation > 0.0 && e.slips >= 1,
        "{e:?}"
    );
    assert!((e.mu_coating - 0.01).abs() <= 1e-12);
}

/// tri-tri θ = 30°: P_max crosses P_crit = 4 GPa between 1.4 and 2.1 mN; contacts above it rub
/// with μ2 = 0.5, so μ_est and the failed fraction jump.
#[test]
fn mu_grows_when_p_max_crosses_p_crit() {
    let sc = Scene::preset("tri-tri").unwrap();
    let s = Solver::new(&sc).unwrap();
    let theta = 30.0 * DEG;
    let line = contact_line_direction(&sc, theta, &MapParams::default()).angle;
    let p = FrictionParams::default();
    let lo = estimate_friction(&s, theta, line + 90.0 * DEG, 1.4e-3, &p).unwrap();
    let hi = estimate_friction(&s, theta, line + 90.0 * DEG, 2.1e-3, &p).unwrap();
    finite(&lo);
    finite(&hi);
    assert!(lo.p_max_max < 4e9 && hi.p_max_max > 4e9, "{lo:?} {hi:?}");
    assert_eq!(lo.failed_fraction, 0.0);
    assert!(hi.failed_fraction > 0.0);
    assert!((lo.mu_coating - 0.01).abs() < 1e-3, "{}", lo.mu_coating);
    assert!(
        hi.mu_est > 2.0 * lo.mu_est,
        "{} vs {}",
        hi.mu_est,
        lo.mu_est
    );
    // the coating term is μ1 plus (μ2 − μ1) times about the failed share of the load
    let expect = 0.01 + 0.49 * hi.failed_fraction;
    assert!((hi.mu_coating - expect).abs() < 0.2 * expect, "{hi:?}");
}

/// The screen's hard cases: 3505 on-top contacts (tri-tri θ = 0) from 1 nN to 3.86 mN, grazing
/// contacts at 1 nN, σ_h = 0.5 µm (a few contacts, large tilts) — finite numbers everywhere.
#[test]
fn never_nan_on_hard_cases() {
    let p = FrictionParams {
        length: 6e-6,
        transient: 1.5e-6,
        step: 0.1e-6,
        ..FrictionParams::default()
    };
    let s = Solver::new(&Scene::preset("tri-tri").unwrap()).unwrap();
    for (theta, dir, w) in [
        (0.0, 0.0, 1e-9),
        (0.0, 0.0, 3.86e-3),
        (0.0, 90.0 * DEG, 1e-9),
        (30.0 * DEG, 15.0 * DEG, 1e-9),
        (30.0 * DEG, 37.0 * DEG, 3.86e-3),
    ] {
        let e = estimate_friction(&s, theta, dir, w, &p).unwrap();
        finite(&e);
    }
    for pattern in ["tri-tri", "square-tri"] {
        let mut sc = Scene::preset(pattern).unwrap();
        sc.substrate.sigma_h = 0.5e-6;
        let s = Solver::new(&sc).unwrap();
        for w in [1e-9, 1.4e-3] {
            let e = estimate_friction(&s, 0.0, 90.0 * DEG, w, &p).unwrap();
            finite(&e);
            assert!(e.contacts_mean >= 1.0);
        }
    }
}

/// square-tri θ = 0, 1.4 mN. Along the contact lines (α = 0) the square rows are commensurate
/// with the substrate rows: the slider rides over the full ≈ 90 nm corrugation every 1.5 µm,
/// η ≫ 1, stick-slip, μ_PT of order the largest lateral force / W. Across them (α = 90°, the
/// study's design point) the path is nearly flat (≈ 1 nm): its corrugation friction is more than
/// 20× smaller and μ_est stays superlubric (< 0.02) up to 3.86 mN with the coating intact.
#[test]
fn square_tri_design_point_alpha_0_vs_90() {
    let sc = Scene::preset("square-tri").unwrap();
    let s = Solver::new(&sc).unwrap();
    let line = contact_line_direction(&sc, 0.0, &MapParams::default()).angle;
    assert!(line.abs() < 1e-12);
    let p = FrictionParams::default();
    let a0 = estimate_friction(&s, 0.0, line, 1.4e-3, &p).unwrap();
    let a90 = estimate_friction(&s, 0.0, line + 90.0 * DEG, 1.4e-3, &p).unwrap();
    finite(&a0);
    finite(&a90);
    // both are lattice directions: one exact period each (3 µm along x, 3√3 µm along y)
    assert!(a0.periodic && (a0.length - 3e-6).abs() < 1e-12);
    assert!(a90.periodic && (a90.length - 3e-6 * 3f64.sqrt()).abs() < 1e-12);
    assert!(
        a0.eta > 1.0 && a0.mu_corrugation > 0.0 && a0.slips >= 1,
        "{a0:?}"
    );
    assert!(
        a0.mu_corrugation > 0.3 * a0.max_lateral_force / 1.4e-3,
        "{a0:?}"
    );
    assert!(a0.mu_corrugation < a0.max_lateral_force / 1.4e-3);
    assert!(
        a0.mu_corrugation > 20.0 * a90.mu_corrugation,
        "{a0:?} {a90:?}"
    );
    assert!(a0.barrier > 50.0 * a90.barrier);
    for w in [0.35e-3, 1.4e-3, 3.86e-3] {
        let e = estimate_friction(&s, 0.0, line + 90.0 * DEG, w, &p).unwrap();
        assert!(e.mu_est < 0.02 && e.failed_fraction == 0.0, "{e:?}");
        assert!(e.mu_coating >= 0.01 - 1e-12);
    }
    // the DEM measures μ = 0.115 here (docs/validation/friction.md): inertia lets each slip run past
    // the next well, so the estimate falls well below the overdamped (quasi-static) one
    assert!(a0.mu_est > 0.05, "{a0:?}");
    assert!(a0.mu_est < 0.7 * a0.mu_quasi_static, "{a0:?}");
    assert!(
        a0.mu_est_spread > 0.0 && a0.mu_est_spread < 0.3 * a0.mu_est,
        "{a0:?}"
    );
}

#[test]
fn lattice_periods() {
    let tri = Lattice::triangular(3e-6);
    let p = |deg: f64| lattice_period(&tri, [(deg * DEG).cos(), (deg * DEG).sin()], 12e-6, 1e-6);
    assert!((p(0.0).unwrap() - 3e-6).abs() < 1e-15);
    assert!((p(60.0).unwrap() - 3e-6).abs() < 1e-15);
    assert!((p(90.0).unwrap() - 3e-6 * 3f64.sqrt()).abs() < 1e-15);
    assert!((p(30.0).unwrap() - 3e-6 * 3f64.sqrt()).abs() < 1e-15);
    assert!(p(180.0).is_some());
    assert!(p(12.345).is_none());
}

#[test]
fn bad_input_names_the_field() {
    let s = Solver::new(&Scene::preset("square-tri").unwrap()).unwrap();
    let p = FrictionParams::default();
    let err = |r: Result<FrictionEstimate, surrogate::SceneError>| r.unwrap_err().to_string();
    assert!(err(estimate_friction(&s, 0.0, 0.0, 0.0, &p)).contains("load_mN"));
    assert!(err(estimate_friction(&s, f64::NAN, 0.0, 1e-3, &p)).contains("theta_deg"));
    assert!(err(estimate_friction(&s, 0.0, f64::INFINITY, 1e-3, &p)).contains("alpha_deg"));
    for (q, field) in [
        (FrictionParams { step: 0.0, ..p }, "friction.step_um"),
        (FrictionParams { k0: -1.0, ..p }, "friction.k0_N_m"),
        (
            FrictionParams {
                transient: 20e-6,
                ..p
            },
            "friction.transient_um",
        ),
        (
            FrictionParams {
                length: 400e-6,
                ..p
            },
            "friction.length_um",
        ),
    ] {
        let e = err(estimate_friction(&s, 0.0, 12.3 * DEG, 1e-3, &q));
        assert!(e.contains(field), "{e}");
    }
}

/// Same inputs → identical output, whatever the thread count.
#[test]
fn deterministic_across_thread_counts() {
    let s = Solver::new(&Scene::preset("square-tri").unwrap()).unwrap();
    let p = FrictionParams {
        length: 4e-6,
        transient: 1e-6,
        ..FrictionParams::default()
    };
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| estimate_friction(&s, 10.2 * DEG, 20.0 * DEG, 1.4e-3, &p).unwrap())
    };
    assert_eq!(run(1), run(3));
}

/// Several loads of one (θ, direction) share the path's candidate searches and pair lists
/// (`estimate_friction_loads`): every estimate is bit-identical to `estimate_friction` at that
/// load alone (periodic and quasi-periodic paths, a rough substrate whose poses escalate to the
/// tilt model); a bad load errs in its own slot, a path off the substrate for all.
#[test]
fn several_loads_equal_single_loads_bit_for_bit() {
    use surrogate::friction::estimate_friction_loads;
    let p = FrictionParams {
        length: 3e-6,
        transient: 1e-6,
        step: 0.1e-6,
        ..FrictionParams::default()
    };
    let mut rough = Scene::preset("tri-tri").unwrap();
    rough.slider.radius = 20e-6;
    rough.substrate.size = [80e-6, 80e-6];
    rough.substrate.sigma_h = 0.01e-6;
    let mut small = Scene::preset("square-tri").unwrap();
    small.slider.radius = 20e-6;
    small.substrate.size = [80e-6, 80e-6];
    let loads = [0.05e-3, 0.2e-3, 0.6e-3];
    for (sc, theta, dir) in [
        (&small, 0.0, 90.0 * DEG),
        (&small, 10.2 * DEG, 13.0 * DEG),
        (&rough, 30.0 * DEG, 15.0 * DEG),
    ] {
        let s = Solver::new(sc).unwrap();
        let many = estimate_friction_loads(&s, theta, dir, &loads, &p).unwrap();
        assert_eq!(many.len(), loads.len());
        for (w, m) in loads.iter().zip(&many) {
            let one = estimate_friction(&s, theta, dir, *w, &p).unwrap();
            let m = m.as_ref().unwrap();
            assert_eq!(format!("{one:?}"), format!("{m:?}"));
            assert_eq!(one.mu_est.to_bits(), m.mu_est.to_bits());
        }
    }
    let s = Solver::new(&small).unwrap();
    let r = estimate_friction_loads(&s, 0.0, 0.0, &[0.1e-3, -1.0, 0.2e-3], &p).unwrap();
    assert!(r[0].is_ok() && r[2].is_ok());
    assert!(r[1].as_ref().unwrap_err().to_string().contains("load_mN"));
    let far = FrictionParams {
        length: 200e-6,
        max_period: 1e-6,
        ..p
    };
    let e = estimate_friction_loads(&s, 0.0, 0.3, &[0.1e-3], &far).unwrap_err();
    assert!(e.to_string().contains("friction.length_um"), "{e}");
}
