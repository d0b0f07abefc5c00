//! Per-site sphere sizes in the DEM engine (a slider site file whose `diameter_um` column gives
//! two sizes): each pair touches at its own `r_i + r_j`, each slider sphere hangs `R − r_i`
//! below the plate reference, and the settled contacts carry the load; the active set stays
//! exact.

mod common;

use common::{run_kind, tmpdir};
use dem::protocol::RunKind;
use dem::{prepare, SimParams, Start};
use surrogate::scene::SceneFile;
use surrogate::Scene;

/// Seven slider spheres right above seven substrate spheres of the 3 µm triangular substrate:
/// the centre and three of the ring 3 µm across (the body's size, empty cells), the other three
/// 2.99 µm (hanging 5 nm higher and reaching 5 nm less: 10 nm more gap to close).
fn scene(dir: &std::path::Path) -> Scene {
    let h = 1.5 * 3f64.sqrt();
    std::fs::write(
        dir.join("sites.csv"),
        format!(
            "x_um,y_um,diameter_um\n0,0,\n3,0,2.99\n-3,0,\n1.5,{h},\n-1.5,{h},2.99\n\
             1.5,-{h},2.99\n-1.5,-{h},\n"
        ),
    )
    .unwrap();
    let toml = dir.join("sized.toml");
    std::fs::write(
        &toml,
        "pattern = 'square-tri'\n[substrate]\nsize_um = [60, 60]\n[slider]\nsites = 'sites.csv'\n",
    )
    .unwrap();
    SceneFile::read(&toml).unwrap().into_scene().unwrap()
}

/// Equilibrated from a gap in the full model (implicit mount), the reduced model (rigid z) and
/// the explicit full model: every touching pair's overlap is `r_i + r_j − |x_i − x_j|` of its
/// own two spheres (to 10⁻¹⁵ m), contacts of both sizes carry load, the small spheres' overlaps
/// are 10 nm below the large ones' (±1 nm), and the total normal force balances the load
/// (0.5 %); P_max is the surrogate's within 2 %. A contact distance or R_eff of the body's reference size would break the first
/// or the last.
#[test]
fn two_slider_sizes_settle_with_each_pairs_own_contact_distance() {
    let dir = tmpdir("site-sizes");
    let scene = scene(&dir);
    let radii = scene.slider_radii().expect("per-site sizes").to_vec();
    let load = 1.0e-3;
    for (name, rigid_z, implicit_mount) in [
        ("full", false, true),
        ("reduced", true, false),
        ("full-explicit", false, false),
    ] {
        let params = SimParams {
            protocol: dem::ProtocolParams {
                load,
                equilibrate_time: 3e-6,
                slide_time: 0.0,
                sample_interval: 0.1e-6,
                ..Default::default()
            },
            mount: dem::MountParams {
                rigid_z,
                implicit_mount,
                ..Default::default()
            },
            active: dem::ActiveSetParams {
                enabled: false,
                prune_substrate: true,
                ..Default::default()
            },
            ..SimParams::default()
        };
        let prep = prepare(&scene, params, Start::Gap(1e-9), None).unwrap();
        let p_screen = prep.start.p_max;
        let mut sim = prep.sim;
        run_kind(&mut sim, RunKind::Equilibrate);
        let p_max = sim.observe().p_max;
        assert!(
            (p_max / p_screen - 1.0).abs() < 0.02,
            "{name}: DEM P_max {p_max:e} vs the surrogate's {p_screen:e} Pa"
        );
        let snap = sim.snapshot();
        let s = &sim.state;
        let (mut fz, mut big, mut small) = (0.0, Vec::new(), Vec::new());
        for (p, o) in s.act.out.iter().enumerate() {
            if o.delta <= 0.0 {
                continue;
            }
            let k = s.act.pairs[p] as usize;
            let (i, j) = (s.pairs.i[k] as usize, s.pairs.j[k] as usize);
            let (a, b) = (snap.slider[i], snap.substrate[j]);
            let dist =
                ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
            let want = radii[i] + sim.spec.substrate_radius(j) - dist;
            assert!(
                (o.delta - want).abs() < 1e-15,
                "{name}: pair ({i}, {j}) overlap {:e} vs r_i + r_j − d = {want:e}",
                o.delta
            );
            fz += o.force[2];
            if radii[i] < 1.5e-6 {
                small.push(o.delta)
            } else {
                big.push(o.delta)
            }
        }
        assert_eq!(
            (big.len(), small.len()),
            (4, 3),
            "{name}: {big:?} {small:?}"
        );
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
        let gap = mean(&big) - mean(&small);
        assert!((gap - 10e-9).abs() < 1e-9, "{name}: overlap gap {gap:e} m");
        assert!(
            (fz / load - 1.0).abs() < 5e-3,
            "{name}: Σ F_z {fz:e} N vs load {load:e} N"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The active set with per-site sizes keeps every sphere of a body whose sizes differ
/// integrated (its common mode and ringing maps take one mass) and lets the other body's spheres
/// leave the set: a short slide (equilibrate, relax, slide at 1 m/s) matches the run without
/// the active set to 10⁻⁹ in every column, in the full and the reduced model.
#[test]
fn the_active_set_matches_every_sphere_integrated_with_per_site_sizes() {
    let dir = tmpdir("site-sizes-active");
    let scene = scene(&dir);
    for rigid_z in [false, true] {
        let go = |active_set: bool| {
            let params = {
                let mut params = common::slide_params(&scene);
                params.protocol.load = 1e-3;
                params.mount.rigid_z = rigid_z;
                params.mount.implicit_mount = !rigid_z;
                params.active.enabled = active_set;
                params
            };
            let mut sim = prepare(&scene, params, Start::Surrogate, None).unwrap().sim;
            let samples = common::run_slide(&mut sim);
            (samples, sim.active_particles(), sim.particles())
        };
        let (on, active, all) = go(true);
        let (off, _, _) = go(false);
        let d = common::max_rel_diff(&on, &off);
        assert!(
            d < 1e-9,
            "rigid_z {rigid_z}: active set on/off differ by {d:e}"
        );
        assert!(
            active < all,
            "rigid_z {rigid_z}: {active} of {all} particles active"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
