//! `superlube lammps-check`: where the constant-μ LAMMPS run left the study's model — the
//! contacts whose Hertz pressure exceeded P_crit, frame by frame, from the deck's contact dump.

use super::dump::{DumpFrame, DumpReader};
use super::meta::ExportMeta;
use crate::DemError;
use serde::Serialize;
use std::collections::HashSet;
use std::io::BufRead;

/// One dump frame's contacts (CSV row of `lammps-check --out`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FrameReport {
    /// LAMMPS timestep.
    pub step: u64,
    /// Time (µs) = step × dt.
    pub t_us: f64,
    /// Protocol phase of the step: equilibrate, relax or slide.
    pub phase: &'static str,
    /// Slider–substrate pairs in contact (δ > 0).
    pub contacts: usize,
    /// Largest Hertz pressure p0 (GPa), 0 without contacts.
    #[serde(rename = "p_max_GPa")]
    pub p_max_gpa: f64,
    /// Contacts with p0 > P_crit (the coating would have failed: μ2, not the exported μ).
    pub failed_contacts: usize,
}

/// One contact above P_crit (CSV row of `lammps-check --failed-out`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FailedContact {
    /// LAMMPS timestep.
    pub step: u64,
    /// Time (µs).
    pub t_us: f64,
    /// Slider sphere index (0-based, `Scene::slider_sites` order).
    pub slider_index: u64,
    /// Substrate sphere index (0-based, `Scene::substrate_spheres` order, after pruning).
    pub substrate_index: u64,
    /// Hertz pressure p0 (GPa).
    #[serde(rename = "p0_GPa")]
    pub p0_gpa: f64,
}

/// Whole-run summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckSummary {
    /// Frames read.
    pub frames: usize,
    /// Time of the first and last frame (µs).
    pub t_us: [f64; 2],
    /// Largest contact number over the frames.
    pub max_contacts: usize,
    /// Mean contact number over the frames.
    pub mean_contacts: f64,
    /// Largest P_max (GPa) and the time (µs) of its first occurrence.
    #[serde(rename = "max_p_max_GPa")]
    pub max_p_max_gpa: f64,
    /// See `max_p_max_gpa`.
    pub max_p_max_t_us: f64,
    /// Frames with at least one contact above P_crit.
    pub frames_failed: usize,
    /// Time (µs) and phase of the first such frame.
    pub first_failed_t_us: Option<f64>,
    /// See `first_failed_t_us`.
    pub first_failed_phase: Option<&'static str>,
    /// Most contacts above P_crit in one frame.
    pub max_failed_contacts: usize,
    /// Distinct slider–substrate pairs that were above P_crit in some frame.
    pub distinct_failed_pairs: usize,
    /// P_crit (GPa), the exported μ and the coating's μ1, μ2.
    #[serde(rename = "p_crit_GPa")]
    pub p_crit_gpa: f64,
    /// See `p_crit_gpa`.
    pub mu: f64,
    /// See `p_crit_gpa`.
    pub mu1: f64,
    /// See `p_crit_gpa`.
    pub mu2: f64,
}

impl CheckSummary {
    /// A few lines for a human: what the run did and whether the constant-μ export is valid.
    pub fn text(&self) -> String {
        let mut s = format!(
            "{} frames, t = {:.4} to {:.4} µs: contacts up to {} (mean {:.1}), P_max up to {:.4} GPa (first at t = {:.4} µs)\n",
            self.frames,
            self.t_us[0],
            self.t_us[1],
            self.max_contacts,
            self.mean_contacts,
            self.max_p_max_gpa,
            self.max_p_max_t_us
        );
        match (self.first_failed_t_us, self.first_failed_phase) {
            (Some(t), Some(ph)) => s += &format!(
                "INVALID where P_crit = {} GPa was exceeded: {} of {} frames (first at t = {:.4} µs, {}), up to {} contacts at once, {} distinct pairs. \
The study's coating would give those contacts μ2 = {}; the export used μ = {} for all.\n",
                self.p_crit_gpa,
                self.frames_failed,
                self.frames,
                t,
                ph,
                self.max_failed_contacts,
                self.distinct_failed_pairs,
                self.mu2,
                self.mu
            ),
            _ => {
                s += &format!(
                    "no contact exceeded P_crit = {} GPa in any frame: ",
                    self.p_crit_gpa
                );
                if self.mu == self.mu1 {
                    s += &format!(
                        "the constant μ = {} (μ1) is the study's coating law throughout these frames (between frames it is not checked).\n",
                        self.mu
                    );
                } else {
                    s += &format!(
                        "the study's coating would give μ1 = {} everywhere, but the export used μ = {}.\n",
                        self.mu1, self.mu
                    );
                }
            }
        }
        s
    }
}

/// Callback of [`check_dump`]: one frame's report and its contacts above P_crit.
pub type FrameSink<'a> = dyn FnMut(&FrameReport, &[FailedContact]) -> Result<(), DemError> + 'a;

