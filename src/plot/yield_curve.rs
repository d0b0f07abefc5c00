//! The yield chart of `superlube yield` (`yield.png`): yield(W) as a step curve with its
//! Clopper–Pearson band, q as a dashed line, the quoted load and its bound marked.

use super::{line_plot, LinePlot, Series};
use crate::study::fab_yield::{CurvePoint, YieldSummary};
use anyhow::Result;
use std::path::Path;

/// The step polyline of `value` over the curve's points (ascending loads, mN): the value at
/// each point holds from the previous point (from 0 for the first) up to that point, then
/// falls to the next point's; past the last, 0 (the band's upper end: its own).
fn steps(
    curve: &[CurvePoint],
    value: fn(&CurvePoint) -> f64,
    tail: f64,
    x_end: f64,
) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * curve.len() + 2);
    let mut x = 0.0;
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

/// Draws `yield.png` at `path` from the summary's curve. Cost: one 1000×700 PNG.
pub fn yield_png(path: &Path, s: &YieldSummary) -> Result<()> {
    let c = &s.curve;
    let x_end = c.last().map_or(1.0, |p| p.load_mN) * 1.1;
    // the last band's upper end past the highest critical load: P(W_c > W_max) ≤ that
    let tail_high =
        crate::study::fab_yield::interval::clopper_pearson(0, s.samples, s.confidence).1;
    let mut series = vec![
        Series {
            name: "yield (fraction of devices with W_c ≥ W)".into(),
            points: steps(c, |p| p.fraction, 0.0, x_end),
        },
        Series {
            name: format!(
                "{:.0} % interval (Clopper–Pearson), low",
                100.0 * s.confidence
            ),
            points: steps(c, |p| p.low, 0.0, x_end),
        },
        Series {
            name: format!(
                "{:.0} % interval (Clopper–Pearson), high",
                100.0 * s.confidence
            ),
            points: steps(c, |p| p.high, tail_high, x_end),
        },
    ];
    if let Some(w) = s.load_at_quantile_mN {
        series.push(Series {
            name: format!("load at {:.0} % yield: {w} mN", 100.0 * s.quantile),
            points: vec![(w, 0.0), (w, 1.0)],
        });
    }
    if let Some(b) = s.load_at_quantile_bound_mN {
        series.push(Series {
            name: format!("its {:.0} % lower bound: {b} mN", 100.0 * s.confidence),
            points: vec![(b, 0.0), (b, 1.0)],
        });
    }
    let plot = LinePlot {
        title: format!(
            "{}: yield at θ = {}°, direction {}° ({} devices)",
            s.pattern, s.theta_deg, s.direction_deg, s.samples
        ),
        x_label: "normal load W (mN)".into(),
        y_label: "yield (fraction of devices superlubric)".into(),
        series,
        hlines: vec![(s.quantile, format!("q = {}", s.quantile))],
        log_y: false,
    };
    line_plot(path, (1000, 700), &plot)
}
