//! The DEM section of the report data: one line per run, the study-protocol check.

use super::super::rows::{DemProtocol, DemRow};
use super::super::top::{angle, angle_decimals};
use super::super::words::{fmt_g, opt, protocol_words, which_design};
use super::lines::{DemLine, DemSection, StudyCheck};
use crate::study::design::{DesignOutcome, DesignParams};
use crate::study::load::LoadKey;
use crate::study::rows::label;
use surrogate::units::m_to_um;

fn verdict_word(v: Option<bool>) -> &'static str {
    match v {
        Some(true) => "superlubric",
        Some(false) => "not superlubric",
        None => "no verdict",
    }
}

fn dem_line(d: &DemRow, dec: usize) -> DemLine {
    let verdict = |v: Option<bool>| match v {
        Some(true) => "superlubric",
        Some(false) => "not",
        None => "–",
    };
    DemLine {
        pattern: d.pattern.clone(),
        rank: d.rank,
        theta_deg: angle(d.theta_deg, dec),
        alpha_deg: angle(d.alpha_deg, dec),
        corner: if d.theta_offset_deg == 0.0 && d.direction_offset_deg == 0.0 {
            "–".to_string()
        } else {
            format!("{:+}, {:+}", d.theta_offset_deg, d.direction_offset_deg)
        },
        load_mn: format!("{}", d.load_mN),
        protocol: d.protocol.to_string(),
        mu_est: opt(d.mu_est, 3),
        mu_dem: opt(d.mu_dem, 3),
        ratio: opt(d.ratio_est_dem, 3),
        verdict_est: verdict(d.superlubric_est).into(),
        verdict_dem: verdict(d.superlubric_dem).into(),
        max_p_max_gpa: opt(d.max_p_max_GPa, 3),
        contacts: opt(d.mean_contacts, 3),
        status: if d.error.is_empty() {
            d.status.to_string()
        } else {
            format!("{}: {}", d.status, d.error.replace('|', "/"))
        },
        wall_s: opt(d.wall_s, 3),
    }
}

pub(super) fn dem_section(o: &DesignOutcome, p: &DesignParams, dem: &[DemRow]) -> DemSection {
    let study: Vec<&DemRow> = dem
        .iter()
        .filter(|d| d.protocol == DemProtocol::Study)
        .collect();
    let checks = study
        .iter()
        .map(|s| {
            let short = dem.iter().find(|d| {
                d.protocol == DemProtocol::Design
                    && d.pattern == s.pattern
                    && d.theta_deg == s.theta_deg
                    && d.alpha_deg == s.alpha_deg
                    && LoadKey::of_mn(d.load_mN) == LoadKey::of_mn(s.load_mN)
            });
            let mus = (short.and_then(|d| d.mu_dem), s.mu_dem);
            let (short_verdict, study_verdict) = (
                verdict_word(short.and_then(|d| d.superlubric_dem)),
                verdict_word(s.superlubric_dem),
            );
            StudyCheck {
                what: which_design(o, s),
                pattern: s.pattern.clone(),
                theta_deg: format!("{}", s.theta_deg),
                alpha_deg: format!("{}", s.alpha_deg),
                load_mn: format!("{}", s.load_mN),
                measured: matches!(mus, (Some(_), Some(_))),
                mu_short: mus.0.map_or(String::new(), |a| fmt_g(a, 4)),
                mu_study: mus.1.map_or(String::new(), |b| fmt_g(b, 4)),
                difference_pct: match mus {
                    (Some(a), Some(b)) => format!("{:+.1}", 100.0 * (a / b - 1.0)),
                    _ => String::new(),
                },
                same: short_verdict == study_verdict,
                short_verdict: short_verdict.into(),
                study_verdict: study_verdict.into(),
                error: s.error.clone(),
            }
        })
        .collect();
    DemSection {
        protocol: protocol_words(p),
        study_protocol: p.confirm.dem_is_study_protocol,
        model: model_words(p.confirm.dem.model.request).into(),
        checks,
        unmeasured: study.is_empty() && !p.confirm.dem_is_study_protocol,
        rows: dem.iter().map(|d| dem_line(d, angle_decimals(p))).collect(),
        agree: dem
            .iter()
            .filter(|d| d.verdicts_agree == Some(true))
            .count(),
        judged: dem.iter().filter(|d| d.verdicts_agree.is_some()).count(),
        path_um: format!("{}", label(m_to_um(p.friction.length))),
        slid_um: format!(
            "{}",
            label(m_to_um(p.friction.speed * p.friction.slide_time))
        ),
        resonance_drop: format!("{}", surrogate::friction::RESONANCE_DROP_MAX),
    }
}

/// The DEM model of the confirmation runs in words, with the `--model` value that asks for it.
fn model_words(request: dem::ModelRequest) -> &'static str {
    match request {
        dem::ModelRequest::Reduced => "reduced model `--model reduced` (slider spheres rigid in z; unreachable substrate spheres left out and only the active set integrated, both exact)",
        dem::ModelRequest::Full => "full model `--model full` (slider spheres on their z springs; pruning and the active set, both exact)",
        dem::ModelRequest::FullExplicit => "full model by velocity-Verlet throughout `--model full-explicit` (slider spheres on their z springs; pruning and the active set, both exact)",
        dem::ModelRequest::Auto => "`--model auto` (per run: the full model near coating failure, where stick-slip is expected or beyond the measured stiffness ratio, else rigid-z; the choice is in each run's JSON)",
    }
}
