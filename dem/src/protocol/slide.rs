//! Summary of a sliding run: friction force and coefficient, contacts, lock-in.

use super::{lock_in, Sample};
use crate::SimParams;
use serde::Serialize;

/// JSON summary of `superlube slide` (user units in the names).
#[derive(Debug, Clone, Serialize)]
pub struct SlideSummary {
    /// Mean pulling-spring force over the measuring window (mN).
    #[serde(rename = "friction_mN")]
    pub friction_mn: f64,
    /// Standard deviation of the spring force over the window (mN).
    #[serde(rename = "friction_std_mN")]
    pub friction_std_mn: f64,
    /// friction / W (–).
    pub mu: f64,
    /// Mean contact number over the window.
    pub mean_contacts: f64,
    /// Largest p0 over the window (GPa), at any step (each sample's `p_max_peak_GPa`), not only
    /// at the samples; the window's first sample's peak reaches back one sampling interval.
    #[serde(rename = "max_p_max_GPa")]
    pub max_p_max_gpa: f64,
    /// Mean failed contacts over the window.
    pub mean_failed_contacts: f64,
    /// Whether the slider locked in (did not follow the support).
    pub locked_in: bool,
    /// Slider advance / support advance over the window.
    pub advance_ratio: f64,
    /// Spring-force slope / (K0·v) over the window (≈ 1 when locked).
    pub force_slope_ratio: f64,
    /// Measuring window (µs of sliding).
    pub window_us: [f64; 2],
    /// Steps taken.
    pub steps: u64,
    /// Wall time (s).
    pub wall_s: f64,
}

/// Summary over the slide window `[measure_from·T, T]` of sliding time T (samples with
/// `t_us` measured from the run start; sliding starts at `equilibrate + relax`).
pub fn slide_summary(samples: &[Sample], p: &SimParams, steps: u64, wall_s: f64) -> SlideSummary {
    let t0 = (p.protocol.equilibrate_time + p.protocol.relax_time) * 1e6;
    let a = t0 + p.protocol.measure_from * p.protocol.slide_time * 1e6;
    let b = t0 + p.protocol.slide_time * 1e6;
    let w: Vec<Sample> = samples
        .iter()
        .filter(|s| s.t_us >= a - 1e-9 && s.t_us <= b + 1e-9)
        .copied()
        .collect();
    let n = w.len().max(1) as f64;
    let f = w.iter().map(|s| s.spring_force_mn).sum::<f64>() / n;
    let sd = (w
        .iter()
        .map(|s| (s.spring_force_mn - f).powi(2))
        .sum::<f64>()
        / n)
        .sqrt();
    let li = lock_in(
        &w,
        p.protocol.k0,
        p.protocol.support_speed,
        p.protocol.lock_in_ratio,
    );
    let load_mn = p.protocol.load * 1e3;
    SlideSummary {
        friction_mn: f,
        friction_std_mn: sd,
        mu: f / load_mn,
        mean_contacts: w.iter().map(|s| s.contacts as f64).sum::<f64>() / n,
        max_p_max_gpa: w
            .iter()
            .map(|s| s.p_max_gpa.max(s.p_max_peak_gpa))
            .fold(0.0, f64::max),
        mean_failed_contacts: w.iter().map(|s| s.failed_contacts as f64).sum::<f64>() / n,
        locked_in: li.locked_in,
        advance_ratio: li.advance_ratio,
        force_slope_ratio: li.force_slope_ratio,
        window_us: [a - t0, b - t0],
        steps,
        wall_s,
    }
}
