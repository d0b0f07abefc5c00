//! The tolerance map's heat map: superlubric limit load over θ × pulling direction, with the
//! nominal design and its tolerance box.

use super::{heat_map, HeatMap};
use crate::study::tolerance::ToleranceRow;
use anyhow::{bail, Result};
use std::path::Path;

/// What a tolerance map colours: the limit itself, or — where the limit is the same at every
/// point — the margin that decides it at that load, so the picture shows how close the box is
/// to the edge.
#[derive(Debug, Clone, PartialEq)]
pub struct MapValues {
    /// One value per row.
    pub values: Vec<f64>,
    /// The colour bar's label.
    pub label: String,
}

/// The values a map of `rows` draws (see [`MapValues`]): `superlubric_to_mN` where it varies
/// (or is 0 everywhere); else at the common limit load W the margin that ends superlubricity
/// above it: P_max/P_crit (the path's P_max at W, `p_crit_gpa`) where most points are limited
/// by the coating (`path`, `placement`), μ_est/μ_sl (`mu_sl`) where most are limited by
/// friction — whichever ratio is higher over the map when none is limited (superlubric at the
/// highest load).
pub fn map_values(rows: &[ToleranceRow], p_crit_gpa: f64, mu_sl: f64) -> MapValues {
    let limit = |r: &ToleranceRow| r.superlubric_to_mN;
    let flat = rows.windows(2).all(|w| limit(&w[0]) == limit(&w[1]));
    let w = rows.first().map_or(0.0, limit);
    let plain = || MapValues {
        values: rows.iter().map(limit).collect(),
        label: "superlubric up to (mN)".into(),
    };
    if !flat || w == 0.0 {
        return plain();
    }
    let p: Option<Vec<f64>> = rows
        .iter()
        .map(|r| r.p_max_at_limit_GPa.map(|x| x / p_crit_gpa))
        .collect();
    let m: Option<Vec<f64>> = rows
        .iter()
        .map(|r| r.mu_est_at_limit.map(|x| x / mu_sl))
        .collect();
    let (Some(p), Some(m)) = (p, m) else {
        return plain();
    };
    let count = |what: &[&str]| {
        rows.iter()
            .filter(|r| what.contains(&r.limited_by.as_str()))
            .count()
    };
    let (coating, friction) = (count(&["path", "placement"]), count(&["friction"]));
    let max = |v: &[f64]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let by_pressure = if coating != friction {
        coating > friction
    } else {
        max(&p) >= max(&m)
    };
    if by_pressure {
        MapValues {
            values: p,
            label: format!("P_max / P_crit at {w} mN (limit {w} mN everywhere)"),
        }
    } else {
        MapValues {
            values: m,
            label: format!("μ_est / {mu_sl} at {w} mN (limit {w} mN everywhere)"),
        }
    }
}

/// Draws `rows` (direction outer, θ inner, `ni` θ per direction) to `path`: tiles coloured by
/// [`map_values`] (the limit, or where it is flat the margin that decides it, against P_crit
/// `thresholds.0` GPa or μ_sl `thresholds.1`), a cross at the nominal (θ, direction) and the box
/// ±`tol` (degrees: θ, direction) around it.
pub fn tolerance_png(
    path: &Path,
    title: &str,
    rows: &[ToleranceRow],
    ni: usize,
    nominal: (f64, f64),
    tol: (f64, f64),
    thresholds: (f64, f64),
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
    let drawn = map_values(rows, thresholds.0, thresholds.1);
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
            value_label: drawn.label,
            n: [ni, nj],
            origin: [first.0, first.1],
            da: [dt, 0.0],
            db: [0.0, dd],
            values: &drawn.values,
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

#[cfg(test)]
mod tests {
    use super::*;

    fn row(limit: f64, mu: f64, p: f64, by: &str) -> ToleranceRow {
        ToleranceRow {
            pattern: "square-tri".into(),
            theta_deg: 0.0,
            direction_deg: 0.0,
            theta_offset_deg: 0.0,
            direction_offset_deg: 0.0,
            alpha_deg: 0.0,
            placement_intact_to_mN: limit,
            superlubric_to_mN: limit,
            confident_to_mN: limit,
            mu_est_at_limit: (limit > 0.0).then_some(mu),
            p_max_at_limit_GPa: (limit > 0.0).then_some(p),
            limited_by: by.into(),
            loads_estimated: 1,
        }
    }

    /// A varying limit is drawn as is; a flat one as the margin that ends it at that load.
    #[test]
    fn a_flat_limit_draws_its_deciding_margin() {
        let v = map_values(
            &[row(1.4, 0.01, 3.0, "path"), row(1.75, 0.01, 3.0, "path")],
            4.0,
            0.02,
        );
        assert_eq!(v.values, vec![1.4, 1.75]);
        assert!(v.label.starts_with("superlubric up to"));
        let rows = [
            row(1.75, 0.01, 3.0, "path"),
            row(1.75, 0.012, 3.6, "placement"),
        ];
        let v = map_values(&rows, 4.0, 0.02);
        assert_eq!(v.values, vec![0.75, 0.9]);
        assert!(
            v.label.starts_with("P_max / P_crit at 1.75 mN"),
            "{}",
            v.label
        );
        let rows = [
            row(1.75, 0.015, 3.0, "friction"),
            row(1.75, 0.018, 3.0, "friction"),
        ];
        let v = map_values(&rows, 4.0, 0.02);
        assert!((v.values[1] - 0.9).abs() < 1e-12);
        assert!(v.label.starts_with("μ_est / 0.02"), "{}", v.label);
        // none superlubric anywhere: the (flat) limit itself
        let v = map_values(&[row(0.0, 0.0, 0.0, "placement")], 4.0, 0.02);
        assert_eq!(v.values, vec![0.0]);
    }
}
