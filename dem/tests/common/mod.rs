//! Helpers shared by the DEM engine tests: small scenes and run wrappers.
#![allow(dead_code)]

use dem::protocol::{run, RunIo, RunKind, Sample};
use dem::SimParams;
use surrogate::Scene;

/// A small disc of the study's slider over a small substrate.
pub fn small(pattern: &str, radius_um: f64, theta_deg: f64) -> Scene {
    let mut s = Scene::preset(pattern).unwrap();
    s.slider.radius = radius_um * 1e-6;
    s.slider.theta = theta_deg.to_radians();
    s.substrate.size = [60e-6, 60e-6];
    s
}

/// Study's mean load per slider sphere at 1.4 mN (N), times the slider's sphere count.
pub fn load_for(scene: &Scene) -> f64 {
    1.4e-3 / 3505.0 * scene.slider_sites().len() as f64
}

/// Equilibration-only knobs for a small scene (3 µs under load).
pub fn params(scene: &Scene) -> SimParams {
    SimParams {
        protocol: dem::ProtocolParams {
            load: load_for(scene),
            slide_time: 0.0,
            equilibrate_time: 3e-6,
            sample_interval: 0.05e-6,
            ..Default::default()
        },
        active: dem::ActiveSetParams {
            prune_substrate: true,
            ..Default::default()
        },
        ..SimParams::default()
    }
}

/// Short sliding knobs (0.2 + 0.2 + 0.4 µs at 1 m/s).
pub fn slide_params(scene: &Scene) -> SimParams {
    SimParams {
        protocol: dem::ProtocolParams {
            load: load_for(scene),
            equilibrate_time: 0.2e-6,
            relax_time: 0.2e-6,
            slide_time: 0.4e-6,
            support_speed: 1.0,
            sample_interval: 0.02e-6,
            ..Default::default()
        },
        active: dem::ActiveSetParams {
            prune_substrate: true,
            ..Default::default()
        },
        ..SimParams::default()
    }
}

/// Runs `kind` of `sim` to the end and returns its samples.
pub fn run_kind(sim: &mut dem::Sim, kind: RunKind) -> Vec<Sample> {
    let mut samples = Vec::new();
    run(sim, kind, &RunIo::default(), &mut samples, &mut |_| {}).unwrap();
    samples
}

/// Runs the slide protocol of `sim` to the end and returns its samples.
pub fn run_slide(sim: &mut dem::Sim) -> Vec<Sample> {
    run_kind(sim, RunKind::Slide)
}

/// A fresh temporary directory for one test.
pub fn tmpdir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("dem-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Largest relative difference between two time series, column by column (time, support,
/// spring force, z, contacts, P_max, failed), relative to each column's largest magnitude.
pub fn max_rel_diff(a: &[Sample], b: &[Sample]) -> f64 {
    assert_eq!(a.len(), b.len(), "series lengths differ");
    let cols = |s: &Sample| {
        [
            s.t_us,
            s.support_x_um,
            s.spring_force_mn,
            s.z_um,
            s.contacts as f64,
            s.p_max_gpa,
            s.failed_contacts as f64,
        ]
    };
    let mut worst: f64 = 0.0;
    let verbose = std::env::var("DEM_DIFF").is_ok();
    for c in 0..7 {
        let scale = a
            .iter()
            .chain(b)
            .map(|s| cols(s)[c].abs())
            .fold(0.0, f64::max)
            .max(1e-300);
        for (x, y) in a.iter().zip(b) {
            let d = (cols(x)[c] - cols(y)[c]).abs() / scale;
            if verbose && d > 0.0 {
                eprintln!(
                    "column {c} at t = {} µs: {} vs {} ({d:e})",
                    x.t_us,
                    cols(x)[c],
                    cols(y)[c]
                );
            }
            worst = worst.max(d);
        }
    }
    worst
}
