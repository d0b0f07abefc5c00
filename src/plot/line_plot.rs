//! Line plots with legends and horizontal reference lines (the study's figures), drawn by the
//! chart engine ([`super::chart`]) in its [`Look::Figures`] framing.

use super::chart::{draw, Chart, Colour, Curve, Look, Style};
use super::png_atomic;
use anyhow::Result;
use std::path::Path;

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
    png_atomic(path, size, |root| draw(&root, &plot.chart(), Look::Figures))
}

/// Draws `panels` stacked top to bottom, equal heights, into the PNG `path` of `size` pixels.
pub fn stacked_line_plots(path: &Path, size: (u32, u32), panels: &[&LinePlot]) -> Result<()> {
    png_atomic(path, size, |root| {
        let areas = root.split_evenly((panels.len(), 1));
        for (area, plot) in areas.iter().zip(panels) {
            draw(area, &plot.chart(), Look::Figures)?;
        }
        Ok(())
    })
}

impl LinePlot {
    /// The chart of this plot: each series a line in the palette's colour of its rank.
    fn chart(&self) -> Chart {
        Chart {
            title: self.title.clone(),
            x_label: self.x_label.clone(),
            y_label: self.y_label.clone(),
            curves: self
                .series
                .iter()
                .enumerate()
                .map(|(k, s)| Curve {
                    name: s.name.clone(),
                    points: s.points.clone(),
                    colour: Colour::Palette(k),
                    style: Style::Line,
                })
                .collect(),
            hlines: self.hlines.clone(),
            log_y: self.log_y,
        }
    }
}
