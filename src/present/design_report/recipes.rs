//! The report's recipe section (`design --vary`): the robust limit against each varied field
//! (one chart per field, `recipe_<k>.png`, the other fields at the best recipe's values), the
//! best recipe per pattern as the DEM decided it (a recipe outside the validated range is named
//! only when the DEM confirmed it, [`crate::study::design::recipe_answer`]), the DEM
//! confirmation of the best recipes at their tolerance-box corners and the recipe table. Built
//! from `patterns.csv`'s rows, the recipes' names ([`crate::study::recipe::parse_name`]) and
//! the answer table.

use super::patterns::PatternRow;
use super::top::TopRow;
use super::words::fmt_g;
use crate::plot::chart::{chart_png, Chart, Colour, Curve, Style};
use crate::runs::output::Outputs;
use crate::study::design::answer::Check;
use crate::study::design::recipe_answer::{self, Naming, RecipeDecision};
use crate::study::design::store::Store;
use crate::study::design::DesignOutcome;
use crate::study::recipe::parse_name;
use crate::study::rows::label;
use anyhow::Result;
use serde::Serialize;
use surrogate::units::pa_to_gpa;

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

/// How the named recipe of a pattern stands (the template words it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Standing {
    /// Inside the validated range: the surrogate's answer.
    Surrogate,
    /// Outside it; the DEM confirmed it at its centre and its tolerance-box corners.
    DemConfirmed,
    /// Outside it; the DEM did not run (`--no-dem`): unconfirmed.
    Unconfirmed,
}

/// One recipe in words (cells as printed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecipeWords {
    /// `field = value, …`.
    pub values: String,
    /// Robust limit (mN), `≤ x` for an upper bound.
    pub limit_mn: String,
    /// Slider spheres.
    pub spheres: usize,
    /// Mean pressure at the limit (kPa).
    pub mean_pressure_kpa: String,
    /// Load per sphere at the limit (µN).
    pub load_per_sphere_un: String,
    /// Why it lies outside the validated range (empty: inside).
    pub outside: String,
    /// What the DEM said of it, where it refused it (empty otherwise).
    pub dem_says: String,
}

/// The best recipe of one pattern, as the DEM decided it
/// ([`crate::study::design::recipe_answer`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BestRecipe {
    /// The pattern the recipes were made from.
    pub base: String,
    /// The named recipe (`None`: no recipe of the pattern can be named).
    pub named: Option<RecipeWords>,
    /// How it stands.
    pub standing: Option<Standing>,
    /// Better-ranked recipes outside the validated range that the DEM did not confirm.
    pub refused: Vec<RecipeWords>,
    /// Without the DEM, when the named recipe is unconfirmed: the best recipe inside the
    /// validated range, if any.
    pub inside: Option<RecipeWords>,
}

/// One row of the DEM confirmation of the best recipes (cells as printed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecipeDemLine {
    /// `field = value, …` of the recipe (and its base pattern).
    pub recipe: String,
    /// θ ± tolerance, pull from x ± tolerance, α, the robust limit, the verdict, the DEM at the
    /// design and at its box corners: the answer table's cells ([`super::top::TopRow`]).
    pub theta: String,
    /// See [`RecipeDemLine::theta`].
    pub pull_x: String,
    /// See [`RecipeDemLine::theta`].
    pub limit_mn: String,
    /// See [`RecipeDemLine::theta`].
    pub verdict: String,
    /// See [`RecipeDemLine::theta`].
    pub dem_centre: String,
    /// See [`RecipeDemLine::theta`].
    pub dem_corners: String,
    /// Why it lies outside the validated range (`inside` when it does not).
    pub range: String,
    /// `named`, `named, unconfirmed`, `not named: …` or `–` (not the best of its pattern).
    pub decision: String,
}

/// The recipe section of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecipeSection {
    /// The varied fields (dotted scene-file paths, user units).
    pub fields: Vec<String>,
    /// Per pattern: its best recipe as the DEM decided it.
    pub best: Vec<BestRecipe>,
    /// Every recipe, best first.
    pub table: Vec<RecipeLine>,
    /// The DEM confirmation of the best recipes (the first [`DEM_RECIPES`] with a design, and
    /// every one the DEM refused before a named one); empty without the DEM.
    pub dem: Vec<RecipeDemLine>,
    /// The charts, one per field (`recipe_<k>.png`), with the field each shows.
    pub charts: Vec<(String, String)>,
    /// Whether `coating.p_crit_GPa` is among the fields (its chart is the limit's dependence on
    /// the coating's strength).
    pub p_crit_varied: bool,
    /// The best named recipe (`base: field = value, …`, θ and pull) whose limit the P_crit
    /// lines give; empty without them.
    pub p_crit_recipe: String,
    /// Its robust limit at each coating strength ([`crate::study::design::p_crit`]).
    pub p_crit: Vec<PCritLine>,
}

