//! Line plots with legends and horizontal reference lines.

use super::{perr, png_atomic, FONT};
use anyhow::Result;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Colour-blind-friendly palette (Tableau 10), used in series order.
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

/// One curve.
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Points `(x, y)` in plot units.
    pub points: Vec<(f64, f64)>,
}

/// A line plot: curves, dashed horizontal reference lines, optional logarithmic y axis.
pub struct LinePlot {
    /// Title above the plot.
    pub title: String,
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// The curves (coloured from `PALETTE` in order).
    pub series: Vec<Series>,
    /// Horizontal reference lines `(y, legend entry)`, drawn dashed black.
    pub hlines: Vec<(f64, String)>,
    /// Logarithmic y axis (values ≤ 0 are dropped).
    pub log_y: bool,
}

/// Draws `plot` into the PNG `path` of `size` pixels.
pub fn line_plot(path: &Path, size: (u32, u32), plot: &LinePlot) -> Result<()> {
    png_atomic(path, size, |root| line_plot_area(&root, plot))
}

/// Draws `panels` stacked top to bottom, equal heights, into the PNG `path` of `size` pixels.
pub fn stacked_line_plots(path: &Path, size: (u32, u32), panels: &[&LinePlot]) -> Result<()> {
    png_atomic(path, size, |root| {
        let areas = root.split_evenly((panels.len(), 1));
        for (area, plot) in areas.iter().zip(panels) {
            line_plot_area(area, plot)?;
        }
        Ok(())
    })
}

/// Draws `plot` into a drawing area (used to stack panels in one PNG).
pub fn line_plot_area<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    plot: &LinePlot,
) -> Result<()> {
    let tf = |y: f64| if plot.log_y { y.log10() } else { y };
    let keep = |y: f64| y.is_finite() && (!plot.log_y || y > 0.0);
    let mut xr = (f64::INFINITY, f64::NEG_INFINITY);
    let mut yr = (f64::INFINITY, f64::NEG_INFINITY);
    for s in &plot.series {
        for &(x, y) in &s.points {
            if keep(y) && x.is_finite() {
                xr = (xr.0.min(x), xr.1.max(x));
                yr = (yr.0.min(tf(y)), yr.1.max(tf(y)));
            }
        }
    }
    for &(y, _) in &plot.hlines {
        if keep(y) {
            yr = (yr.0.min(tf(y)), yr.1.max(tf(y)));
        }
    }
    if !xr.0.is_finite() {
        xr = (0.0, 1.0);
        yr = (0.0, 1.0);
    }
    if xr.1 <= xr.0 {
        xr = (xr.0 - 0.5, xr.0 + 0.5);
    }
    let pad = if yr.1 > yr.0 {
        0.06 * (yr.1 - yr.0)
    } else {
        0.5
    };
    let yr = (
        if plot.log_y {
            yr.0 - pad
        } else {
            (yr.0 - pad).min(if yr.0 >= 0.0 { 0.0 } else { yr.0 - pad })
        },
        yr.1 + pad,
    );
    let mut chart = ChartBuilder::on(area)
        .caption(&plot.title, (FONT, 22))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(perr("line plot"))?;
    let log = plot.log_y;
    let yfmt = move |v: &f64| {
        if log {
            let p = 10f64.powf(*v);
            if p >= 10.0 {
                format!("{p:.0}")
            } else {
                format!("{p:.2}")
            }
        } else {
            let a = v.abs();
            if a == 0.0 || (1e-2..1e4).contains(&a) {
                format!("{v:.2}")
            } else {
                format!("{v:.1e}")
            }
        }
    };
    chart
        .configure_mesh()
        .x_desc(&plot.x_label)
        .y_desc(&plot.y_label)
        .label_style((FONT, 17))
        .axis_desc_style((FONT, 19))
        .light_line_style(RGBColor(235, 235, 235))
        .y_label_formatter(&yfmt)
        .draw()
        .map_err(perr("line plot axes"))?;
    for (k, s) in plot.series.iter().enumerate() {
        let c = PALETTE[k % PALETTE.len()];
        let pts: Vec<(f64, f64)> = s
            .points
            .iter()
            .filter(|p| keep(p.1) && p.0.is_finite())
            .map(|&(x, y)| (x, tf(y)))
            .collect();
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(2)))
            .map_err(perr("series"))?
            .label(&s.name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], c.stroke_width(3)));
    }
    for (y, name) in &plot.hlines {
        if !keep(*y) {
            continue;
        }
        let yy = tf(*y);
        let n = 60;
        let dashes = (0..n).step_by(2).map(move |k| {
            let a = xr.0 + (xr.1 - xr.0) * k as f64 / n as f64;
            let b = xr.0 + (xr.1 - xr.0) * (k + 1) as f64 / n as f64;
            PathElement::new(vec![(a, yy), (b, yy)], BLACK.stroke_width(2))
        });
        chart
            .draw_series(dashes)
            .map_err(perr("reference line"))?
            .label(name)
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FONT, 16))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(perr("legend"))?;
    Ok(())
}
