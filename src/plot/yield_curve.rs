//! The yield chart of `superlube yield` (`yield.png`): yield(W) as a step curve inside its
//! shaded Clopper–Pearson band, q as a dashed line, the quoted load (solid) and its lower
//! bound (dotted) marked and labelled to 3 significant digits, the DEM check as a point with
//! its interval; the x axis ranged to the data, the legend in the lower left, clear of a curve
//! that falls from the upper left.

use super::chart::PALETTE;
use super::{perr, png_atomic, FONT};
use crate::study::fab_yield::{CurvePoint, YieldSummary};
use anyhow::Result;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use std::path::Path;
use surrogate::units::significant;

/// A load (mN) as the chart, the log and the report print it: 3 significant digits, trailing
/// zeros kept (the report's `fmt_g(w, 3)`; the bisection resolves 1 % of the load, so more
/// digits are noise).
pub fn load_text(w: f64) -> String {
    let a = w.abs();
    if !w.is_finite() || w == 0.0 || !(1e-3..1e4).contains(&a) {
        return format!("{}", significant(w, 3));
    }
    let d = (2 - a.log10().floor() as i32).max(0) as usize;
    format!("{w:.d$}")
}

/// The step polyline of `value` over the curve's points (ascending loads, mN) from `x0`: the
/// value at each point holds from the previous point up to that point, then falls to the next
/// point's; past the last, `tail` up to `x_end`.
fn steps(
    curve: &[CurvePoint],
    value: fn(&CurvePoint) -> f64,
    x0: f64,
    tail: f64,
    x_end: f64,
) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * curve.len() + 2);
    let mut x = x0;
    for c in curve {
        let y = value(c);
        out.push((x, y));
        out.push((c.load_mN, y));
        x = c.load_mN;
    }
    out.push((x, tail));
    out.push((x_end, tail));
    out
}

/// The x range (mN) of the chart: the curve's loads, the quoted load, its bound and the DEM
/// check's load, widened by 8 % of their span each side (not from 0: the curve would sit in a
/// corner).
fn x_range(s: &YieldSummary) -> (f64, f64) {
    let xs: Vec<f64> = s
        .curve
        .iter()
        .map(|c| c.load_mN)
        .chain(s.load_at_quantile_mN)
        .chain(s.load_at_quantile_bound_mN)
        .chain(s.dem_check_load_mN)
        .filter(|x| x.is_finite())
        .collect();
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = if hi > lo {
        0.08 * (hi - lo)
    } else {
        0.1 * hi.abs().max(0.01)
    };
    ((lo - pad).max(0.0), hi + pad)
}

/// The legend entries of the chart, in drawing order: curve, band, quoted load, bound, DEM
/// check (those present).
fn labels(s: &YieldSummary) -> Vec<String> {
    let q = 100.0 * s.quantile;
    let g = 100.0 * s.confidence;
    let mut out = vec![
        "yield: fraction of devices with W_c ≥ W".to_string(),
        format!("{g:.0} % interval (Clopper–Pearson)"),
    ];
    if let Some(w) = s.load_at_quantile_mN {
        out.push(format!("load at {q:.0} % yield: {} mN", load_text(w)));
    }
    if let Some(b) = s.load_at_quantile_bound_mN {
        out.push(format!("its {g:.0} % lower bound: {} mN", load_text(b)));
    }
    if let (Some(w), true) = (s.dem_check_load_mN, s.dem_check_total > 0) {
        out.push(format!(
            "DEM check at {} mN: {} of {} held",
            load_text(w),
            s.dem_check_passed,
            s.dem_check_total
        ));
    }
    out
}

/// Draws `yield.png` at `path` from the summary. Cost: one 1000×700 PNG.
pub fn yield_png(path: &Path, s: &YieldSummary) -> Result<()> {
    let (x0, x1) = x_range(s);
    // the last band's upper end past the highest critical load: P(W_c > W_max) ≤ that
    let tail_high =
        crate::study::fab_yield::interval::clopper_pearson(0, s.samples, s.confidence).1;
    let names = labels(s);
    let mut name = names.into_iter();
    let title = format!(
        "{}: yield at θ = {}°, direction {}° ({} devices)",
        s.pattern, s.theta_deg, s.direction_deg, s.samples
    );
    png_atomic(path, (1000, 700), |root| {
        let mut ch = ChartBuilder::on(&root)
            .caption(&title, (FONT, 22))
            .margin(12)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, -0.03..1.05)
            .map_err(perr("chart"))?;
        ch.configure_mesh()
            .x_desc("normal load W (mN)")
            .y_desc("yield (fraction of devices superlubric)")
            .label_style((FONT, 17))
            .axis_desc_style((FONT, 19))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(perr("chart axes"))?;
        band_and_curve(&mut ch, s, (x0, x1), tail_high, &mut name)?;
        quantile_lines(&mut ch, s, (x0, x1), &mut name)?;
        dem_check(&mut ch, s, (x0, x1), &mut name)?;
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font((FONT, 16))
            .position(SeriesLabelPosition::LowerLeft)
            .draw()
            .map_err(perr("legend"))?;
        Ok(())
    })
}

