//! The slider mount in the DEM: tilt degrees of freedom of the control layer (free, anti-tilt
//! springs) or none (locked). Energy conservation with tilts, the tilted equilibrium against
//! the surrogate's rigid-tilt answer and a torque balance, and locked = springs on a symmetric
//! scene.

mod common;
use common::*;
use dem::model::{Constant, Friction};
use dem::protocol::RunKind;
use dem::{prepare, Prepared, Start};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::{Mount, Scene};

/// Undamped, frictionless fall onto a rough substrate (σ_h = 10 nm, so the contacts exert a
/// moment and the tilting mounts rock): total energy, tilt springs included, is conserved —
/// also with the active set, whose free spheres ring undamped for ever (common mode, aggregate
/// and individual deviations all accounted).
#[test]
fn undamped_run_conserves_energy_with_each_mount() {
    for (mount, active_set) in [
        (Mount::Locked, false),
        (Mount::Free, false),
        (Mount::Springs { k1: 1e6 }, false),
        (Mount::Locked, true),
        (Mount::Springs { k1: 1e6 }, true),
    ] {
        let mut scene = small("tri-tri", 9.0, 30.0);
        scene.substrate.sigma_h = 0.01e-6;
        scene.slider.offset = [1.0e-6, 0.4e-6];
        scene.slider.mount = mount;
        let p = {
            let mut sp = params(&scene);
            sp.numerics.damping_time = f64::INFINITY;
            sp.contact.gamma_n = 0.0;
            sp.contact.gamma_t = 0.0;
            sp.numerics.dt = None;
            sp.numerics.dt_safety = 0.1;
            sp.active.enabled = active_set;
            sp
        };
        let Prepared {
            mut sim, stable, ..
        } = prepare(
            &scene,
            p,
            Start::Gap(2e-9),
            Some(Friction::Constant(Constant { mu: 0.0 })),
        )
        .unwrap();
        assert!(sim.dt <= 0.1 * stable.dt_crit * (1.0 + 1e-12));
        assert_eq!(sim.tilting(), mount.tilts());
        let e0 = sim.energy();
        let mut scale: f64 = 0.0;
        let mut drift: f64 = 0.0;
        let mut tilt: f64 = 0.0;
        let mut touched = false;
        for k in 0..60_000 {
            sim.step().unwrap();
            touched |= sim.observe().contacts > 0;
            if k % 100 == 0 {
                let e = sim.energy();
                drift = drift.max((e - e0).abs());
                scale = scale
                    .max(sim.params.protocol.load * (sim.spec.control_z - sim.state.cl_x[2]).abs());
                tilt = tilt.max(sim.state.tilt[0].abs().max(sim.state.tilt[1].abs()));
            }
        }
        eprintln!(
            "{} (active set {active_set}): energy drift {drift:e} J, exchanged {scale:e} J, max tilt {tilt:e} rad, {} deactivations, {} ringing",
            mount.name(),
            sim.state.stats.deactivations,
            sim.state.ringing.sl.len() + sim.state.ringing.sub.len()
        );
        assert!(touched, "the slider never touched");
        assert!(
            drift < 1e-3 * scale,
            "{}: drift {drift:e} vs {scale:e}",
            mount.name()
        );
        if mount == Mount::Free {
            assert!(tilt > 1e-5, "free: the layer hardly tilted ({tilt:e} rad)");
        }
        if mount.tilts() {
            assert!(tilt > 0.0, "{}: the layer never tilted", mount.name());
        } else {
            assert_eq!(tilt, 0.0);
        }
    }
}

/// Equilibrates `scene` with the rigid-z reduction (the control layer and slider then form the
/// surrogate's rigid body in z) and returns the engine. The damping time is cut to 0.1 µs (the
/// equilibrium does not depend on it) so the lightly damped tilt modes settle in a few µs.
fn settle(scene: &Scene, time: f64, k_lateral: f64) -> dem::Sim {
    let p = {
        let mut sp = params(scene);
        sp.mount.rigid_z = true;
        sp.numerics.damping_time = 0.1e-6;
        sp.protocol.equilibrate_time = time;
        sp.mount.k_slider_xy = k_lateral;
        sp.mount.k_substrate_xy = k_lateral;
        sp
    };
    let mut sim = prepare(scene, p, Start::Surrogate, None).unwrap().sim;
    run_kind(&mut sim, RunKind::Equilibrate);
    sim
}

/// Σ F_z (y_i, −x_i) of the contact forces on the slider about the control-layer centre (N·m).
fn contact_moment(sim: &dem::Sim) -> [f64; 2] {
    let s = &sim.state;
    let mut m = [0.0; 2];
    for (p, o) in sim.pair_results().iter().enumerate() {
        let k = s.act.pairs[p] as usize;
        let off = sim.site_offset(s.pairs.i[k] as usize);
        m[0] += o.force[2] * off[1];
        m[1] -= o.force[2] * off[0];
    }
    m
}

