//! Work-precision diagrams: per scene a panel of log₁₀ CPU cost against log₁₀ relative error,
//! one line per knob (its settings in refinement order), the default ringed. Each point is one of
//! three [`Mark`]s: **resolved** (its error stands above its noise, the DEM window's standard
//! error: a filled dot with a ± noise whisker), **unresolved** (the error is within its noise: a
//! hollow dot with a whisker up to error + noise and an arrow down, the error could be 0) or
//! **exact** (error 0: the reference itself and speed-only knobs, a cross on a strip marked
//! "exact" below the measured errors, never drawn as if a small error had been measured). The
//! legend names the three. The tiers diagram draws each method (each setting of its one knob) as
//! its own labelled point.

use super::chart::PALETTE;
use super::{perr, png_atomic, FONT};
use crate::study::work_precision::{Knob, Tier, WorkPrecisionRow};
use anyhow::Result;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// How a point of the diagram is drawn: what its error against its noise says.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    /// Error above its noise (or a noiseless, deterministic error): measured.
    Resolved,
    /// Error within its noise: only an upper bound, error + noise, is measured.
    Unresolved,
    /// Error exactly 0 (the reference, a speed-only knob).
    Exact,
}

impl Mark {
    /// The mark of a point with relative error `error` and noise `noise` (both ≥ 0).
    pub fn of(error: f64, noise: f64) -> Mark {
        if error == 0.0 {
            Mark::Exact
        } else if noise > 0.0 && error <= noise {
            Mark::Unresolved
        } else {
            Mark::Resolved
        }
    }
}

/// The y range of a panel (log₁₀ relative error) and the height of its "exact" strip: the
/// measured range spans every nonzero error, error + noise and resolved error − noise of
/// `points` ((error, noise) pairs) with a margin; the strip lies 0.6 below it. Without any
/// nonzero value the measured range is [−3, 0].
pub fn error_range(points: &[(f64, f64)]) -> (f64, f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for &(e, n) in points {
        for v in [e, e + n] {
            if v > 0.0 {
                lo = lo.min(v.log10());
                hi = hi.max(v.log10());
            }
        }
        if Mark::of(e, n) == Mark::Resolved && n > 0.0 {
            lo = lo.min((e - n).log10());
        }
    }
    if !lo.is_finite() {
        (lo, hi) = (-3.0, 0.0);
    }
    let (lo, hi) = (lo - 0.3, hi + 0.5);
    (lo - 0.9, hi, lo - 0.6)
}

/// Draws the diagram of one tier's `rows` into the PNG `path` (one panel per scene; the tiers
/// diagram one series per method, the others one per knob).
pub fn work_precision_png(
    path: &Path,
    title: &str,
    tier: Tier,
    rows: &[WorkPrecisionRow],
) -> Result<()> {
    // the tiers diagram's points run from the upper left (cheap, rough) to the lower right
    let legend = || {
        if tier == Tier::Tiers {
            SeriesLabelPosition::LowerLeft
        } else {
            SeriesLabelPosition::UpperRight
        }
    };
    let mut scenes: Vec<&str> = Vec::new();
    for r in rows {
        if !scenes.contains(&r.scene.as_str()) {
            scenes.push(&r.scene);
        }
    }
    let n = scenes.len().max(1);
    let cols = n.min(3);
    let nrows = n.div_ceil(cols);
    png_atomic(path, (700 * cols as u32, 620 * nrows as u32), |root| {
        let areas = root.split_evenly((nrows, cols));
        for (area, scene) in areas.iter().zip(&scenes) {
            let rs: Vec<&WorkPrecisionRow> = rows.iter().filter(|r| r.scene == *scene).collect();
            panel(
                area,
                &format!("{title}: {scene}"),
                &rs,
                legend(),
                tier == Tier::Tiers,
            )?;
        }
        Ok(())
    })
}

/// One series of a panel: a knob's settings, or on the tiers diagram one method (a setting of
/// its one knob, by the setting's text).
#[derive(Debug, Clone, PartialEq)]
enum Series {
    Knob(Knob),
    Method(String),
}

impl Series {
    /// The legend's label.
    fn label(&self) -> &str {
        match self {
            Series::Knob(k) => k.name(),
            Series::Method(m) => m,
        }
    }

    /// The refinement order of its points (a method is one point: none).
    fn larger_is_finer(&self) -> Option<bool> {
        match self {
            Series::Knob(k) => k.larger_is_finer(),
            Series::Method(_) => None,
        }
    }
}

