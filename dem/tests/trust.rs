//! A trustworthy engine: checkpoints that refuse what they should (other inputs, edited or
//! corrupt state), a slide path checked before the run, a distinct message for each failure,
//! and snapshot files that a rerun replaces and a resume continues exactly.

mod common;
use common::*;
use dem::model::{Constant, Friction};
use dem::protocol::{run, RunIo, RunKind};
use dem::{prepare, DemError, SimParams, Start};
use surrogate::{Mount, Scene};

fn short(scene: &Scene) -> SimParams {
    {
        let mut params = slide_params(scene);
        params.mount.rigid_z = true;
        params.active.enabled = true;
        params.protocol.equilibrate_time = 0.1e-6;
        params.protocol.relax_time = 0.1e-6;
        params.protocol.slide_time = 0.3e-6;
        params
    }
}

/// Runs `scene` with a checkpoint every `every` steps into `path`; returns the total steps.
fn checkpointed(
    scene: &Scene,
    p: &SimParams,
    friction: Option<Friction>,
    path: &std::path::Path,
) -> u64 {
    let mut sim = prepare(scene, p.clone(), Start::Surrogate, friction)
        .unwrap()
        .sim;
    let (ne, nr, ns, _) = dem::protocol::step_counts(&sim, RunKind::Slide);
    let io = RunIo {
        checkpoint: Some(path.to_path_buf()),
        checkpoint_every: (ne + nr + ns) / 2,
        ..RunIo::default()
    };
    run(&mut sim, RunKind::Slide, &io, &mut Vec::new(), &mut |_| {}).unwrap();
    ne + nr + ns
}

fn load_into(
    scene: &Scene,
    p: &SimParams,
    friction: Option<Friction>,
    path: &std::path::Path,
) -> Result<u64, DemError> {
    let mut sim = prepare(scene, p.clone(), Start::Surrogate, friction)
        .unwrap()
        .sim;
    dem::checkpoint::load(path, &mut sim).map(|_| sim.state.step)
}

