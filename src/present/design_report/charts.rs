//! The design's charts: P_max versus θ per load (`pmax_<p>.png`), corrugation versus α of the
//! finalists (`corrugation_<p>.png`), μ versus load with the DEM markers (`mu_<p>.png`). Each
//! function only builds the [`Chart`] data; `crate::plot::design::chart_png` draws it.

use super::rows::{DemProtocol, DemRow};
use crate::plot::design::{Chart, Colour, Curve, Style};
use crate::study::design::trim::CHART_DESIGNS;
use crate::study::design::{DesignParams, PatternResult};
use crate::study::load::{Load, LoadKey};
use surrogate::units::pa_to_gpa;

/// P_max versus θ, one curve per load (viridis), P_crit dashed. Needs the screen rows: drawn
/// before the pattern is trimmed.
pub fn pmax_chart(pr: &PatternResult, p: &DesignParams) -> Chart {
    let n = p.loads.len();
    let curves = p
        .loads
        .iter()
        .enumerate()
        .map(|(k, &w)| {
            let w = Load::from_n(w);
            Curve {
                name: format!("W = {} mN", w.mn()),
                points: pr
                    .screen
                    .iter()
                    .filter(|r| LoadKey::of_mn(r.load_mN) == w.key())
                    .filter_map(|r| r.p_max_GPa.map(|pm| (r.theta_deg, pm)))
                    .collect(),
                colour: Colour::Scale(if n > 1 {
                    k as f64 / (n - 1) as f64
                } else {
                    0.0
                }),
                style: Style::Line,
            }
        })
        .collect();
    Chart {
        title: format!(
            "{}: maximum Hertz pressure versus orientation θ",
            pr.scene.name
        ),
        x_label: "slider rotation θ (°)".into(),
        y_label: "P_max (GPa)".into(),
        curves,
        hlines: vec![(
            pa_to_gpa(pr.scene.scene.coating.p_crit),
            "P_crit (coating fails above)".into(),
        )],
        log_y: false,
    }
}

/// Corrugation versus α of the finalists (the top 5 distinct θ of the ranking). Needs the α
/// scans: drawn before the pattern is trimmed.
pub fn corrugation_chart(pr: &PatternResult) -> Chart {
    let mut thetas: Vec<f64> = Vec::new();
    for c in &pr.ranking {
        if !thetas.contains(&c.theta_deg) {
            thetas.push(c.theta_deg);
        }
        if thetas.len() == 5 {
            break;
        }
    }
    let curves = thetas
        .iter()
        .enumerate()
        .filter_map(|(k, &t)| {
            let e = pr.evaluated.iter().find(|e| e.eval.theta_deg == t)?;
            let mut pts: Vec<(f64, f64)> = e
                .eval
                .scan
                .iter()
                .map(|r| (r.alpha_deg, r.corrugation_nm))
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            Some(Curve {
                name: format!("θ = {t}° (at {} mN)", e.eval.scan_load_mN),
                points: pts,
                colour: Colour::Palette(k),
                style: Style::LinePoints,
            })
        })
        .collect();
    Chart {
        title: format!(
            "{}: corrugation versus pulling angle α (finalists)",
            pr.scene.name
        ),
        x_label: "α from the contact line (°)".into(),
        y_label: "corrugation (nm, log scale)".into(),
        curves,
        hlines: vec![],
        log_y: true,
    }
}

/// μ versus load: the surrogate estimate of the top 5 designs ([`CHART_DESIGNS`]: they keep
/// their friction rows in a trimmed pattern) as lines and the DEM runs as markers, the
/// superlubric limit dashed.
pub fn mu_chart(pr: &PatternResult, dem: &[DemRow], p: &DesignParams) -> Chart {
    let mut curves = Vec::new();
    for (k, c) in pr.ranking.iter().take(CHART_DESIGNS).enumerate() {
        curves.push(Curve {
            name: format!(
                "#{} θ = {}°, α = {}°: μ_est",
                k + 1,
                c.theta_deg,
                c.alpha_deg
            ),
            points: c
                .friction
                .iter()
                .filter_map(|r| r.mu_est.map(|m| (r.load_mN, m)))
                .collect(),
            colour: Colour::Palette(k),
            style: Style::LinePoints,
        });
        let pts: Vec<(f64, f64)> = dem
            .iter()
            .filter(|d| {
                d.pattern == pr.scene.name
                    && d.rank == k + 1
                    && d.protocol == DemProtocol::Design
                    && d.mu_dem.is_some()
            })
            .map(|d| (d.load_mN, d.mu_dem.unwrap_or(f64::NAN)))
            .collect();
        if !pts.is_empty() {
            curves.push(Curve {
                name: format!("#{} DEM", k + 1),
                points: pts,
                colour: Colour::Palette(k),
                style: Style::Markers,
            });
        }
    }
    Chart {
        title: format!("{}: friction coefficient versus load", pr.scene.name),
        x_label: "normal load W (mN)".into(),
        y_label: "μ (log scale)".into(),
        curves,
        hlines: vec![(
            p.mu_superlubric,
            format!("superlubric limit μ = {}", p.mu_superlubric),
        )],
        log_y: true,
    }
}