/// One panel of the diagram in `area`: a line per knob (or a point per method, `by_method`)
/// of `rows`, the exact strip, the legend at `legend`.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    rows: &[&WorkPrecisionRow],
    legend: SeriesLabelPosition,
    by_method: bool,
) -> Result<()> {
    let series_of = |r: &&WorkPrecisionRow| {
        if by_method {
            Series::Method(r.setting.clone())
        } else {
            Series::Knob(r.knob)
        }
    };
    let knobs = distinct(rows.iter().map(series_of));
    let costed: Vec<&&WorkPrecisionRow> = rows.iter().filter(|r| r.cost_cpu_s > 0.0).collect();
    let (x0, x1) = cost_range(&costed);
    let pairs: Vec<(f64, f64)> = costed.iter().map(|r| (r.error_rel, r.noise_rel)).collect();
    let (y0, y1, y_exact) = error_range(&pairs);
    // a point's height: its error, or the strip for an exact one
    let y_of = |e: f64| if e > 0.0 { e.log10() } else { y_exact };
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FONT, 20))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(x0 - 0.15..x1 + 0.15, y0..y1)
        .map_err(perr("work-precision plot"))?;
    chart
        .configure_mesh()
        .x_desc("log₁₀ CPU cost (s)")
        .y_desc("log₁₀ relative error (1)")
        .label_style((FONT, 15))
        .axis_desc_style((FONT, 17))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(perr("work-precision axes"))?;
    // the "exact" strip: below a dashed rule, labelled, no error scale
    let (xl, xr) = (x0 - 0.15, x1 + 0.15);
    exact_strip(&mut chart, xl, xr, y_exact + 0.3)?;
    for (k, knob) in knobs.iter().enumerate() {
        let c = PALETTE[k % PALETTE.len()];
        let mut v: Vec<&&&WorkPrecisionRow> =
            costed.iter().filter(|r| series_of(r) == *knob).collect();
        if let Some(up) = knob.larger_is_finer() {
            v.sort_by(|a, b| {
                let (x, y) = (
                    a.setting_value.unwrap_or(0.0),
                    b.setting_value.unwrap_or(0.0),
                );
                if up {
                    x.total_cmp(&y)
                } else {
                    y.total_cmp(&x)
                }
            });
        }
        // the knob's line joins its measured points; an exact point stands on the strip alone
        let line: Vec<(f64, f64)> = v
            .iter()
            .filter(|r| r.error_rel > 0.0)
            .map(|r| (r.cost_cpu_s.log10(), r.error_rel.log10()))
            .collect();
        chart
            .draw_series(LineSeries::new(line, c.stroke_width(2)))
            .map_err(perr("series"))?
            .label(knob.label())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], c.stroke_width(3)));
        for r in &v {
            let (x, y) = (r.cost_cpu_s.log10(), y_of(r.error_rel));
            draw_mark(&mut chart, r, (x, y), c)?;
            if r.is_default {
                chart
                    .draw_series([Circle::new((x, y), 10, c.stroke_width(2))])
                    .map_err(perr("default"))?;
            }
            chart
                .draw_series([Text::new(
                    r.setting.clone(),
                    (x, y),
                    (FONT, 12).into_font().color(&c),
                )])
                .map_err(perr("labels"))?;
        }
    }
    mark_legend(&mut chart)?;
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FONT, 13))
        .position(legend)
        .draw()
        .map_err(perr("legend"))?;
    Ok(())
}

/// The distinct series of `all`, in order of first appearance.
fn distinct(all: impl Iterator<Item = Series>) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    for k in all {
        if !out.contains(&k) {
            out.push(k);
        }
    }
    out
}

/// The diagram's plotting area: log₁₀ cost against log₁₀ error.
type Plot<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The log₁₀ cost range (s) of the `costed` rows, at least half a decade wide (−3..0 without
/// any).
fn cost_range(costed: &[&&WorkPrecisionRow]) -> (f64, f64) {
    let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
    for r in costed {
        x0 = x0.min(r.cost_cpu_s.log10());
        x1 = x1.max(r.cost_cpu_s.log10());
    }
    if !x0.is_finite() {
        (x0, x1) = (-3.0, 0.0);
    }
    if x1 - x0 < 0.5 {
        (x0, x1) = (x0 - 0.25, x1 + 0.25);
    }
    (x0, x1)
}

/// The "exact" strip from `xl` to `xr`: a dashed rule at height `rule`, labelled.
fn exact_strip<DB: DrawingBackend>(
    chart: &mut Plot<'_, DB>,
    xl: f64,
    xr: f64,
    rule: f64,
) -> Result<()> {
    let dash = (xr - xl) / 80.0;
    chart
        .draw_series((0..80).step_by(2).map(|k| {
            let a = xl + k as f64 * dash;
            PathElement::new(vec![(a, rule), (a + dash, rule)], BLACK.mix(0.5))
        }))
        .map_err(perr("exact rule"))?;
    chart
        .draw_series([Text::new(
            "exact (error 0)",
            (xl + 0.02 * (xr - xl), rule - 0.08),
            (FONT, 13).into_font().color(&BLACK.mix(0.7)),
        )])
        .map_err(perr("exact label"))?;
    Ok(())
}

/// The mark of row `r` at `(x, y)` in colour `c` (see [`Mark`]), with its noise whisker.
fn draw_mark<DB: DrawingBackend>(
    chart: &mut Plot<'_, DB>,
    r: &WorkPrecisionRow,
    (x, y): (f64, f64),
    c: RGBColor,
) -> Result<()> {
    let (e, n) = (r.error_rel, r.noise_rel);
    let cap = |yy: f64| {
        EmptyElement::at((x, yy)) + PathElement::new(vec![(-4, 0), (4, 0)], c.stroke_width(1))
    };
    match Mark::of(e, n) {
        Mark::Resolved => {
            if n > 0.0 {
                let (lo, hi) = ((e - n).log10(), (e + n).log10());
                chart
                    .draw_series([PathElement::new(vec![(x, lo), (x, hi)], c.stroke_width(1))])
                    .map_err(perr("noise whisker"))?;
                chart
                    .draw_series([cap(lo), cap(hi)])
                    .map_err(perr("noise caps"))?;
            }
            chart
                .draw_series([Circle::new((x, y), 4, c.filled())])
                .map_err(perr("markers"))?;
        }
        Mark::Unresolved => {
            let hi = (e + n).log10();
            chart
                .draw_series([PathElement::new(vec![(x, y), (x, hi)], c.stroke_width(1))])
                .map_err(perr("noise whisker"))?;
            chart.draw_series([cap(hi)]).map_err(perr("noise caps"))?;
            chart
                .draw_series([EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 6), (0, 18)], c.stroke_width(1))
                    + PathElement::new(vec![(-3, 13), (0, 18), (3, 13)], c.stroke_width(1))])
                .map_err(perr("arrows"))?;
            chart
                .draw_series([
                    Circle::new((x, y), 4, WHITE.filled()),
                    Circle::new((x, y), 4, c.stroke_width(2)),
                ])
                .map_err(perr("markers"))?;
        }
        Mark::Exact => {
            chart
                .draw_series([Cross::new((x, y), 5, c.stroke_width(2))])
                .map_err(perr("markers"))?;
        }
    }
    Ok(())
}

