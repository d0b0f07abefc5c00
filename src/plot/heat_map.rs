//! Heat map of values on a (possibly oblique) grid, with a colour bar.

use super::{perr, png_atomic, viridis, FONT};
use anyhow::Result;
use plotters::prelude::*;
use std::path::Path;

/// A scalar field on an Ni×Nj grid of points `origin + i·da + j·db` (plot units), row-major
/// `values[j·Ni + i]`, with optional closed outlines and point marks drawn on top.
pub struct HeatMap<'a> {
    /// Title above the plot.
    pub title: String,
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// Colour-bar label with unit.
    pub value_label: String,
    /// Points along i and along j (Ni, Nj).
    pub n: [usize; 2],
    /// Position of the first point (plot units).
    pub origin: [f64; 2],
    /// Step between neighbouring points along i (plot units).
    pub da: [f64; 2],
    /// Step between neighbouring points along j (plot units).
    pub db: [f64; 2],
    /// Values, row-major.
    pub values: &'a [f64],
    /// Axes of different quantities: a square plot instead of equal scales.
    pub free_aspect: bool,
    /// Closed outlines drawn in white over the map (plot units).
    pub outlines: Vec<Vec<(f64, f64)>>,
    /// Points marked with a white cross (plot units).
    pub marks: Vec<(f64, f64)>,
}

/// Draws `map` to the PNG `path` (about 1000×720 px): one parallelogram tile per grid point
/// coloured with viridis between the min and max value, equal axis scales (unless
/// `free_aspect`), a labelled colour bar, then the outlines and marks.
pub fn heat_map(path: &Path, map: &HeatMap) -> Result<()> {
    let [ni, nj] = map.n;
    let (lo, hi) = map
        .values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let (lo, hi) = bar_range(lo, hi);
    let span = hi - lo;
    let pt = |i: f64, j: f64| {
        (
            map.origin[0] + i * map.da[0] + j * map.db[0],
            map.origin[1] + i * map.da[1] + j * map.db[1],
        )
    };
    let (xr, yr) = extent(ni, nj, &pt);
    // Equal aspect: plot area width/height follows the data aspect (square for free axes).
    let aspect = if map.free_aspect {
        1.0
    } else {
        (yr.1 - yr.0) / (xr.1 - xr.0)
    };
    let plot_h = 700u32;
    let plot_w = ((plot_h as f64 - 110.0) / aspect + 120.0).clamp(380.0, 1100.0) as u32;
    let size = (plot_w + 190, plot_h + 20);
    // tick decimals: one for spans of a few units, more for small spans
    let decimals = |span: f64| (-(span / 5.0).log10().floor()).clamp(1.0, 4.0) as usize;
    let (px, py) = (decimals(xr.1 - xr.0), decimals(yr.1 - yr.0));
    png_atomic(path, size, |root| {
        // The title spans the whole image (heat map + colour bar) so long titles are not cut.
        let root = root
            .titled(&map.title, (FONT, 19))
            .map_err(perr("heat map title"))?;
        let (left, right) = root.split_horizontally(plot_w);
        let mut chart = ChartBuilder::on(&left)
            .margin(12)
            .x_label_area_size(55)
            .y_label_area_size(70)
            .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
            .map_err(perr("heat map"))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(&map.x_label)
            .y_desc(&map.y_label)
            .label_style((FONT, 18))
            .axis_desc_style((FONT, 20))
            .x_label_formatter(&|v| tick(*v, px))
            .y_label_formatter(&|v| tick(*v, py))
            .draw()
            .map_err(perr("heat map axes"))?;
        let mut tiles = Vec::with_capacity(ni * nj);
        for j in 0..nj {
            for i in 0..ni {
                let (fi, fj) = (i as f64, j as f64);
                let c = viridis((map.values[j * ni + i] - lo) / span);
                tiles.push(Polygon::new(
                    vec![
                        pt(fi - 0.5, fj - 0.5),
                        pt(fi + 0.5, fj - 0.5),
                        pt(fi + 0.5, fj + 0.5),
                        pt(fi - 0.5, fj + 0.5),
                    ],
                    c.filled(),
                ));
            }
        }
        chart.draw_series(tiles).map_err(perr("heat map tiles"))?;
        for o in &map.outlines {
            let mut closed = o.clone();
            closed.extend(o.first().copied());
            chart
                .draw_series(std::iter::once(PathElement::new(
                    closed,
                    WHITE.stroke_width(3),
                )))
                .map_err(perr("heat map outline"))?;
        }
        chart
            .draw_series(
                map.marks
                    .iter()
                    .map(|&p| Cross::new(p, 9, WHITE.stroke_width(3))),
            )
            .map_err(perr("heat map marks"))?;
        colour_bar(&right, lo, hi, &map.value_label, 12)?;
        Ok(())
    })
}

