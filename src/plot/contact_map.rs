//! Top view of slider and substrate spheres with the contacts coloured by p0.

use super::heat_map::colour_bar;
use super::{perr, png_atomic, viridis, FONT};
use anyhow::Result;
use plotters::prelude::*;
use std::path::Path;

/// What a contact map shows (plot units: µm, GPa).
pub struct ContactMapData {
    /// Title above the map.
    pub title: String,
    /// Sphere radius (µm).
    pub sphere_radius_um: f64,
    /// Per-sphere radii (µm) of the slider and the substrate spheres when a body has per-site
    /// sizes (drawn each at its own size); empty: every sphere has `sphere_radius_um`.
    pub radii_um: [Vec<f64>; 2],
    /// Slider sphere centres (µm, substrate frame).
    pub slider_um: Vec<[f64; 2]>,
    /// Substrate sphere centres (µm).
    pub substrate_um: Vec<[f64; 2]>,
    /// Contacts: slider-sphere centre (µm), p0 (GPa), coating failed.
    pub contacts: Vec<([f64; 2], f64, bool)>,
    /// Coating strength P_crit (GPa), drawn on the colour bar.
    pub p_crit_gpa: f64,
}

/// Draws the contact map to the PNG `path` (1150×960 px): substrate spheres light grey, slider
/// spheres as blue rings, every contact as a disc coloured by p0 (viridis, colour bar in GPa),
/// contacts whose coating failed (p0 > P_crit) with a thick red ring. The view is the slider's
/// bounding square.
pub fn contact_map(path: &Path, data: &ContactMapData) -> Result<()> {
    let r = data.sphere_radius_um;
    let (cx, cy, half) = view(data);
    let (xr, yr) = ((cx - half)..(cx + half), (cy - half)..(cy + half));
    let plot_px = 820.0;
    let px_per_um = plot_px / (2.0 * half);
    let rad_px = ((r * px_per_um).round() as i32).max(1);
    let (p_lo, p_hi) = pressure_range(data);
    png_atomic(path, (1150, 960), |root| {
        let (left, right) = root.split_horizontally(960);
        let mut chart = ChartBuilder::on(&left)
            .caption(&data.title, (FONT, 22))
            .margin(10)
            .x_label_area_size(55)
            .y_label_area_size(75)
            .build_cartesian_2d(xr.clone(), yr.clone())
            .map_err(perr("contact map"))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x (µm)")
            .y_desc("y (µm)")
            .label_style((FONT, 17))
            .axis_desc_style((FONT, 19))
            .draw()
            .map_err(perr("contact map axes"))?;
        let inside = |p: &[f64; 2]| xr.contains(&p[0]) && yr.contains(&p[1]);
        // each sphere's own radius (px) where the body has per-site sizes
        let px = |body: usize, i: usize| match data.radii_um[body].get(i) {
            Some(r) => ((r * px_per_um).round() as i32).max(1),
            None => rad_px,
        };
        chart
            .draw_series(
                data.substrate_um
                    .iter()
                    .enumerate()
                    .filter(|(_, p)| inside(p))
                    .map(|(i, p)| {
                        Circle::new((p[0], p[1]), px(1, i), RGBColor(215, 215, 215).filled())
                    }),
            )
            .map_err(perr("substrate"))?;
        chart
            .draw_series(data.slider_um.iter().enumerate().map(|(i, p)| {
                Circle::new(
                    (p[0], p[1]),
                    px(0, i),
                    RGBColor(70, 110, 200).stroke_width(1),
                )
            }))
            .map_err(perr("slider"))?
            .label("slider sphere")
            .legend(|(x, y)| Circle::new((x + 10, y), 6, RGBColor(70, 110, 200).stroke_width(1)));
        let span = p_hi - p_lo;
        chart
            .draw_series(data.contacts.iter().map(|c| {
                Circle::new(
                    (c.0[0], c.0[1]),
                    (rad_px - 1).max(2),
                    viridis((c.1 - p_lo) / span).filled(),
                )
            }))
            .map_err(perr("contacts"))?
            .label("contact (colour: p0)")
            .legend(|(x, y)| Circle::new((x + 10, y), 6, viridis(0.6).filled()));
        chart
            .draw_series(
                data.contacts
                    .iter()
                    .filter(|c| c.2)
                    .map(|c| Circle::new((c.0[0], c.0[1]), rad_px + 3, RED.stroke_width(3))),
            )
            .map_err(perr("failed contacts"))?
            .label(format!("coating failed (p0 > {} GPa)", data.p_crit_gpa))
            .legend(|(x, y)| Circle::new((x + 10, y), 7, RED.stroke_width(3)));
        chart
            // legend entry only: a sphere outside the view (near enough that its pixel
            // coordinates stay far inside i32)
            .draw_series(std::iter::once(Circle::new(
                (cx - 3.0 * half, cy - 3.0 * half),
                1,
                RGBColor(215, 215, 215).filled(),
            )))
            .map_err(perr("legend"))?
            .label("substrate sphere")
            .legend(|(x, y)| Circle::new((x + 10, y), 6, RGBColor(215, 215, 215).filled()));
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font((FONT, 16))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(perr("legend"))?;
        colour_bar(&right, p_lo, p_hi, "contact pressure p0 (GPa)", 50)?;
        Ok(())
    })
}

/// The view: the centre (µm) and half-width (µm) of the slider's bounding square, with a
/// sphere diameter of margin.
fn view(data: &ContactMapData) -> (f64, f64, f64) {
    let r = data.sphere_radius_um;
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in &data.slider_um {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if !lo[0].is_finite() {
        lo = [-1.0, -1.0];
        hi = [1.0, 1.0];
    }
    let cx = 0.5 * (lo[0] + hi[0]);
    let cy = 0.5 * (lo[1] + hi[1]);
    let half = 0.5 * (hi[0] - lo[0]).max(hi[1] - lo[1]) + 2.0 * r;
    (cx, cy, half)
}

/// The colour bar's range of contact pressures p0 (GPa): the contacts' (at least 0.1 GPa wide),
/// 0..1 without contacts.
fn pressure_range(data: &ContactMapData) -> (f64, f64) {
    let (p_lo, p_hi) = data
        .contacts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
            (a.min(c.1), b.max(c.1))
        });
    if p_lo.is_finite() {
        (p_lo, if p_hi > p_lo { p_hi } else { p_lo + 0.1 })
    } else {
        (0.0, 1.0)
    }
}
