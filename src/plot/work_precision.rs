//! Work-precision diagrams: per scene a panel of log₁₀ CPU cost against log₁₀ relative error,
//! one line per knob (its settings in refinement order), the default ringed, the noise of each
//! point (the DEM window's standard error) drawn as a vertical bar, errors below the floor
//! drawn at the floor (the reference itself, and speed-only knobs, whose error is 0). The tiers
//! diagram draws each method (each setting of its one knob) as its own labelled point.

use super::chart::PALETTE;
use super::{perr, png_atomic, FONT};
use crate::study::work_precision::check::larger_is_finer;
use crate::study::work_precision::{Tier, WorkPrecisionRow};
use anyhow::Result;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Errors below this (relative) are drawn at it.
pub const ERROR_FLOOR: f64 = 1e-7;

/// Draws the diagram of one tier's `rows` into the PNG `path` (one panel per scene; the tiers
/// diagram one series per method, the others one per knob).
pub fn work_precision_png(
    path: &Path,
    title: &str,
    tier: Tier,
    rows: &[WorkPrecisionRow],
) -> Result<()> {
    let rows: Vec<WorkPrecisionRow> = if tier == Tier::Tiers {
        // one series per method: the method is the series' name
        rows.iter()
            .map(|r| WorkPrecisionRow {
                knob: r.setting.clone(),
                ..r.clone()
            })
            .collect()
    } else {
        rows.to_vec()
    };
    let rows = &rows;
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
            panel(area, &format!("{title}: {scene}"), &rs, legend())?;
        }
        Ok(())
    })
}

fn y_of(e: f64) -> f64 {
    e.max(ERROR_FLOOR).log10()
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    rows: &[&WorkPrecisionRow],
    legend: SeriesLabelPosition,
) -> Result<()> {
    let mut knobs: Vec<&str> = Vec::new();
    for r in rows {
        if !knobs.contains(&r.knob.as_str()) {
            knobs.push(&r.knob);
        }
    }
    let pts: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.cost_cpu_s > 0.0)
        .map(|r| (r.cost_cpu_s.log10(), y_of(r.error_rel)))
        .collect();
    let (mut x0, mut x1, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, ERROR_FLOOR.log10());
    for &(x, y) in &pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y1 = y1.max(y);
    }
    for r in rows {
        if r.noise_rel > 0.0 {
            y1 = y1.max(y_of(r.error_rel + r.noise_rel));
        }
    }
    if !x0.is_finite() {
        (x0, x1) = (-3.0, 0.0);
    }
    if x1 - x0 < 0.5 {
        (x0, x1) = (x0 - 0.25, x1 + 0.25);
    }
    let y0 = ERROR_FLOOR.log10() - 0.3;
    let y1 = y1 + 0.5;
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
    for (k, knob) in knobs.iter().enumerate() {
        let c = PALETTE[k % PALETTE.len()];
        let mut v: Vec<&&WorkPrecisionRow> = rows
            .iter()
            .filter(|r| r.knob == *knob && r.cost_cpu_s > 0.0)
            .collect();
        if let Some(up) = larger_is_finer(knob) {
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
        let line: Vec<(f64, f64)> = v
            .iter()
            .map(|r| (r.cost_cpu_s.log10(), y_of(r.error_rel)))
            .collect();
        chart
            .draw_series(LineSeries::new(line.clone(), c.stroke_width(2)))
            .map_err(perr("series"))?
            .label(*knob)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], c.stroke_width(3)));
        chart
            .draw_series(line.iter().map(|&p| Circle::new(p, 4, c.filled())))
            .map_err(perr("markers"))?;
        for (r, &(x, y)) in v.iter().zip(&line) {
            if r.noise_rel > 0.0 {
                let lo = y_of((r.error_rel - r.noise_rel).max(0.0));
                let hi = y_of(r.error_rel + r.noise_rel);
                chart
                    .draw_series([PathElement::new(vec![(x, lo), (x, hi)], c.stroke_width(1))])
                    .map_err(perr("noise bars"))?;
            }
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
