//! The tolerance map's heat map: superlubric limit load over θ × pulling direction, with the
//! nominal design and its tolerance box.

use super::{heat_map, HeatMap};
use crate::study::tolerance::ToleranceRow;
use anyhow::{bail, Result};
use std::path::Path;

/// Draws `rows` (direction outer, θ inner, `ni` θ per direction) to `path`: tiles coloured by
/// `superlubric_to_mN`, a cross at the nominal (θ, direction) and the box ±`tol` (degrees: θ,
/// direction) around it.
pub fn tolerance_png(
    path: &Path,
    title: &str,
    rows: &[ToleranceRow],
    ni: usize,
    nominal: (f64, f64),
    tol: (f64, f64),
) -> Result<()> {
    if ni == 0 || rows.is_empty() || !rows.len().is_multiple_of(ni) {
        bail!(
            "a tolerance map needs a full grid ({} points, {ni} per row)",
            rows.len()
        );
    }
    let nj = rows.len() / ni;
    let step = |a: f64, b: f64, n: usize| {
        if n > 1 {
            (b - a) / (n - 1) as f64
        } else {
            1e-3
        }
    };
    let dt = step(rows[0].theta_deg, rows[ni - 1].theta_deg, ni);
    let dd = step(
        rows[0].direction_deg,
        rows[rows.len() - 1].direction_deg,
        nj,
    );
    // plot units: offsets (degrees) from the nominal
    let (nt, nd) = nominal;
    let values: Vec<f64> = rows.iter().map(|r| r.superlubric_to_mN).collect();
    let rel = |t: f64, d: f64| (t - nt, d - nd);
    let first = rel(rows[0].theta_deg, rows[0].direction_deg);
    let outline = vec![
        rel(nt - tol.0, nd - tol.1),
        rel(nt + tol.0, nd - tol.1),
        rel(nt + tol.0, nd + tol.1),
        rel(nt - tol.0, nd + tol.1),
    ];
    heat_map(
        path,
        &HeatMap {
            title: title.to_string(),
            x_label: format!("θ − {}° (deg)", fmt(nt)),
            y_label: format!(
                "pull direction − {}° (deg, from the substrate x axis)",
                fmt(nd)
            ),
            value_label: "superlubric up to (mN)".into(),
            n: [ni, nj],
            origin: [first.0, first.1],
            da: [dt, 0.0],
            db: [0.0, dd],
            values: &values,
            free_aspect: true,
            outlines: if tol.0 > 0.0 || tol.1 > 0.0 {
                vec![outline]
            } else {
                Vec::new()
            },
            marks: vec![rel(nt, nd)],
        },
    )
}

/// A degree value with at most 4 decimals (`82.5292`, `7.3`).
fn fmt(v: f64) -> String {
    format!("{}", (v * 1e4).round() / 1e4)
}