/// The yield chart's plotting area: load (mN) against yield.
type Plot<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The yield curve's confidence band (filled; `tail_high`: its upper end past the highest
/// critical load) and the curve, over loads `x0..x1` (mN), with their legend `names`.
fn band_and_curve<'a, DB: DrawingBackend + 'a>(
    ch: &mut Plot<'a, DB>,
    s: &YieldSummary,
    (x0, x1): (f64, f64),
    tail_high: f64,
    name: &mut impl Iterator<Item = String>,
) -> Result<()> {
    let c = &s.curve;
    let (curve_c, band_c) = (PALETTE[0], PALETTE[0]);
    // the band: the low steps forward, the high steps back, filled
    let low = steps(c, |p| p.low, x0, 0.0, x1);
    let high = steps(c, |p| p.high, x0, tail_high, x1);
    let poly: Vec<(f64, f64)> = low.iter().chain(high.iter().rev()).copied().collect();
    let band_name = name.nth(1).unwrap_or_default();
    ch.draw_series(std::iter::once(Polygon::new(
        poly,
        band_c.mix(0.2).filled(),
    )))
    .map_err(perr("band"))?
    .label(band_name)
    .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 22, y + 6)], band_c.mix(0.2).filled()));
    let curve_name = labels(s).remove(0);
    ch.draw_series(LineSeries::new(
        steps(c, |p| p.fraction, x0, 0.0, x1),
        curve_c.stroke_width(3),
    ))
    .map_err(perr("curve"))?
    .label(curve_name)
    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], curve_c.stroke_width(3)));
    Ok(())
}

/// The quantile q (dashed), the load quoted at it (solid) and its confidence bound (dotted).
fn quantile_lines<'a, DB: DrawingBackend + 'a>(
    ch: &mut Plot<'a, DB>,
    s: &YieldSummary,
    (x0, x1): (f64, f64),
    name: &mut impl Iterator<Item = String>,
) -> Result<()> {
    let (q_c, b_c) = (PALETTE[3], PALETTE[1]);
    // q: dashed black
    let dashes = (0..60).step_by(2).map(|k| {
        let a = x0 + (x1 - x0) * k as f64 / 60.0;
        let b = x0 + (x1 - x0) * (k + 1) as f64 / 60.0;
        PathElement::new(
            vec![(a, s.quantile), (b, s.quantile)],
            BLACK.stroke_width(2),
        )
    });
    ch.draw_series(dashes)
        .map_err(perr("q line"))?
        .label(format!("q = {}", s.quantile))
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(2)));
    // the quoted load: a solid line; its bound: dotted, so both show where they meet
    if let Some(w) = s.load_at_quantile_mN {
        ch.draw_series(LineSeries::new(
            vec![(w, 0.0), (w, 1.0)],
            q_c.stroke_width(3),
        ))
        .map_err(perr("quoted load"))?
        .label(name.next().unwrap_or_default())
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], q_c.stroke_width(3)));
    }
    if let Some(b) = s.load_at_quantile_bound_mN {
        let dots = (0..40).step_by(2).map(move |k| {
            let (a, e) = (k as f64 / 40.0, (k + 1) as f64 / 40.0);
            PathElement::new(vec![(b, a), (b, e)], b_c.stroke_width(3))
        });
        ch.draw_series(dots)
            .map_err(perr("bound"))?
            .label(name.next().unwrap_or_default())
            .legend(move |(x, y)| {
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 0), (8, 0)], b_c.stroke_width(3))
                    + PathElement::new(vec![(14, 0), (22, 0)], b_c.stroke_width(3))
            });
    }
    Ok(())
}

/// The DEM check: its passed fraction at its load, with its interval (none without a check).
fn dem_check<'a, DB: DrawingBackend + 'a>(
    ch: &mut Plot<'a, DB>,
    s: &YieldSummary,
    (x0, x1): (f64, f64),
    name: &mut impl Iterator<Item = String>,
) -> Result<()> {
    let dem_c = PALETTE[2];
    if let (Some(w), Some([lo, hi]), true) = (
        s.dem_check_load_mN,
        s.dem_check_interval,
        s.dem_check_total > 0,
    ) {
        let f = s.dem_check_passed as f64 / s.dem_check_total as f64;
        // the interval: a vertical bar with caps
        let cap = 0.01 * (x1 - x0);
        let bar = [
            vec![(w, lo), (w, hi)],
            vec![(w - cap, lo), (w + cap, lo)],
            vec![(w - cap, hi), (w + cap, hi)],
        ];
        ch.draw_series(
            bar.into_iter()
                .map(|p| PathElement::new(p, dem_c.stroke_width(2))),
        )
        .map_err(perr("DEM check interval"))?;
        ch.draw_series(std::iter::once(
            EmptyElement::at((w, f))
                + Circle::new((0, 0), 7, dem_c.filled())
                + Circle::new((0, 0), 7, BLACK.stroke_width(1)),
        ))
        .map_err(perr("DEM check"))?
        .label(name.next().unwrap_or_default())
        .legend(move |(x, y)| Circle::new((x + 11, y), 6, dem_c.filled()));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loads_are_printed_to_three_significant_digits() {
        assert_eq!(load_text(0.161328125), "0.161");
        assert_eq!(load_text(1.40625), "1.41");
        assert_eq!(load_text(1.4), "1.40");
        assert_eq!(load_text(1.02265625), "1.02");
        assert_eq!(load_text(3.86), "3.86");
    }
}