/// A checkpoint resumes only into a run with the same inputs: another μ1, P_crit, mount or a
/// constant `--mu` is refused with a message naming what differs.
#[test]
fn checkpoint_refuses_a_run_with_other_inputs() {
    let dir = tmpdir("ckpt-inputs");
    let path = dir.join("run.ckpt");
    let scene = small("square-tri", 9.0, 10.2);
    let p = short(&scene);
    let total = checkpointed(&scene, &p, None, &path);
    // the last checkpoint is at the last multiple of total/2
    let every = total / 2;
    assert_eq!(
        load_into(&scene, &p, None, &path).unwrap(),
        total / every * every
    );
    let mut mu1 = scene.clone();
    mu1.coating.mu1 = 0.02;
    let mut pc = scene.clone();
    pc.coating.p_crit = 3e9;
    let mut mount = scene.clone();
    mount.slider.mount = Mount::Free;
    let cases: [(&Scene, Option<Friction>, &str); 4] = [
        (&mu1, None, "scene.coating.mu1"),
        (&pc, None, "scene.coating.p_crit"),
        (&mount, None, "scene.slider.mount"),
        (
            &scene,
            Some(Friction::Constant(Constant { mu: 0.3 })),
            "friction",
        ),
    ];
    for (s, f, key) in cases {
        let e = load_into(s, &p, f, &path).unwrap_err().to_string();
        eprintln!("{key}: {e}");
        assert!(e.contains(key) && e.contains("differ"), "{key}: {e}");
    }
    let e = load_into(
        &scene,
        &{
            let mut params = p.clone();
            params.active.margin = 10e-9;
            params
        },
        None,
        &path,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("params.active_margin"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Offset in `bytes` of the little-endian f64 `v` (the first occurrence).
fn find_f64(bytes: &[u8], v: f64) -> usize {
    let pat = v.to_le_bytes();
    bytes
        .windows(8)
        .position(|w| w == pat)
        .expect("value present in the checkpoint")
}

/// A checkpoint with one slider sphere moved by 1 µm is refused (checksum); a NaN written
/// with a valid checksum is reported as a corrupt checkpoint, not as a time-step problem; a
/// file of the old format is named as such.
#[test]
fn edited_or_corrupt_checkpoints_are_refused_with_their_own_message() {
    let dir = tmpdir("ckpt-corrupt");
    let path = dir.join("run.ckpt");
    let scene = small("square-tri", 9.0, 10.2);
    let p = short(&scene);
    checkpointed(&scene, &p, None, &path);
    let good = std::fs::read(&path).unwrap();
    let mut sim = prepare(&scene, p.clone(), Start::Surrogate, None)
        .unwrap()
        .sim;
    dem::checkpoint::load(&path, &mut sim).unwrap();
    // a slider sphere's x, as stored (the global array of the last evaluation)
    let x = sim.state.sl_x[3][0];
    let at = find_f64(&good, x);
    let mut moved = good.clone();
    moved[at..at + 8].copy_from_slice(&(x + 1e-6).to_le_bytes());
    std::fs::write(&path, &moved).unwrap();
    let e = load_into(&scene, &p, None, &path).unwrap_err().to_string();
    eprintln!("moved: {e}");
    assert!(e.contains("checksum"), "{e}");
    // NaN with a recomputed checksum
    let mut nan = good.clone();
    nan[at..at + 8].copy_from_slice(&f64::NAN.to_le_bytes());
    let crc = crc32fast::hash(&nan[12..]);
    nan[8..12].copy_from_slice(&crc.to_le_bytes());
    std::fs::write(&path, &nan).unwrap();
    let e = load_into(&scene, &p, None, &path).unwrap_err();
    let m = e.to_string();
    eprintln!("nan: {m}");
    assert!(matches!(e, DemError::Checkpoint { .. }), "{m}");
    assert!(m.contains("corrupt") && m.contains("non-finite"), "{m}");
    assert!(!m.contains("dt") && !m.contains("step"), "{m}");
    // the old format
    let mut old = good.clone();
    old[..8].copy_from_slice(b"SLDEMCK1");
    std::fs::write(&path, &old).unwrap();
    let m = load_into(&scene, &p, None, &path).unwrap_err().to_string();
    assert!(m.contains("older superlube"), "{m}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A slide whose path leaves the substrate is refused before any work, with the flags to change
/// and the longest slide that fits; the study's protocol (α = 90°) fits.
#[test]
fn a_path_off_the_substrate_is_refused_before_the_run() {
    let scene = small("square-tri", 12.0, 0.0);
    let p = {
        let mut params = slide_params(&scene);
        params.protocol.slide_time = 20e-6;
        params.protocol.support_speed = 1.0;
        params
    };
    let e = match prepare(&scene, p, Start::Surrogate, None) {
        Err(e) => e,
        Ok(_) => panic!("the path leaves the 60 µm substrate"),
    };
    let m = e.to_string();
    eprintln!("{m}");
    assert!(matches!(e, DemError::Path(_)));
    for flag in [
        "--slide-us",
        "--speed-m-s",
        "--alpha",
        "--offset-um",
        "--substrate-um",
    ] {
        assert!(m.contains(flag), "{flag} missing: {m}");
    }
    assert!(m.contains("longest slide that fits is 13.500 µs"), "{m}");
    let study = Scene::preset("square-tri").unwrap();
    let p = SimParams {
        protocol: dem::ProtocolParams {
            alpha: 90f64.to_radians(),
            ..Default::default()
        },
        ..SimParams::default()
    };
    dem::check_path(&study, &p).unwrap();
}

/// A slider that leaves the substrate during the run (here: a longer slide than the one the
/// path was checked for) stops with that message, not with a time-step one.
#[test]
fn leaving_the_substrate_is_reported_as_such() {
    let scene = small("square-tri", 12.0, 0.0);
    let p = {
        let mut params = short(&scene);
        params.protocol.slide_time = 1e-6;
        params.protocol.support_speed = 2.0;
        params
    };
    let mut sim = prepare(&scene, p, Start::Surrogate, None).unwrap().sim;
    sim.params.protocol.slide_time = 12e-6;
    let mut samples = Vec::new();
    let e = run(
        &mut sim,
        RunKind::Slide,
        &RunIo::default(),
        &mut samples,
        &mut |_| {},
    )
    .unwrap_err();
    let m = e.to_string();
    eprintln!("{m}");
    assert!(matches!(e, DemError::OffSubstrate { .. }), "{m}");
    assert!(m.contains("left the substrate") && m.contains("not a time-step problem"));
    assert!(samples.iter().all(|s| s.z_um.is_finite()));
}

/// `--xyz`: a fresh run replaces the file; a run resumed from a checkpoint continues it exactly
/// (no frame twice, none from the aborted segment after the checkpoint), byte for byte.
#[test]
fn xyz_is_replaced_by_a_fresh_run_and_continued_exactly_on_resume() {
    let dir = tmpdir("xyz");
    let (xyz, ckpt) = (dir.join("run.xyz"), dir.join("run.ckpt"));
    let scene = small("square-tri", 6.0, 10.2);
    let p = short(&scene);
    let fresh = || {
        prepare(&scene, p.clone(), Start::Surrogate, None)
            .unwrap()
            .sim
    };
    let total = {
        let s = fresh();
        let (a, b, c, _) = dem::protocol::step_counts(&s, RunKind::Slide);
        a + b + c
    };
    let io = RunIo {
        checkpoint: Some(ckpt.clone()),
        checkpoint_every: total * 3 / 5,
        xyz: Some(xyz.clone()),
        xyz_every: total / 10,
    };
    std::fs::write(&xyz, "stale content from an older run\n").unwrap();
    let mut a = fresh();
    run(&mut a, RunKind::Slide, &io, &mut Vec::new(), &mut |_| {}).unwrap();
    let whole = std::fs::read(&xyz).unwrap();
    let frames = |b: &[u8]| String::from_utf8_lossy(b).matches("Properties=").count();
    assert!(!String::from_utf8_lossy(&whole).contains("stale"));
    assert_eq!(frames(&whole) as u64, total / (total / 10));
    assert_eq!(a.state.xyz_bytes, whole.len() as u64);
    // the file now also holds the frames written after the checkpoint: resume from it
    let mut b = fresh();
    let mut s = dem::checkpoint::load(&ckpt, &mut b).unwrap();
    run(&mut b, RunKind::Slide, &io, &mut s, &mut |_| {}).unwrap();
    assert_eq!(std::fs::read(&xyz).unwrap(), whole, "resumed xyz differs");
    // a second fresh run replaces the file
    let mut c = fresh();
    run(&mut c, RunKind::Slide, &io, &mut Vec::new(), &mut |_| {}).unwrap();
    assert_eq!(std::fs::read(&xyz).unwrap(), whole, "rerun appended");
    std::fs::remove_dir_all(&dir).ok();
}

/// `auto` takes rigid-z on the superlubric study scene (square-tri 0°, α = 90°: κ = 0.0053,
/// P_max far below P_crit, η = 0.33) and the full model where the slider sticks and slips
/// (α = 0°, along the contact lines: η = 6), where contacts come near coating failure
/// (tri-tri 30° at 2.45 mN) or where κ is large (E = 400 GPa); `full` and `reduced` are
/// honoured; prune and the active set are always on; every reason names κ.
#[test]
fn the_model_choice_follows_stiffness_coating_failure_and_stick_slip() {
    use dem::{choose_model, ModelRequest};
    let p = |w: f64| SimParams {
        protocol: dem::ProtocolParams {
            load: w,
            alpha: 90f64.to_radians(),
            ..Default::default()
        },
        ..SimParams::default()
    };
    let study = Scene::preset("square-tri").unwrap();
    let c = choose_model(&study, &p(1.4e-3), ModelRequest::Auto).unwrap();
    eprintln!("study 1.4 mN, α = 90°: {} — {}", c.model, c.reason);
    assert!(c.rigid_z && c.prune && c.active_set);
    assert!(
        (c.stiffness_ratio - 0.0053).abs() < 1e-4,
        "{}",
        c.stiffness_ratio
    );
    assert!(c.stick_slip_eta.unwrap() < 1.0);
    let along = {
        let mut params = p(1.4e-3);
        params.protocol.alpha = 0.0;
        params
    };
    let c = choose_model(&study, &along, ModelRequest::Auto).unwrap();
    eprintln!("study 1.4 mN, α = 0°: {} — {}", c.model, c.reason);
    assert!(
        !c.rigid_z && c.reason.contains("stick-slip"),
        "{}",
        c.reason
    );
    assert!(c.stick_slip_eta.unwrap() > 1.0);
    // equilibration only: no sliding, no stick-slip question
    let eq = {
        let mut params = along;
        params.protocol.slide_time = 0.0;
        params
    };
    let c = choose_model(&study, &eq, ModelRequest::Auto).unwrap();
    assert!(c.rigid_z && c.stick_slip_eta.is_none(), "{}", c.reason);
    let mut tt = Scene::preset("tri-tri").unwrap();
    tt.slider.theta = 30f64.to_radians();
    let c = choose_model(&tt, &p(2.45e-3), ModelRequest::Auto).unwrap();
    eprintln!("tri-tri 30° 2.45 mN: {} — {}", c.model, c.reason);
    assert!(!c.rigid_z && c.prune && c.active_set);
    assert!(c.reason.contains("P_crit"), "{}", c.reason);
    let mut stiff = study.clone();
    stiff.material.youngs = 400e9;
    stiff.coating.p_crit = 40e9;
    let c = choose_model(&stiff, &p(1.4e-3), ModelRequest::Auto).unwrap();
    eprintln!("E = 400 GPa: {} — {}", c.model, c.reason);
    assert!(!c.rigid_z && c.reason.contains("κ"));
    assert!(
        !choose_model(&study, &p(1.4e-3), ModelRequest::Full)
            .unwrap()
            .rigid_z
    );
    assert!(
        choose_model(&tt, &p(2.45e-3), ModelRequest::Reduced)
            .unwrap()
            .rigid_z
    );
    let mut q = p(1.4e-3);
    choose_model(&tt, &q.clone(), ModelRequest::Auto)
        .unwrap()
        .apply(&mut q);
    assert!(!q.mount.rigid_z && q.active.prune_substrate && q.active.enabled);
}
