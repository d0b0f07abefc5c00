//! The one line-chart engine: curves (lines, lines with points, markers, rings) and dashed
//! horizontal reference lines on one chart, a linear or logarithmic y axis, a legend. The
//! design report's figures (P_max versus θ per load with P_crit; corrugation versus α of the
//! finalists; μ versus load, surrogate lines and DEM markers) draw [`Chart`]s with
//! [`chart_png`]; the study's figures draw [`super::LinePlot`]s through it in the
//! [`Look::Figures`] framing.

use super::{perr, png_atomic, viridis, FONT};
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

/// How a chart frames its data (the axes' margins, tick labels, legend size).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Look {
    /// The design report's: x range widened 3 % each side, y by 8 %; a linear y axis of
    /// non-negative data starts at 0; y ticks to 2 decimals, 3 below 0.1, else exponent form;
    /// legend 15 pt.
    Report,
    /// The study's figures: the x range of the data, y widened 6 %, a linear y axis reaching
    /// down to 0 only where the margin crosses it; y ticks to 2 decimals (whole numbers from 10
    /// on a log axis), exponent form outside [0.01, 10⁴); legend 16 pt.
    Figures,
}

impl Look {
    /// The margin each side of the x range, as a fraction of it.
    fn x_margin(self) -> f64 {
        match self {
            Look::Report => 0.03,
            Look::Figures => 0.0,
        }
    }

    /// The margin above and below the y range (in axis units, log10 on a log axis), as a
    /// fraction of it.
    fn y_margin(self) -> f64 {
        match self {
            Look::Report => 0.08,
            Look::Figures => 0.06,
        }
    }

    /// The bottom of the y axis for data from `lo` with margin `pad`.
    fn y_bottom(self, lo: f64, pad: f64, log: bool) -> f64 {
        match self {
            Look::Report if log || lo < 0.0 => lo - pad,
            Look::Report => 0.0,
            Look::Figures if log => lo - pad,
            Look::Figures => (lo - pad).min(if lo >= 0.0 { 0.0 } else { lo - pad }),
        }
    }

    /// The label of the y tick at `v` (axis units: log10 of the value on a log axis).
    fn y_tick(self, v: f64, log: bool) -> String {
        match self {
            Look::Report => {
                let p = if log { 10f64.powf(v) } else { v };
                let a = p.abs();
                if a == 0.0 || (0.1..1e4).contains(&a) {
                    format!("{p:.2}")
                } else if (1e-3..0.1).contains(&a) {
                    format!("{p:.3}")
                } else {
                    format!("{p:.1e}")
                }
            }
            Look::Figures if log => {
                let p = 10f64.powf(v);
                if p >= 10.0 {
                    format!("{p:.0}")
                } else {
                    format!("{p:.2}")
                }
            }
            Look::Figures => {
                let a = v.abs();
                if a == 0.0 || (1e-2..1e4).contains(&a) {
                    format!("{v:.2}")
                } else {
                    format!("{v:.1e}")
                }
            }
        }
    }

    /// The legend's font size (pt).
    fn legend_font(self) -> u32 {
        match self {
            Look::Report => 15,
            Look::Figures => 16,
        }
    }
}

/// Draws `chart` into the PNG `path` (1100 × 700 pixels) in the design report's look.
pub fn chart_png(path: &Path, chart: &Chart) -> Result<()> {
    png_atomic(path, (1100, 700), |root| draw(&root, chart, Look::Report))
}

/// Draws `chart` into a drawing area (a whole PNG or one panel of a stack) in the look `look`.
/// O(points).
pub fn draw<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    chart: &Chart,
    look: Look,
) -> Result<()> {
    let tf = |y: f64| if chart.log_y { y.log10() } else { y };
    let keep = |y: f64| y.is_finite() && (!chart.log_y || y > 0.0);
    let (xr, yr) = ranges(chart, look);
    let mut ch = ChartBuilder::on(area)
        .caption(&chart.title, (FONT, 22))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(perr("chart"))?;
    let log = chart.log_y;
    let yfmt = move |v: &f64| look.y_tick(*v, log);
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
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(2)));
    }
    ch.configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FONT, look.legend_font()))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(perr("legend"))?;
    Ok(())
}

/// The x and y ranges of the axes (y in axis units): the finite points' (and reference lines')
/// extent, widened by the look's margins; `(0, 1)` each without a point. O(points).
fn ranges(chart: &Chart, look: Look) -> ((f64, f64), (f64, f64)) {
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
    let xpad = look.x_margin() * (xr.1 - xr.0);
    let xr = (xr.0 - xpad, xr.1 + xpad);
    let pad = if yr.1 > yr.0 {
        look.y_margin() * (yr.1 - yr.0)
    } else {
        0.5
    };
    let yr = (look.y_bottom(yr.0, pad, chart.log_y), yr.1 + pad);
    (xr, yr)
}