/// The best recipe's robust limit at one coating strength (cells as printed).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PCritLine {
    /// P_crit (GPa).
    pub p_crit_gpa: String,
    /// The robust limit (mN).
    pub limit_mn: String,
    /// The worst verdict up to it.
    pub verdict: String,
    /// Whether it is the design's own P_crit (its score, not a new search).
    pub own: bool,
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

/// Recipes of the report's DEM table (best first), besides the ones refused before a named one.
pub const DEM_RECIPES: usize = crate::study::design::best::BEST_PATTERNS;

/// `field = value, …` of a recipe's values.
fn values_text(values: &[(String, f64)]) -> String {
    values
        .iter()
        .map(|(f, v)| format!("{f} = {}", crate::study::recipe::value_text(*v)))
        .collect::<Vec<_>>()
        .join(", ")
}

fn limit(r: &PatternRow) -> String {
    if r.robust_exact {
        fmt_g(r.superlubric_to_mN, 3)
    } else {
        format!("≤ {}", fmt_g(r.superlubric_to_mN, 3))
    }
}

/// The reasons in one phrase (`slider E = 50 GPa, in the mount's resonance band`).
fn reasons(v: &[crate::study::recipe::Outside]) -> String {
    v.iter()
        .map(|o| o.to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

/// What the DEM said of a recipe it did not confirm.
fn dem_says(c: &Check) -> String {
    match c {
        Check::Contradicted(why) => format!("the DEM contradicted it: {why}"),
        Check::Unchecked => "the DEM did not check it at its limit and box corners".into(),
        Check::NoDem | Check::Confirmed(_) => String::new(),
    }
}

/// The section, when the design's patterns are recipes: `rows` best first (`patterns.csv`),
/// `top` the answer table's rows in the outcome's pattern order. Cost: one pass over the rows
/// and the recipes.
pub fn section(rows: &[PatternRow], o: &DesignOutcome, top: &[TopRow]) -> Option<RecipeSection> {
    let rec = recipes(rows);
    let first = rec.first()?;
    let fields: Vec<String> = first.values.iter().map(|(f, _)| f.clone()).collect();
    let decisions = recipe_answer::decisions(o);
    let words = |d: &RecipeDecision| recipe_words(o, &rec, d);
    let (best, dem_names) = best_recipes(&rec, &decisions, &words);
    let dem = if o.dem_ran {
        dem_lines(&decisions, &dem_names, &best, top, &words)
    } else {
        Vec::new()
    };
    let (p_crit_recipe, p_crit) = p_crit_lines(o);
    Some(RecipeSection {
        p_crit_recipe,
        p_crit,
        p_crit_varied: fields.iter().any(|f| f == "coating.p_crit_GPa"),
        charts: fields
            .iter()
            .enumerate()
            .map(|(k, f)| (format!("recipe_{k}.png"), f.clone()))
            .collect(),
        fields,
        best,
        dem,
        table: table_lines(&rec),
    })
}

/// The words of the recipe of decision `d` (`None` when `rec` lacks its pattern).
fn recipe_words(o: &DesignOutcome, rec: &[Recipe<'_>], d: &RecipeDecision) -> Option<RecipeWords> {
    let name = &o.patterns[d.pattern].scene.name;
    let r = rec.iter().find(|r| &r.row.pattern == name)?;
    Some(RecipeWords {
        values: values_text(&r.values),
        limit_mn: limit(r.row),
        spheres: r.row.spheres,
        mean_pressure_kpa: fmt_g(r.row.mean_pressure_kPa, 3),
        load_per_sphere_un: fmt_g(r.row.load_per_sphere_uN, 3),
        outside: reasons(&d.outside),
        dem_says: if d.naming.nameable() {
            String::new()
        } else {
            dem_says(&d.check)
        },
    })
}

/// The best recipe of each base with the ones the DEM refused and the best inside the range;
/// and the patterns the DEM section lists (those, then the first [`DEM_RECIPES`] decisions).
fn best_recipes(
    rec: &[Recipe<'_>],
    decisions: &[RecipeDecision],
    words: &dyn Fn(&RecipeDecision) -> Option<RecipeWords>,
) -> (Vec<BestRecipe>, Vec<usize>) {
    let mut bases: Vec<&str> = Vec::new();
    for r in rec {
        if !bases.contains(&r.base.as_str()) {
            bases.push(&r.base);
        }
    }
    let mut best = Vec::new();
    let mut dem_names: Vec<usize> = Vec::new();
    for base in bases {
        let (named, refused) = recipe_answer::named(decisions, base);
        let standing = named.map(|d| match d.naming {
            Naming::DemConfirmed => Standing::DemConfirmed,
            Naming::Unconfirmed => Standing::Unconfirmed,
            Naming::Surrogate | Naming::Refused => Standing::Surrogate,
        });
        let inside = (standing == Some(Standing::Unconfirmed))
            .then(|| {
                decisions
                    .iter()
                    .find(|d| d.base == base && d.naming == Naming::Surrogate)
            })
            .flatten();
        dem_names.extend(refused.iter().map(|d| d.pattern));
        dem_names.extend(named.map(|d| d.pattern));
        best.push(BestRecipe {
            base: base.to_string(),
            named: named.and_then(words),
            standing,
            refused: refused.iter().filter_map(|d| words(d)).collect(),
            inside: inside.and_then(words),
        });
    }
    for d in decisions.iter().take(DEM_RECIPES) {
        if !dem_names.contains(&d.pattern) {
            dem_names.push(d.pattern);
        }
    }
    (best, dem_names)
}

/// The DEM section's line of each decision of `dem_names`.
fn dem_lines(
    decisions: &[RecipeDecision],
    dem_names: &[usize],
    best: &[BestRecipe],
    top: &[TopRow],
    words: &dyn Fn(&RecipeDecision) -> Option<RecipeWords>,
) -> Vec<RecipeDemLine> {
    decisions
        .iter()
        .filter(|d| dem_names.contains(&d.pattern))
        .filter_map(|d| {
            let t = top.get(d.pattern)?;
            let named = best.iter().any(|b| {
                b.named.is_some()
                    && recipe_answer::named(decisions, &b.base)
                        .0
                        .is_some_and(|n| n.pattern == d.pattern)
            });
            Some(RecipeDemLine {
                recipe: format!("{}: {}", d.base, words(d)?.values),
                theta: t.theta.clone(),
                pull_x: t.pull_x.clone(),
                limit_mn: t.limit_mn.clone(),
                verdict: t.verdict.clone(),
                dem_centre: t.dem_centre.clone(),
                dem_corners: t.dem_corners.clone(),
                range: if d.outside.is_empty() {
                    "inside".into()
                } else {
                    reasons(&d.outside)
                },
                decision: if named {
                    "named".into()
                } else if !d.naming.nameable() {
                    format!("not named: {}", dem_says(&d.check))
                } else {
                    "–".into()
                },
            })
        })
        .collect()
}

/// The best recipe's robust limit at each P_crit of the sweep, with the recipe in words
/// (empty without the sweep).
fn p_crit_lines(o: &DesignOutcome) -> (String, Vec<PCritLine>) {
    match &o.p_crit {
        Some(sw) => (
            format!(
                "{} at θ = {}°, pull {}° from x",
                parse_name(&sw.pattern).map_or(sw.pattern.clone(), |(b, v)| format!(
                    "{b}: {}",
                    values_text(&v)
                )),
                sw.theta_deg,
                fmt_g(sw.direction_deg, 4)
            ),
            sw.limits
                .iter()
                .map(|l| PCritLine {
                    p_crit_gpa: format!("{}", label(pa_to_gpa(l.p_crit))),
                    limit_mn: format!("{}", l.superlubric_to_mn),
                    verdict: l.verdict.to_string(),
                    own: l.own,
                })
                .collect(),
        ),
        None => (String::new(), Vec::new()),
    }
}

/// The table of every recipe, best first.
fn table_lines(rec: &[Recipe<'_>]) -> Vec<RecipeLine> {
    rec.iter()
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
        .collect()
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

/// The chart files `recipe_<k>.png`, one per varied field; `None` without recipes.
fn section_fields(rows: &[PatternRow]) -> Option<Vec<String>> {
    let rec = recipes(rows);
    let first = rec.first()?;
    Some(
        (0..first.values.len())
            .map(|k| format!("recipe_{k}.png"))
            .collect(),
    )
}

/// Writes `recipe_<k>.png` for every varied field, each redrawn when missing or when
/// `patterns.csv` changed. Cost: one chart per field.
pub fn write_figures(
    store: &Store,
    outs: &mut Outputs,
    wrote: &mut Vec<String>,
    rows: &[PatternRow],
) -> Result<()> {
    let Some(s) = section_fields(rows) else {
        return Ok(());
    };
    let changed = wrote.iter().any(|w| w == "patterns.csv");
    for (k, file) in s.iter().enumerate() {
        if let Some(c) = field_chart(rows, k) {
            super::redraw::redraw(store, outs, wrote, file, changed, |path| {
                chart_png(path, &c)
            });
        }
    }
    Ok(())
}
