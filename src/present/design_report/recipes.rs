//! The report's recipe section (`design --vary`): the robust limit against each varied field
//! (one chart per field, `recipe_<k>.png`, the other fields at the best recipe's values), the
//! best recipe per pattern and the recipe table. Built from `patterns.csv`'s rows and the
//! recipes' names ([`crate::study::recipe::parse_name`]).

use super::patterns::PatternRow;
use super::words::fmt_g;
use crate::plot::design::{chart_png, Chart, Colour, Curve, Style};
use crate::runs::output::Outputs;
use crate::study::design::store::Store;
use crate::study::recipe::parse_name;
use anyhow::Result;
use serde::Serialize;

/// One recipe of the table (cells as printed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecipeLine {
    /// The pattern the recipe was made from.
    pub base: String,
    /// The varied values, in the order of the fields.
    pub values: Vec<String>,
    /// Robust limit (mN), `≤ x` for an upper bound (not searched over its box).
    pub limit_mn: String,
    /// Slider spheres.
    pub spheres: usize,
    /// Mean pressure at the limit (kPa).
    pub mean_pressure_kpa: String,
    /// Load per sphere at the limit (µN).
    pub load_per_sphere_un: String,
}

/// The recipe section of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecipeSection {
    /// The varied fields (dotted scene-file paths, user units).
    pub fields: Vec<String>,
    /// One sentence per pattern: its best recipe and limit.
    pub best: Vec<String>,
    /// Every recipe, best first.
    pub table: Vec<RecipeLine>,
    /// The charts, one per field (`recipe_<k>.png`), with the field each shows.
    pub charts: Vec<(String, String)>,
    /// Whether `coating.p_crit_GPa` is among the fields (its chart is the limit's dependence on
    /// the coating's strength).
    pub p_crit_varied: bool,
}

/// One recipe row: its `patterns.csv` row, the pattern it was made from and its values.
struct Recipe<'a> {
    row: &'a PatternRow,
    base: String,
    values: Vec<(String, f64)>,
}

/// The recipes among `rows` (best first) with their base and values; empty when none.
fn recipes(rows: &[PatternRow]) -> Vec<Recipe<'_>> {
    rows.iter()
        .filter_map(|row| {
            parse_name(&row.pattern).map(|(base, values)| Recipe { row, base, values })
        })
        .collect()
}

/// The section, when the design's patterns are recipes. Cost: one pass over the rows.
pub fn section(rows: &[PatternRow]) -> Option<RecipeSection> {
    let rec = recipes(rows);
    let first = rec.first()?;
    let fields: Vec<String> = first.values.iter().map(|(f, _)| f.clone()).collect();
    let limit = |r: &PatternRow| {
        if r.robust_exact {
            fmt_g(r.superlubric_to_mN, 3)
        } else {
            format!("≤ {}", fmt_g(r.superlubric_to_mN, 3))
        }
    };
    let mut best = Vec::new();
    for Recipe {
        row: r,
        base,
        values,
    } in &rec
    {
        if best.iter().any(|(b, _): &(String, String)| b == base) {
            continue;
        }
        let v: Vec<String> = values
            .iter()
            .map(|(f, v)| format!("{f} = {}", crate::study::recipe::value_text(*v)))
            .collect();
        best.push((
            base.clone(),
            format!(
                "**{base}**: best recipe {} — robust limit {} mN ({} spheres, {} kPa, {} µN per sphere)",
                v.join(", "),
                limit(r),
                r.spheres,
                fmt_g(r.mean_pressure_kPa, 3),
                fmt_g(r.load_per_sphere_uN, 3)
            ),
        ));
    }
    Some(RecipeSection {
        p_crit_varied: fields.iter().any(|f| f == "coating.p_crit_GPa"),
        charts: fields
            .iter()
            .enumerate()
            .map(|(k, f)| (format!("recipe_{k}.png"), f.clone()))
            .collect(),
        fields,
        best: best.into_iter().map(|(_, s)| s).collect(),
        table: rec
            .iter()
            .map(|c| RecipeLine {
                base: c.base.clone(),
                values: c
                    .values
                    .iter()
                    .map(|(_, v)| crate::study::recipe::value_text(*v))
                    .collect(),
                limit_mn: limit(c.row),
                spheres: c.row.spheres,
                mean_pressure_kpa: fmt_g(c.row.mean_pressure_kPa, 3),
                load_per_sphere_un: fmt_g(c.row.load_per_sphere_uN, 3),
            })
            .collect(),
    })
}

/// The chart of field `k`: the robust limit of the recipes whose other fields take the best
/// recipe's values (of the best recipe's pattern), against field `k`'s value; exact limits as
/// points joined by a line, upper bounds (recipes not searched over their box) as rings.
pub fn field_chart(rows: &[PatternRow], k: usize) -> Option<Chart> {
    let rec = recipes(rows);
    let first = rec.first()?;
    let (base, best) = (&first.base, &first.values);
    let field = best.get(k)?.0.clone();
    let mut exact = Vec::new();
    let mut bound = Vec::new();
    for c in &rec {
        let (r, b, v) = (c.row, &c.base, &c.values);
        let others_best = b == base
            && v.iter()
                .zip(best.iter())
                .enumerate()
                .all(|(j, (a, c))| j == k || a.1 == c.1);
        if others_best {
            let p = (v[k].1, r.superlubric_to_mN);
            if r.robust_exact {
                exact.push(p);
            } else {
                bound.push(p);
            }
        }
    }
    exact.sort_by(|a, b| a.0.total_cmp(&b.0));
    bound.sort_by(|a, b| a.0.total_cmp(&b.0));
    let others: Vec<String> = best
        .iter()
        .enumerate()
        .filter(|(j, _)| *j != k)
        .map(|(_, (f, v))| format!("{f} = {}", crate::study::recipe::value_text(*v)))
        .collect();
    Some(Chart {
        title: if others.is_empty() {
            format!("{base}: robust limit against {field}")
        } else {
            format!(
                "{base}: robust limit against {field} ({})",
                others.join(", ")
            )
        },
        x_label: field,
        y_label: "superlubric to (mN)".into(),
        curves: vec![
            Curve {
                name: "robust limit (exact)".into(),
                points: exact,
                colour: Colour::Palette(0),
                style: Style::LinePoints,
            },
            Curve {
                name: "upper bound (not searched over its box)".into(),
                points: bound,
                colour: Colour::Palette(1),
                style: Style::Rings,
            },
        ],
        hlines: vec![],
        log_y: false,
    })
}

/// Writes `recipe_<k>.png` for every varied field, each redrawn when missing or when
/// `patterns.csv` changed. Cost: one chart per field.
pub fn write_figures(
    store: &Store,
    outs: &mut Outputs,
    wrote: &mut Vec<String>,
    rows: &[PatternRow],
) -> Result<()> {
    let Some(s) = section(rows) else {
        return Ok(());
    };
    let changed = wrote.iter().any(|w| w == "patterns.csv");
    for (k, (file, _)) in s.charts.iter().enumerate() {
        if let Some(c) = field_chart(rows, k) {
            super::redraw(store, outs, wrote, file, changed, |path| {
                chart_png(path, &c)
            });
        }
    }
    Ok(())
}