/// A rough substrate (σ_h = 10 nm) under a small slider at an in-plane offset: the contact
/// forces have a net moment. With a free mount the DEM settles where the moment vanishes, at the
/// surrogate's rigid-tilt answer (tilts to 10⁻³, P_max, contacts) once the lateral springs are
/// stiff enough to make the slider as rigid as the surrogate's (with the study's 10³ N/m
/// lateral compliance the tilts differ by ~2 %: the inclined contact forces shift the spheres
/// by nm). With the study's anti-tilt springs the layer tilts until the
/// springs' moment K_t·t balances the contacts' (torque balance), much less than when free.
#[test]
fn tilted_equilibrium_matches_the_surrogate_and_the_torque_balance() {
    let mut scene = small("tri-tri", 12.0, 30.0);
    scene.substrate.sigma_h = 0.01e-6;
    scene.slider.offset = [1.0e-6, 0.4e-6];
    scene.slider.mount = Mount::Free;
    let load = load_for(&scene);
    let eq = Solver::new(&scene)
        .unwrap()
        .solve(
            Pose {
                theta: scene.slider.theta,
                shift: [0.0, 0.0],
            },
            load,
            Model::RigidTilt,
        )
        .unwrap();
    let free = settle(&scene, 3e-6, 1e7);
    let o = free.observe();
    let m = contact_moment(&free);
    eprintln!(
        "free: DEM tilt {:?}, P_max {:.5} GPa, {} contacts, residual moment {m:?}; surrogate rigid-tilt tilt {:?}, P_max {:.5} GPa, {} contacts",
        o.tilt,
        o.p_max * 1e-9,
        o.contacts,
        eq.tilt,
        eq.p_max * 1e-9,
        eq.contact_count()
    );
    let tmag = eq.tilt[0].hypot(eq.tilt[1]);
    assert!(tmag > 1e-5, "the scene should tilt: {:?}", eq.tilt);
    for k in 0..2 {
        assert!(
            (o.tilt[k] - eq.tilt[k]).abs() < 1e-3 * tmag,
            "tilt {k}: DEM {} vs surrogate {}",
            o.tilt[k],
            eq.tilt[k]
        );
    }
    assert!((o.p_max / eq.p_max - 1.0).abs() < 1e-3);
    assert_eq!(o.contacts, eq.contact_count());
    // springs: the layer tilts until K_t·t balances the contacts' moment
    scene.slider.mount = Mount::Springs { k1: 1e6 };
    let sp = settle(&scene, 3e-6, 1e3);
    let kt = sp.spec.tilt_stiffness.expect("springs tilt");
    let t = sp.state.tilt;
    let m = contact_moment(&sp);
    let spring = [
        kt[0][0] * t[0] + kt[0][1] * t[1],
        kt[1][0] * t[0] + kt[1][1] * t[1],
    ];
    eprintln!("springs: tilt {t:?}, contact moment {m:?} N·m, K_t·t {spring:?} N·m");
    let mag = m[0].hypot(m[1]);
    assert!(mag > 0.0);
    for k in 0..2 {
        assert!(
            (m[k] - spring[k]).abs() < 1e-3 * mag,
            "torque balance {k}: contacts {} vs springs {}",
            m[k],
            spring[k]
        );
    }
    assert!(
        t[0].hypot(t[1]) < 0.5 * tmag,
        "springs must resist the tilt"
    );
}

/// At the default placement a perfect tri-tri slider is symmetric: the contacts have no net
/// moment, so the anti-tilt springs never act and the locked and springs mounts give the same
/// equilibrium to round-off.
#[test]
fn locked_and_springs_agree_on_a_symmetric_scene() {
    let mut scene = small("tri-tri", 12.0, 0.0);
    let go = |scene: &Scene| {
        let p = {
            let mut sp = params(scene);
            sp.protocol.equilibrate_time = 0.5e-6;
            sp
        };
        let mut sim = prepare(scene, p, Start::Gap(5e-9), None).unwrap().sim;
        let s = run_kind(&mut sim, RunKind::Equilibrate);
        (s, sim.observe())
    };
    scene.slider.mount = Mount::Locked;
    let (a, oa) = go(&scene);
    scene.slider.mount = Mount::Springs { k1: 1e6 };
    let (b, ob) = go(&scene);
    let d = max_rel_diff(&a, &b);
    eprintln!(
        "locked vs springs: max rel diff {d:e}, tilt {:?}, contacts {} / {}",
        ob.tilt, oa.contacts, ob.contacts
    );
    assert!(oa.contacts > 0);
    assert!(d < 1e-9, "locked vs springs differ by {d:e}");
    assert!(ob.tilt[0].abs() < 1e-12 && ob.tilt[1].abs() < 1e-12);
}
