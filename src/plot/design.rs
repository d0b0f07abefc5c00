//! The figures of `superlube design`: curves and marker series on one chart (P_max versus θ per
//! load with P_crit; corrugation versus α of the finalists; μ versus load, surrogate lines and
//! DEM markers), with colours from a given palette index or the viridis map.

use super::line_plot::PALETTE;
use super::{perr, png_atomic, viridis, FONT};
use anyhow::Result;
use plotters::prelude::*;
use std::path::Path;

/// How a curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Style {
    /// A line through the points.
    Line,
    /// A line with a small circle at every point.
    LinePoints,
    /// Large filled markers only (e.g. DEM results).
    Markers,
    /// Open rings, larger than the markers (a second value at the same points stays visible
    /// around a marker).
    Rings,
}

/// One curve of a [`Chart`].
#[derive(Debug, Clone)]
pub struct Curve {
    /// Legend entry.
    pub name: String,
    /// Points (x, y) in plot units.
    pub points: Vec<(f64, f64)>,
    /// Colour: `Palette(k)` (Tableau 10) or `Scale(t)` (viridis, t in [0, 1]).
    pub colour: Colour,
    /// Line, line with points, or markers.
    pub style: Style,
}

/// A colour choice of a [`Curve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Colour {
    /// Palette index (cycled).
    Palette(usize),
    /// Viridis at t ∈ [0, 1].
    Scale(f64),
}

impl Colour {
    fn rgb(self) -> RGBColor {
        match self {
            Colour::Palette(k) => PALETTE[k % PALETTE.len()],
            Colour::Scale(t) => viridis(t * 0.9),
        }
    }
}

/// A chart: curves, dashed horizontal reference lines, optional logarithmic y axis.
#[derive(Debug, Clone)]
pub struct Chart {
    /// Title.
    pub title: String,
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// Curves.
    pub curves: Vec<Curve>,
    /// Horizontal reference lines (y, legend entry), dashed black.
    pub hlines: Vec<(f64, String)>,
    /// Logarithmic y axis (values ≤ 0 are dropped).
    pub log_y: bool,
}

/// Draws `chart` into the PNG `path` (1100 × 700 pixels).
pub fn chart_png(path: &Path, chart: &Chart) -> Result<()> {
    png_atomic(path, (1100, 700), |root| {
        let tf = |y: f64| if chart.log_y { y.log10() } else { y };
        let keep = |y: f64| y.is_finite() && (!chart.log_y || y > 0.0);
        let mut xr = (f64::INFINITY, f64::NEG_INFINITY);
        let mut yr = (f64::INFINITY, f64::NEG_INFINITY);
        for c in &chart.curves {
            for &(x, y) in &c.points {
                if keep(y) && x.is_finite() {
                    xr = (xr.0.min(x), xr.1.max(x));
                    yr = (yr.0.min(tf(y)), yr.1.max(tf(y)));
                }
            }
        }
        for &(y, _) in &chart.hlines {
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
        let xpad = 0.03 * (xr.1 - xr.0);
        let xr = (xr.0 - xpad, xr.1 + xpad);
        let pad = if yr.1 > yr.0 {
            0.08 * (yr.1 - yr.0)
        } else {
            0.5
        };
        let yr = (
            if chart.log_y || yr.0 < 0.0 {
                yr.0 - pad
            } else {
                0.0
            },
            yr.1 + pad,
        );
        let mut ch = ChartBuilder::on(&root)
            .caption(&chart.title, (FONT, 22))
            .margin(12)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
            .map_err(perr("chart"))?;
        let log = chart.log_y;
        let yfmt = move |v: &f64| {
            let p = if log { 10f64.powf(*v) } else { *v };
            let a = p.abs();
            if a == 0.0 || (0.1..1e4).contains(&a) {
                format!("{p:.2}")
            } else if (1e-3..0.1).contains(&a) {
                format!("{p:.3}")
            } else {
                format!("{p:.1e}")
            }
        };
        ch.configure_mesh()
            .x_desc(&chart.x_label)
            .y_desc(&chart.y_label)
            .label_style((FONT, 17))
            .axis_desc_style((FONT, 19))
            .light_line_style(RGBColor(235, 235, 235))
            .y_label_formatter(&yfmt)
            .draw()
            .map_err(perr("chart axes"))?;
        for c in &chart.curves {
            let col = c.colour.rgb();
            let pts: Vec<(f64, f64)> = c
                .points
                .iter()
                .filter(|p| keep(p.1) && p.0.is_finite())
                .map(|&(x, y)| (x, tf(y)))
                .collect();
            match c.style {
                Style::Line | Style::LinePoints => {
                    ch.draw_series(LineSeries::new(pts.clone(), col.stroke_width(2)))
                        .map_err(perr("curve"))?
                        .label(&c.name)
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 22, y)], col.stroke_width(3))
                        });
                    if c.style == Style::LinePoints {
                        ch.draw_series(pts.iter().map(|&p| Circle::new(p, 3, col.filled())))
                            .map_err(perr("points"))?;
                    }
                }
                Style::Markers => {
                    ch.draw_series(pts.iter().map(|&p| {
                        EmptyElement::at(p)
                            + Circle::new((0, 0), 8, col.filled())
                            + Circle::new((0, 0), 8, BLACK.stroke_width(1))
                    }))
                    .map_err(perr("markers"))?
                    .label(&c.name)
                    .legend(move |(x, y)| Circle::new((x + 11, y), 6, col.filled()));
                }
                Style::Rings => {
                    ch.draw_series(pts.iter().map(|&p| Circle::new(p, 12, col.stroke_width(3))))
                        .map_err(perr("rings"))?
                        .label(&c.name)
                        .legend(move |(x, y)| Circle::new((x + 11, y), 6, col.stroke_width(2)));
                }
            }
        }
        for (y, name) in &chart.hlines {
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
            ch.draw_series(dashes)
                .map_err(perr("reference line"))?
                .label(name)
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(2))
                });
        }
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT, 15))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(perr("legend"))?;
        Ok(())
    })
}