/// Reads the dump `input` (named `name` in errors) of an export described by `meta`, calls
/// `on_frame` with each frame's report and its contacts above P_crit (sorted by slider, then
/// substrate index), and returns the summary. p0 = (2E*/π)√(δ/R_eff), δ = R_sl + R_sb −
/// distance (each pair's own radii and R_eff with per-site sizes).
/// Memory: one frame plus the set of distinct failed pairs.
pub fn check_dump<R: BufRead>(
    input: R,
    name: &str,
    meta: &ExportMeta,
    on_frame: &mut FrameSink,
) -> Result<CheckSummary, DemError> {
    if meta.format != super::meta::FORMAT {
        return Err(DemError::invalid(
            "meta",
            &meta.format,
            &format!("not a `{}` export.json", super::meta::FORMAT),
        ));
    }
    let mut s = empty_summary(meta);
    let mut distinct = HashSet::new();
    let mut sum_contacts = 0usize;
    let mut failed = Vec::new();
    for frame in DumpReader::new(input, name) {
        let frame = frame?;
        let mut r = frame_report(&frame, meta, name, &mut failed)?;
        failed.sort_by_key(|f| (f.slider_index, f.substrate_index));
        r.failed_contacts = failed.len();
        sum_contacts += r.contacts;
        tally(&mut s, &r, &failed, &mut distinct);
        on_frame(&r, &failed)?;
    }
    if s.frames == 0 {
        return Err(DemError::invalid(
            "DUMP",
            name,
            "has no frames (did the run write its dump? the deck's dump_every must be > 0)",
        ));
    }
    s.mean_contacts = sum_contacts as f64 / s.frames as f64;
    s.distinct_failed_pairs = distinct.len();
    Ok(s)
}

/// The summary before any frame.
fn empty_summary(meta: &ExportMeta) -> CheckSummary {
    CheckSummary {
        frames: 0,
        t_us: [0.0; 2],
        max_contacts: 0,
        mean_contacts: 0.0,
        max_p_max_gpa: 0.0,
        max_p_max_t_us: 0.0,
        frames_failed: 0,
        first_failed_t_us: None,
        first_failed_phase: None,
        max_failed_contacts: 0,
        distinct_failed_pairs: 0,
        p_crit_gpa: meta.p_crit_gpa,
        mu: meta.mu,
        mu1: meta.mu1,
        mu2: meta.mu2,
    }
}

/// One frame's report (its failed contacts not yet counted) and, in `failed` (cleared first),
/// its contacts above P_crit. Errors on a pair that is no slider–substrate pair of `meta`.
fn frame_report(
    frame: &DumpFrame,
    meta: &ExportMeta,
    name: &str,
    failed: &mut Vec<FailedContact>,
) -> Result<FrameReport, DemError> {
    let two_r = meta.contact_distance_um();
    // per-site sizes: each pair's own contact distance and R_eff
    let sized = meta.slider_radii_um.is_some() || meta.substrate_radii_um.is_some();
    let pref = 2.0 * meta.e_star_gpa / std::f64::consts::PI;
    let ids = &meta.ids;
    let t_us = frame.step as f64 * meta.dt_us;
    let mut r = FrameReport {
        step: frame.step,
        t_us,
        phase: meta.steps.phase(frame.step),
        contacts: 0,
        p_max_gpa: 0.0,
        failed_contacts: 0,
    };
    failed.clear();
    for p in &frame.pairs {
        let (sl, sb) = if ids.slider.contains(p.id1) && ids.substrate.contains(p.id2) {
            (p.id1, p.id2)
        } else if ids.slider.contains(p.id2) && ids.substrate.contains(p.id1) {
            (p.id2, p.id1)
        } else {
            return Err(DemError::invalid(
                "DUMP",
                format!("{name} step {}", frame.step),
                &format!(
                    "pair {}–{} is not a slider–substrate pair of this export (wrong export.json?)",
                    p.id1, p.id2
                ),
            ));
        };
        let (two_r, r_eff) = if sized {
            meta.pair_um(
                (sl - ids.slider.first) as usize,
                (sb - ids.substrate.first) as usize,
            )
        } else {
            (two_r, meta.r_eff_um)
        };
        let delta = two_r - p.dist;
        if delta <= 0.0 {
            continue;
        }
        let p0 = pref * (delta / r_eff).sqrt();
        r.contacts += 1;
        r.p_max_gpa = r.p_max_gpa.max(p0);
        if p0 > meta.p_crit_gpa {
            failed.push(FailedContact {
                step: frame.step,
                t_us,
                slider_index: sl - ids.slider.first,
                substrate_index: sb - ids.substrate.first,
                p0_gpa: p0,
            });
        }
    }
    Ok(r)
}

/// Adds one frame's report `r` and its sorted `failed` contacts to the summary `s` and the set
/// of distinct failed pairs.
fn tally(
    s: &mut CheckSummary,
    r: &FrameReport,
    failed: &[FailedContact],
    distinct: &mut HashSet<(u64, u64)>,
) {
    let t_us = r.t_us;
    if s.frames == 0 {
        s.t_us[0] = t_us;
    }
    s.t_us[1] = t_us;
    s.frames += 1;
    s.max_contacts = s.max_contacts.max(r.contacts);
    if r.p_max_gpa > s.max_p_max_gpa {
        s.max_p_max_gpa = r.p_max_gpa;
        s.max_p_max_t_us = t_us;
    }
    if !failed.is_empty() {
        s.frames_failed += 1;
        if s.first_failed_t_us.is_none() {
            s.first_failed_t_us = Some(t_us);
            s.first_failed_phase = Some(r.phase);
        }
        s.max_failed_contacts = s.max_failed_contacts.max(failed.len());
        for f in failed {
            distinct.insert((f.slider_index, f.substrate_index));
        }
    }
}
