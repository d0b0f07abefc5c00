//! `patterns.csv`: one row per designed pattern, its geometry beside its best design, so that
//! patterns can be compared (and plotted against a family's parameter) at a glance.

use super::words::fmt_g;
use crate::study::design::DesignOutcome;
use crate::study::rows::label;
use serde::Serialize;
use surrogate::units::{m2_to_um2, m_to_um, mn_to_n, n_to_un, pa_to_kpa};

/// One pattern of a design (user units; `patterns.csv`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[allow(non_snake_case)]
pub struct PatternRow {
    /// Pattern (design scene name; the `pattern_id` of a `superlube patterns` index).
    pub pattern: String,
    /// Slider lattice vectors (µm), `x y;x y`.
    pub lattice_um: String,
    /// Slider basis sites (µm), `x y;x y` (empty: one site per cell).
    pub basis_um: String,
    /// Slider outline (`disc r=100`, …).
    pub outline: String,
    /// Slider spheres.
    pub spheres: usize,
    /// Slider outline area (µm²).
    pub slider_area_um2: f64,
    /// Rank-1 design of the pattern: θ (degrees), empty when none is superlubric.
    pub theta_deg: Option<f64>,
    /// Its α from the contact line (degrees).
    pub alpha_deg: Option<f64>,
    /// Its robust superlubric limit (mN; 0: none).
    pub superlubric_to_mN: f64,
    /// Its limit at the nominal (θ, α) (mN).
    pub superlubric_to_nominal_mN: f64,
    /// Mean nominal pressure at the robust limit: load / slider area (kPa).
    pub mean_pressure_kPa: f64,
    /// Load per slider sphere at the robust limit (µN).
    pub load_per_sphere_uN: f64,
    /// From a `superlube patterns` index: `lubric`, `directional` or `interlocked`.
    pub contact_type: String,
    /// From the index: commensurate period ratio `p/q` (empty when none).
    pub p_q: String,
    /// From the index: commensurate direction (degrees from the substrate x axis).
    pub commensurate_direction_deg: Option<f64>,
}

fn pairs_um(v: &[[f64; 2]]) -> String {
    v.iter()
        .map(|p| format!("{} {}", label(m_to_um(p[0])), label(m_to_um(p[1]))))
        .collect::<Vec<_>>()
        .join(";")
}

/// The rows of every pattern of `o`, in the design's order. Cost: one slider site list per
/// pattern.
pub fn pattern_rows(o: &DesignOutcome) -> Vec<PatternRow> {
    o.patterns
        .iter()
        .map(|pr| {
            let sc = &pr.scene.scene;
            let area = sc.geometry.outline.area(sc.slider.radius);
            let spheres = sc.slider_sites_local().len();
            let best = pr.ranking.first().filter(|c| c.score.nominal_to_mn > 0.0);
            let w = best.map_or(0.0, |c| c.score.superlubric_to_mn);
            let facts = pr.scene.facts.clone().unwrap_or_default();
            PatternRow {
                pattern: pr.scene.name.clone(),
                lattice_um: pairs_um(&[sc.slider.lattice.a1, sc.slider.lattice.a2]),
                basis_um: pairs_um(&sc.geometry.slider_basis),
                outline: sc.geometry.outline.describe(sc.slider.radius),
                spheres,
                slider_area_um2: label(m2_to_um2(area)),
                theta_deg: best.map(|c| c.theta_deg),
                alpha_deg: best.map(|c| c.alpha_deg),
                superlubric_to_mN: w,
                superlubric_to_nominal_mN: best.map_or(0.0, |c| c.score.nominal_to_mn),
                mean_pressure_kPa: label(pa_to_kpa(mn_to_n(w) / area)),
                load_per_sphere_uN: label(n_to_un(mn_to_n(w) / spheres.max(1) as f64)),
                contact_type: facts.contact_type,
                p_q: facts.p_q,
                commensurate_direction_deg: facts.commensurate_direction_deg,
            }
        })
        .collect()
}

/// One row of the report's "Patterns compared" table (cells as printed).
#[derive(Debug, Clone, Serialize)]
pub struct PatternLine {
    pub pattern: String,
    pub outline: String,
    pub spheres: usize,
    pub slider_area_um2: String,
    pub theta_deg: String,
    pub alpha_deg: String,
    pub superlubric_to_mn: String,
    pub nominal_mn: String,
    pub mean_pressure_kpa: String,
    pub load_per_sphere_un: String,
    pub contact_type: String,
}

impl From<&PatternRow> for PatternLine {
    fn from(r: &PatternRow) -> Self {
        PatternLine {
            pattern: r.pattern.clone(),
            outline: r.outline.clone(),
            spheres: r.spheres,
            slider_area_um2: format!("{:.0}", r.slider_area_um2),
            theta_deg: r.theta_deg.map_or("–".into(), |v| format!("{v}")),
            alpha_deg: r.alpha_deg.map_or("–".into(), |v| format!("{v}")),
            superlubric_to_mn: fmt_g(r.superlubric_to_mN, 3),
            nominal_mn: fmt_g(r.superlubric_to_nominal_mN, 3),
            mean_pressure_kpa: fmt_g(r.mean_pressure_kPa, 3),
            load_per_sphere_un: fmt_g(r.load_per_sphere_uN, 3),
            contact_type: if r.contact_type.is_empty() {
                "–".into()
            } else {
                r.contact_type.clone()
            },
        }
    }
}