/// The x and y ranges (plot units) of the `ni` × `nj` grid whose point (i, j) is at `pt(i, j)`:
/// the corners of its outer tiles.
fn extent(ni: usize, nj: usize, pt: &dyn Fn(f64, f64) -> (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let mut xr = (f64::INFINITY, f64::NEG_INFINITY);
    let mut yr = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, j) in [
        (-0.5, -0.5),
        (ni as f64 - 0.5, -0.5),
        (-0.5, nj as f64 - 0.5),
        (ni as f64 - 0.5, nj as f64 - 0.5),
    ] {
        let p = pt(i, j);
        xr = (xr.0.min(p.0), xr.1.max(p.0));
        yr = (yr.0.min(p.1), yr.1.max(p.1));
    }
    (xr, yr)
}

/// The colour bar's range for values in `[lo, hi]`: itself, or around a single value a narrow
/// bar (±1 %, at least ±0.001) whose middle colour is that value and whose ticks name it.
pub(crate) fn bar_range(lo: f64, hi: f64) -> (f64, f64) {
    if hi > lo {
        (lo, hi)
    } else {
        let h = (lo.abs() * 0.01).max(1e-3);
        (lo - h, lo + h)
    }
}

/// A tick label with `prec` decimals, never `-0.0` (a tick at −1e-17 is 0).
pub(crate) fn tick(v: f64, prec: usize) -> String {
    let s = format!("{v:.prec$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// Draws a vertical viridis colour bar for `[lo, hi]` with a label into `area`, `margin_top`
/// pixels below its top (to line up with the chart next to it).
pub(crate) fn colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    lo: f64,
    hi: f64,
    label: &str,
    margin_top: u32,
) -> Result<()> {
    let (lo, hi_v) = bar_range(lo, hi);
    // Enough decimals to tell ticks apart: span 88 → 0, 5.7 → 1, 0.3 → 2.
    let prec = (1.0 - (hi_v - lo).log10().floor()).clamp(0.0, 4.0) as usize;
    let mut bar = ChartBuilder::on(area)
        .margin_top(margin_top)
        .margin_bottom(67)
        .margin_right(10)
        .y_label_area_size(95)
        .build_cartesian_2d(0f64..1f64, lo..hi_v)
        .map_err(perr("colour bar"))?;
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(label)
        .label_style((FONT, 17))
        .axis_desc_style((FONT, 19))
        .y_label_formatter(&|v| tick(*v, prec))
        .draw()
        .map_err(perr("colour bar axis"))?;
    let steps = 200;
    bar.draw_series((0..steps).map(|k| {
        let a = lo + (hi_v - lo) * k as f64 / steps as f64;
        let b = lo + (hi_v - lo) * (k + 1) as f64 / steps as f64;
        Rectangle::new(
            [(0.0, a), (1.0, b)],
            viridis(k as f64 / (steps - 1) as f64).filled(),
        )
    }))
    .map_err(perr("colour bar"))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    #[test]
    fn ticks_never_read_minus_zero() {
        assert_eq!(super::tick(-1e-17, 1), "0.0");
        assert_eq!(super::tick(-0.04, 1), "0.0");
        assert_eq!(super::tick(-0.06, 1), "-0.1");
        assert_eq!(super::tick(1.75, 2), "1.75");
    }
}
