//! The friction campaign's figures: friction force (mN) and μ versus load (mN), one curve per
//! series with markers and error bars (mean ± sample standard deviation over the seeds).

use super::chart::PALETTE;
use super::{perr, png_atomic, FONT};
use crate::study::rows::ConfigStatsRow;
use anyhow::Result;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Points (load mN, mean, spread) of one series.
type Points = Vec<(f64, f64, f64)>;

/// One panel: y of a row (mean, spread) and its axis label.
struct Panel<'a> {
    title: String,
    y_label: &'a str,
    y: fn(&ConfigStatsRow) -> Option<(f64, f64)>,
}

/// Draws the figure of `rows` (a [`ConfigStatsRow`] per series × load, grouped by series in
/// order) into the PNG `path`: friction force on top, μ below, versus load.
pub fn friction_png(path: &Path, title: &str, rows: &[ConfigStatsRow]) -> Result<()> {
    let panels = [
        Panel {
            title: format!("{title}: friction force"),
            y_label: "friction force (mN)",
            y: |r| {
                r.friction_mean_mN
                    .map(|m| (m, r.friction_std_mN.unwrap_or(0.0)))
            },
        },
        Panel {
            title: format!("{title}: friction coefficient"),
            y_label: "friction coefficient μ (1)",
            y: |r| r.mu_mean.map(|m| (m, r.mu_std.unwrap_or(0.0))),
        },
    ];
    png_atomic(path, (1100, 1300), |root| {
        let areas = root.split_evenly((2, 1));
        for (area, p) in areas.iter().zip(&panels) {
            panel(area, p, rows)?;
        }
        Ok(())
    })
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    p: &Panel,
    rows: &[ConfigStatsRow],
) -> Result<()> {
    let mut series: Vec<(&str, Points)> = Vec::new();
    for r in rows {
        let pt = (p.y)(r).map(|(m, s)| (r.load_mN, m, s));
        match series.iter_mut().find(|s| s.0 == r.series) {
            Some(s) => s.1.extend(pt),
            None => series.push((&r.series, pt.into_iter().collect())),
        }
    }
    let mut xr = (f64::INFINITY, f64::NEG_INFINITY);
    let mut yr = (0.0f64, f64::NEG_INFINITY);
    for (_, pts) in &series {
        for &(x, y, s) in pts {
            if x.is_finite() && y.is_finite() {
                xr = (xr.0.min(x), xr.1.max(x));
                yr = (yr.0.min(y - s), yr.1.max(y + s));
            }
        }
    }
    if !xr.0.is_finite() {
        xr = (0.0, 4.0);
    }
    if xr.1 <= xr.0 {
        xr = (xr.0 - 0.5, xr.0 + 0.5);
    }
    if yr.1.partial_cmp(&yr.0) != Some(std::cmp::Ordering::Greater) {
        yr = (0.0, 1.0);
    }
    let pad = 0.06 * (yr.1 - yr.0);
    let xpad = 0.03 * (xr.1 - xr.0);
    let mut chart = ChartBuilder::on(area)
        .caption(&p.title, (FONT, 22))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(xr.0 - xpad..xr.1 + xpad, yr.0 - pad..yr.1 + pad)
        .map_err(perr("friction plot"))?;
    chart
        .configure_mesh()
        .x_desc("load W (mN)")
        .y_desc(p.y_label)
        .label_style((FONT, 17))
        .axis_desc_style((FONT, 19))
        .light_line_style(RGBColor(235, 235, 235))
        .y_label_formatter(&|v: &f64| {
            let a = v.abs();
            if a == 0.0 || (1e-2..1e4).contains(&a) {
                format!("{v:.3}")
            } else {
                format!("{v:.1e}")
            }
        })
        .draw()
        .map_err(perr("friction plot axes"))?;
    for (k, (name, pts)) in series.iter().enumerate() {
        let c = PALETTE[k % PALETTE.len()];
        let line: Vec<(f64, f64)> = pts.iter().map(|&(x, y, _)| (x, y)).collect();
        chart
            .draw_series(LineSeries::new(line.clone(), c.stroke_width(2)))
            .map_err(perr("series"))?
            .label(*name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], c.stroke_width(3)));
        chart
            .draw_series(line.iter().map(|&p| Circle::new(p, 4, c.filled())))
            .map_err(perr("markers"))?;
        // error bars: a vertical line from mean − std to mean + std with caps
        let cap = 0.008 * (xr.1 - xr.0);
        for &(x, y, s) in pts.iter().filter(|p| p.2 > 0.0) {
            let (lo, hi) = (y - s, y + s);
            chart
                .draw_series([
                    PathElement::new(vec![(x, lo), (x, hi)], c.stroke_width(2)),
                    PathElement::new(vec![(x - cap, lo), (x + cap, lo)], c.stroke_width(2)),
                    PathElement::new(vec![(x - cap, hi), (x + cap, hi)], c.stroke_width(2)),
                ])
                .map_err(perr("error bars"))?;
        }
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FONT, 15))
        .position(SeriesLabelPosition::UpperLeft)
        .draw()
        .map_err(perr("legend"))?;
    Ok(())
}
