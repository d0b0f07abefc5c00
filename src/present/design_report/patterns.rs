//! `patterns.csv`: one row per designed pattern, its geometry beside its best design, so that
//! patterns can be compared (and plotted against a family's parameter) at a glance.

use super::words::fmt_g;
use crate::plot::chart::{chart_png, Chart, Colour, Curve, Style};
use crate::plot::figures::contact_map_png;
use crate::runs::output::Outputs;
use crate::study::design::best::{best_contacts, best_order, pattern_order};
use crate::study::design::store::Store;
use crate::study::design::DesignOutcome;
use crate::study::rows::label;
use anyhow::Result;
use serde::Serialize;
use surrogate::units::{m2_to_um2, m_to_um, mn_to_n, n_to_un, pa_to_kpa};

/// One pattern of a design (user units; `patterns.csv`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[allow(non_snake_case)]
pub struct PatternRow {
    /// Rank of the pattern (1 = best): by its rank-1 design, in the ranking's order
    /// ([`crate::study::design::best::pattern_order`]).
    pub rank: usize,
    /// Pattern (design scene name; the `pattern_id` of a `superlube patterns` index).
    pub pattern: String,
    /// Slider lattice vectors (µm), `x y;x y`; `sites FILE` for a slider from a site file.
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
    /// Whether `superlubric_to_mN` is exact (false: an upper bound; with many patterns, one
    /// that cannot reach the best patterns' robust limits is not searched over its tolerance
    /// box, `crate::study::design::design`).
    pub robust_exact: bool,
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

/// The rows of every pattern of `o`, best first ([`pattern_order`]: by the robust limit of
/// its rank-1 design, then the ranking's tie-breaks, then the order given). Cost: one slider
/// site list per pattern.
pub fn pattern_rows(o: &DesignOutcome) -> Vec<PatternRow> {
    pattern_order(o)
        .into_iter()
        .enumerate()
        .map(|(k, i)| {
            let pr = &o.patterns[i];
            let sc = &pr.scene.scene;
            let area = sc.geometry.outline.area(sc.slider.radius);
            let spheres = sc.slider_sites_local().len();
            let best = pr.ranking.first().filter(|c| c.score.nominal_to_mn > 0.0);
            let w = best.map_or(0.0, |c| c.score.superlubric_to_mn);
            let facts = pr.scene.facts.clone().unwrap_or_default();
            PatternRow {
                rank: k + 1,
                pattern: pr.scene.name.clone(),
                lattice_um: match &sc.geometry.slider_sites {
                    // the file replaced the base preset's lattice: name it, not that lattice
                    Some(l) => format!("sites {}", l.path),
                    None => pairs_um(&[sc.slider.lattice.a1, sc.slider.lattice.a2]),
                },
                basis_um: pairs_um(&sc.geometry.slider_basis),
                outline: sc.geometry.outline.describe(sc.slider.radius),
                spheres,
                slider_area_um2: label(m2_to_um2(area)),
                theta_deg: best.map(|c| c.theta_deg),
                alpha_deg: best.map(|c| c.alpha_deg),
                superlubric_to_mN: w,
                superlubric_to_nominal_mN: best.map_or(0.0, |c| c.score.nominal_to_mn),
                robust_exact: best.is_none_or(|c| c.score.exact),
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
    pub rank: usize,
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
            rank: r.rank,
            pattern: r.pattern.clone(),
            outline: r.outline.clone(),
            spheres: r.spheres,
            slider_area_um2: format!("{:.0}", r.slider_area_um2),
            theta_deg: r.theta_deg.map_or("–".into(), |v| format!("{v}")),
            alpha_deg: r.alpha_deg.map_or("–".into(), |v| format!("{v}")),
            superlubric_to_mn: format!(
                "{}{}",
                if r.robust_exact { "" } else { "≤ " },
                fmt_g(r.superlubric_to_mN, 3)
            ),
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

/// The fairness rule of the comparison in one sentence: equal slider area or equal sphere
/// count as `superlube patterns --fair` made the candidates (read from the index's
/// sidecar), else what the patterns as given share (area, sphere count, or neither: then the
/// mean pressure and the load per sphere are the columns to compare). Cost: one pass.
pub fn fairness(o: &DesignOutcome, rows: &[PatternRow]) -> String {
    use crate::study::fairness::{Fairness, MadeFair};
    let rules: Vec<Option<MadeFair>> = o
        .patterns
        .iter()
        .map(|pr| pr.scene.facts.as_ref().and_then(|f| f.made_fair))
        .collect();
    // the rule every candidate shares, if one does
    let rule = [
        MadeFair::Recipe(Fairness::Area),
        MadeFair::Recipe(Fairness::Count),
        MadeFair::Patterns(Fairness::Count),
        MadeFair::Patterns(Fairness::Area),
    ]
    .into_iter()
    .find(|m| rules.iter().all(|r| *r == Some(*m)));
    let same = |f: &dyn Fn(&PatternRow) -> f64| {
        rows.windows(2)
            .all(|w| (f(&w[0]) - f(&w[1])).abs() <= 1e-9 * f(&w[0]).abs().max(1.0))
    };
    let equal_area = same(&|r: &PatternRow| r.slider_area_um2);
    let equal_count = same(&|r: &PatternRow| r.spheres as f64);
    match rule {
        Some(MadeFair::Recipe(Fairness::Area)) => format!(
            "Recipes compared at **equal slider area** (`--fair area`: each keeps the base slider's outline; the sphere count follows the recipe: {}); the mean pressure and the load per sphere at each limit are in patterns.csv.",
            range_text(rows.iter().map(|r| r.spheres as f64), "spheres")
        ),
        Some(MadeFair::Recipe(Fairness::Count)) => format!(
            "Recipes compared at **equal sphere count** (`--fair count`: each outline scaled to hold the base slider's sphere count, the closest its lattice allows: {}; slider area {}).",
            range_text(rows.iter().map(|r| r.spheres as f64), "spheres"),
            range_text(rows.iter().map(|r| r.slider_area_um2), "µm²")
        ),
        Some(MadeFair::Patterns(Fairness::Count)) => format!(
            "Compared at **equal sphere count**: the candidates were made with `superlube patterns --fair count` (each outline scaled to hold the base slider's sphere count, the closest its lattice allows: {}).",
            if equal_count {
                "all equal".to_string()
            } else {
                range_text(rows.iter().map(|r| r.spheres as f64), "spheres")
            }
        ),
        Some(MadeFair::Patterns(Fairness::Area)) => format!(
            "Compared at **equal slider area**: the candidates were made with `superlube patterns --fair area` (each keeps the base scene's outline, {} µm²; the sphere count follows the lattice: {}).",
            rows.first().map_or(String::new(), |r| format!("{:.0}", r.slider_area_um2)),
            range_text(rows.iter().map(|r| r.spheres as f64), "spheres")
        ),
        None if equal_area => {
            "Compared as given, at **equal slider area** (the sphere count follows each lattice)."
                .into()
        }
        None if equal_count => "Compared as given, at **equal sphere count**.".into(),
        None => format!(
            "Compared as given: **neither the slider area ({}) nor the sphere count ({}) is equal**, so compare the mean pressure and the load per sphere.",
            range_text(rows.iter().map(|r| r.slider_area_um2), "µm²"),
            range_text(rows.iter().map(|r| r.spheres as f64), "spheres")
        ),
    }
}

/// `a–b unit` of the values, rounded to integers (`a unit` when all equal).
fn range_text(v: impl Iterator<Item = f64>, unit: &str) -> String {
    let (lo, hi) = v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    });
    if lo == hi {
        format!("{lo:.0} {unit}")
    } else {
        format!("{lo:.0}–{hi:.0} {unit}")
    }
}

/// A lattice parameter of the patterns (for the chart's x axis and its series).
struct Param {
    label: &'static str,
    short: &'static str,
    unit: &'static str,
    values: Vec<f64>,
}

impl Param {
    /// The distinct values (rounded to 1e-6), ascending.
    fn distinct(&self) -> Vec<f64> {
        let mut v: Vec<f64> = self.values.iter().map(|&x| round6(x)).collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    }
}

fn round6(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

/// Most series drawn as separate curves; beyond, every pattern is one marker.
const MAX_SERIES: usize = 12;

/// The superlubric limit of each pattern's best design against the family's parameter
/// (`patterns.png`): x is the first slider lattice parameter that varies across the patterns —
/// a = |a1|, b = |a2| (µm) or the angle γ between them (°) — else the sphere count. With one
/// varying parameter, the robust and the nominal limit as two curves; with a second one, one
/// robust curve per value of it (up to 12, else markers). With a slider from a site file
/// among the patterns (no lattice), against the sphere count. Lines join the points only where
/// the patterns are one family (every one a candidate of `superlube patterns`: `--family`,
/// `--patterns`); patterns given one by one (`--pattern square-tri,tri-tri`, `--scene …`) are
/// points, not a curve. Cost: one pass over the rows.
pub fn limit_chart(o: &DesignOutcome, rows: &[PatternRow]) -> Chart {
    let family = o.patterns.iter().all(|pr| pr.scene.facts.is_some());
    let mut c = if o
        .patterns
        .iter()
        .any(|pr| pr.scene.scene.geometry.slider_sites.is_some())
    {
        chart_over(&[], rows)
    } else {
        // in the rows' order
        let lat: Vec<([f64; 2], [f64; 2])> = pattern_order(o)
            .into_iter()
            .map(|i| {
                let l = &o.patterns[i].scene.scene.slider.lattice;
                (l.a1, l.a2)
            })
            .collect();
        chart_over(&lat, rows)
    };
    if !family {
        points_only(&mut c);
    }
    c
}

/// The chart of patterns that are not one family: every curve as markers (no line suggests a
/// continuous parameter between them), the nominal limits as rings around them.
fn points_only(c: &mut Chart) {
    for k in &mut c.curves {
        k.style = if k.name.starts_with("nominal") {
            Style::Rings
        } else {
            Style::Markers
        };
    }
    c.title
        .push_str(" (separate patterns: points, not a family curve)");
}

/// [`limit_chart`] over the slider lattice vectors (a1, a2; m) of each row (none: against the
/// sphere count).
fn chart_over(lat: &[([f64; 2], [f64; 2])], rows: &[PatternRow]) -> Chart {
    let params = lattice_params(lat);
    let varying: Vec<&Param> = params.iter().filter(|p| p.distinct().len() > 1).collect();
    let spheres = Param {
        label: "slider spheres",
        short: "spheres",
        unit: "",
        values: rows.iter().map(|r| r.spheres as f64).collect(),
    };
    let x = varying.first().copied().unwrap_or(&spheres);
    Chart {
        title: "superlubric limit of each pattern's best design".into(),
        x_label: x.label.into(),
        y_label: "superlubric to (mN)".into(),
        curves: limit_curves(rows, x, &varying),
        hlines: vec![],
        log_y: false,
    }
}

/// The lattice parameters of each row: |a1|, |a2| (µm) and the angle γ between them (°).
fn lattice_params(lat: &[([f64; 2], [f64; 2])]) -> [Param; 3] {
    let norm = |v: [f64; 2]| v[0].hypot(v[1]);
    [
        Param {
            label: "slider lattice a = |a1| (µm)",
            short: "a",
            unit: " µm",
            values: lat.iter().map(|l| m_to_um(norm(l.0))).collect(),
        },
        Param {
            label: "slider lattice b = |a2| (µm)",
            short: "b",
            unit: " µm",
            values: lat.iter().map(|l| m_to_um(norm(l.1))).collect(),
        },
        Param {
            label: "angle γ between a1 and a2 (°)",
            short: "γ",
            unit: "°",
            values: lat
                .iter()
                .map(|(a, b)| {
                    (a[0] * b[1] - a[1] * b[0])
                        .atan2(a[0] * b[0] + a[1] * b[1])
                        .abs()
                        .to_degrees()
                })
                .collect(),
        },
    ]
}

fn robust(r: &PatternRow) -> f64 {
    r.superlubric_to_mN
}

fn nominal(r: &PatternRow) -> f64 {
    r.superlubric_to_nominal_mN
}

/// (x, limit) of the rows `keep` admits, sorted by x.
fn points(
    rows: &[PatternRow],
    x: &Param,
    keep: &dyn Fn(usize) -> bool,
    limit: fn(&PatternRow) -> f64,
) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = rows
        .iter()
        .enumerate()
        .filter(|(i, _)| keep(*i))
        .map(|(i, r)| (x.values[i], limit(r)))
        .collect();
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    v
}

/// One curve of `limit` per value of a second varying parameter, if it has few values.
fn series(
    rows: &[PatternRow],
    x: &Param,
    varying: &[&Param],
    limit: fn(&PatternRow) -> f64,
    prefix: &str,
    style: Style,
) -> Option<Vec<Curve>> {
    let s = varying
        .get(1)
        .filter(|s| s.distinct().len() <= MAX_SERIES)?;
    let d = s.distinct();
    let n = d.len();
    Some(
        d.iter()
            .enumerate()
            .map(|(k, &v)| Curve {
                name: format!("{prefix}{} = {}{}", s.short, fmt_g(v, 4), s.unit),
                points: points(rows, x, &|i| round6(s.values[i]) == v, limit),
                colour: Colour::Scale(k as f64 / (n - 1).max(1) as f64),
                style,
            })
            .collect::<Vec<Curve>>(),
    )
}

/// The limit curves against `x`: the robust and nominal limits, one per value of a second
/// varying parameter when there is one, markers where the patterns are separate points.
fn limit_curves(rows: &[PatternRow], x: &Param, varying: &[&Param]) -> Vec<Curve> {
    if rows.iter().any(|r| !r.robust_exact) {
        // with many patterns only the best are searched over their tolerance boxes
        // (`robust_exact`): the others' `superlubric_to_mN` is an upper bound, so the curves
        // show the nominal limit and the searched robust limits as markers
        let mut c = series(rows, x, varying, nominal, "nominal limit, ", Style::Line)
            .unwrap_or_else(|| {
                vec![Curve {
                    name: "nominal limit (θ, α exact)".into(),
                    points: points(rows, x, &|_| true, nominal),
                    colour: Colour::Palette(1),
                    style: if varying.len() == 1 {
                        Style::Line
                    } else {
                        Style::Markers
                    },
                }]
            });
        c.push(Curve {
            name: "robust limit (searched: the best patterns)".into(),
            points: points(rows, x, &|i| rows[i].robust_exact, robust),
            colour: Colour::Palette(0),
            style: Style::Markers,
        });
        c
    } else if varying.len() < 2 {
        vec![
            Curve {
                name: "robust limit (over the tolerance box)".into(),
                points: points(rows, x, &|_| true, robust),
                colour: Colour::Palette(0),
                style: if varying.is_empty() {
                    Style::Markers
                } else {
                    Style::LinePoints
                },
            },
            Curve {
                name: "nominal limit (θ, α exact)".into(),
                points: points(rows, x, &|_| true, nominal),
                colour: Colour::Palette(1),
                style: if varying.is_empty() {
                    Style::Markers
                } else {
                    Style::Line
                },
            },
        ]
    } else {
        series(rows, x, varying, robust, "", Style::LinePoints).unwrap_or_else(|| {
            vec![Curve {
                name: "robust limit, one marker per pattern".into(),
                points: points(rows, x, &|_| true, robust),
                colour: Colour::Palette(0),
                style: Style::Markers,
            }]
        })
    }
}

/// How many of the best patterns get a contact map (`contacts_<p>.png`).
pub const CONTACT_MAPS: usize = crate::study::design::best::BEST_PATTERNS;

/// Writes `patterns.png` ([`limit_chart`]) and the contact maps of the best
/// [`CONTACT_MAPS`] patterns ([`best_order`]) at their design's limit load, each redrawn when
/// missing or when `patterns.csv` changed. Cost: one equilibrium per redrawn map.
pub fn write_figures(
    store: &Store,
    outs: &mut Outputs,
    wrote: &mut Vec<String>,
    o: &DesignOutcome,
    rows: &[PatternRow],
) -> Result<()> {
    let changed = wrote.iter().any(|w| w == "patterns.csv");
    super::redraw::redraw(store, outs, wrote, "patterns.png", changed, |path| {
        chart_png(path, &limit_chart(o, rows))
    });
    for i in best_order(o, CONTACT_MAPS) {
        let rel = format!("contacts_{}.png", o.patterns[i].scene.name);
        // the equilibrium is solved only for a map to redraw
        if changed || !store.path(&rel).exists() {
            if let Some(b) = best_contacts(o, i)? {
                super::redraw::redraw(store, outs, wrote, &rel, true, |path| {
                    contact_map_png(path, &b.scene, mn_to_n(b.load_mn), &b.eq)
                });
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(spheres: usize, w: f64) -> PatternRow {
        PatternRow {
            rank: 0,
            pattern: String::new(),
            lattice_um: String::new(),
            basis_um: String::new(),
            outline: String::new(),
            spheres,
            slider_area_um2: 1.0,
            theta_deg: None,
            alpha_deg: None,
            superlubric_to_mN: w,
            superlubric_to_nominal_mN: 2.0 * w,
            robust_exact: true,
            mean_pressure_kPa: 0.0,
            load_per_sphere_uN: 0.0,
            contact_type: String::new(),
            p_q: String::new(),
            commensurate_direction_deg: None,
        }
    }

    fn rect(a_um: f64, b_um: f64) -> ([f64; 2], [f64; 2]) {
        ([a_um * 1e-6, 0.0], [0.0, b_um * 1e-6])
    }

    #[test]
    fn the_x_axis_is_the_varying_parameter_and_a_second_one_gives_the_series() {
        // a varies alone: robust and nominal limits against a, sorted by a.
        let c = chart_over(
            &[rect(3.5, 3.0), rect(3.0, 3.0)],
            &[row(9, 1.0), row(8, 2.0)],
        );
        assert!(c.x_label.contains("a = |a1|"), "{}", c.x_label);
        assert_eq!(c.curves.len(), 2);
        assert_eq!(c.curves[0].points, vec![(3.0, 2.0), (3.5, 1.0)]);
        assert_eq!(c.curves[1].points, vec![(3.0, 4.0), (3.5, 2.0)]);
        // a and b vary: one robust curve per b.
        let lat = [
            rect(3.0, 3.0),
            rect(3.5, 3.0),
            rect(3.0, 4.0),
            rect(3.5, 4.0),
        ];
        let rows = [row(4, 1.0), row(3, 2.0), row(2, 3.0), row(1, 4.0)];
        let c = chart_over(&lat, &rows);
        assert_eq!(c.curves.len(), 2);
        assert_eq!(c.curves[1].name, "b = 4.000 µm");
        assert_eq!(c.curves[1].points, vec![(3.0, 3.0), (3.5, 4.0)]);
        // only b varies: x is b.
        let c = chart_over(&[rect(3.0, 3.0), rect(3.0, 4.0)], &rows[..2]);
        assert!(c.x_label.contains("b = |a2|"), "{}", c.x_label);
        // nothing varies (same vectors): markers against the sphere count.
        let c = chart_over(&[rect(3.0, 3.0), rect(3.0, 3.0)], &rows[..2]);
        assert_eq!(c.x_label, "slider spheres");
        assert_eq!(c.curves[0].style, Style::Markers);
        assert_eq!(c.curves[0].points, vec![(3.0, 2.0), (4.0, 1.0)]);
    }

    /// Two presets (square and triangular sliders: γ 90° and 60°) are not a family: points,
    /// no line between them.
    #[test]
    fn patterns_of_no_family_are_points() {
        let tri = ([3e-6, 0.0], [1.5e-6, 3e-6 * 0.75f64.sqrt()]);
        let mut c = chart_over(&[rect(3.0, 3.0), tri], &[row(9, 1.0), row(8, 2.0)]);
        assert!(c.x_label.contains("γ"), "{}", c.x_label);
        assert!(c.curves.iter().any(|k| k.style != Style::Markers));
        points_only(&mut c);
        assert!(c
            .curves
            .iter()
            .all(|k| matches!(k.style, Style::Markers | Style::Rings)));
        assert!(c.title.contains("not a family"));
    }
}