/// What the marks mean, in the legend (grey: every knob's colour).
fn mark_legend<DB: DrawingBackend>(chart: &mut Plot<'_, DB>) -> Result<()> {
    let grey = RGBColor(90, 90, 90);
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
        .map_err(perr("legend"))?
        .label("resolved: error > noise, whisker ± noise")
        .legend(move |(x, y)| Circle::new((x + 11, y), 4, grey.filled()));
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
        .map_err(perr("legend"))?
        .label("unresolved: error ≤ noise, up to error + noise, could be 0")
        .legend(move |(x, y)| Circle::new((x + 11, y), 4, grey.stroke_width(2)));
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
        .map_err(perr("legend"))?
        .label("exact: error 0 (the reference, a speed-only knob)")
        .legend(move |(x, y)| Cross::new((x + 11, y), 5, grey.stroke_width(2)));
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
        .map_err(perr("legend"))?
        .label("ring: the default setting")
        .legend(move |(x, y)| Circle::new((x + 11, y), 7, grey.stroke_width(2)));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marks_tell_resolved_unresolved_and_exact_points() {
        assert_eq!(Mark::of(0.0, 0.0), Mark::Exact);
        assert_eq!(Mark::of(0.0, 0.1), Mark::Exact);
        assert_eq!(Mark::of(0.01, 0.0), Mark::Resolved);
        assert_eq!(Mark::of(0.2, 0.05), Mark::Resolved);
        assert_eq!(Mark::of(0.05, 0.05), Mark::Unresolved);
        assert_eq!(Mark::of(0.01, 0.24), Mark::Unresolved);
    }

    /// Redraws the committed diagrams (`figures/work_precision/*.png`) from their committed CSVs,
    /// the rows unchanged (the full set takes half an hour to measure again):
    /// `cargo test --lib redraw_committed_work_precision_figures -- --ignored`.
    #[test]
    #[ignore = "rewrites figures/work_precision/*.png"]
    fn redraw_committed_work_precision_figures() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("figures/work_precision");
        for tier in Tier::ALL {
            let base = dir.join(tier.stem());
            let mut r = csv::Reader::from_path(base.with_extension("csv")).unwrap();
            let rows: Vec<WorkPrecisionRow> = r.deserialize().map(Result::unwrap).collect();
            work_precision_png(
                &base.with_extension("png"),
                &format!("work-precision, {}", tier.name()),
                tier,
                &rows,
            )
            .unwrap();
        }
    }

    /// The exact strip lies below every measured error and whisker end; a tiny measured error
    /// (1e-14) is on the error scale, not on the strip.
    #[test]
    fn the_exact_strip_lies_below_every_measured_error() {
        let pts = [(0.0, 0.0), (1e-14, 0.0), (0.2, 0.05), (0.01, 0.24)];
        let (y0, y1, strip) = error_range(&pts);
        assert!(strip < -14.0 && y0 < strip, "{y0} {strip}");
        assert!(strip + 0.3 < -14.0);
        assert!(y1 > 0.25f64.log10(), "{y1}");
        assert!((0.2f64 - 0.05).log10() > strip);
        // nothing measured: the default range, strip below it
        let (y0, y1, strip) = error_range(&[(0.0, 0.0)]);
        assert!(y0 < strip && strip < -3.0 && y1 > 0.0);
    }
}
