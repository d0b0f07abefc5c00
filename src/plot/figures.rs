//! The study's figures drawn from the workflows' data: orientation sweep, contact map, Δz
//! landscape, corrugation versus α. Used by `figures` and by the map commands' `--plot` /
//! `--contact-map`.

use super::{contact_map, heat_map, stacked_line_plots, ContactMapData, HeatMap, LinePlot, Series};
use crate::study::figures::fmt_num;
use crate::study::landscape::LandscapeStats;
use crate::study::rows::{CorrugationRow, ScreenRow};
use anyhow::Result;
use std::path::Path;
use surrogate::solver::Equilibrium;
use surrogate::units::{m_to_nm, m_to_um, mn_to_un, n_to_mn, pa_to_gpa, rad_to_deg};
use surrogate::Scene;

/// Two stacked panels: contacts (log) and P_max versus θ, one series per load, P_crit dashed.
pub fn sweep_png(path: &Path, scene: &Scene, rows: &[ScreenRow]) -> Result<()> {
    let pattern = &scene.pattern;
    let mut loads: Vec<f64> = Vec::new();
    for r in rows {
        if !loads.contains(&r.load_mN) {
            loads.push(r.load_mN);
        }
    }
    let series = |f: &dyn Fn(&ScreenRow) -> Option<f64>| -> Vec<Series> {
        loads
            .iter()
            .map(|&w| Series {
                name: format!("W = {} mN", fmt_num(w)),
                points: rows
                    .iter()
                    .filter(|r| r.load_mN == w)
                    .filter_map(|r| f(r).map(|v| (r.theta_deg, v)))
                    .collect(),
            })
            .collect()
    };
    let contacts = LinePlot {
        title: format!("{pattern}: contact number versus orientation θ"),
        x_label: "slider rotation θ (°)".into(),
        y_label: "contacts (log scale)".into(),
        series: series(&|r| r.contacts.map(|c| c as f64)),
        hlines: vec![],
        log_y: true,
    };
    let pmax = LinePlot {
        title: format!("{pattern}: maximum Hertz pressure versus θ"),
        x_label: "slider rotation θ (°)".into(),
        y_label: "P_max (GPa)".into(),
        series: series(&|r| r.p_max_GPa),
        hlines: vec![(
            pa_to_gpa(scene.coating.p_crit),
            "P_crit (coating fails above)".into(),
        )],
        log_y: false,
    };
    stacked_line_plots(path, (1100, 1150), &[&contacts, &pmax])
}

/// Top view of `scene` at its θ with the contacts of `eq` (load `load`, N) coloured by p0.
pub fn contact_map_png(path: &Path, scene: &Scene, load: f64, eq: &Equilibrium) -> Result<()> {
    let theta = scene.slider.theta;
    let slider = scene.slider_sites_at(theta, [0.0, 0.0]);
    let um = |p: [f64; 2]| [m_to_um(p[0]), m_to_um(p[1])];
    let data = ContactMapData {
        title: format!(
            "{}, θ = {}°, W = {} mN: {} contacts, P_max = {:.2} GPa, {} failed",
            scene.pattern,
            fmt_num(rad_to_deg(theta)),
            fmt_num(n_to_mn(load)),
            eq.contact_count(),
            pa_to_gpa(eq.p_max),
            eq.failed_count()
        ),
        sphere_radius_um: m_to_um(scene.sphere_radius),
        radii_um: [scene.slider_radii(), scene.substrate_radii()]
            .map(|r| r.unwrap_or_default().iter().map(|&v| m_to_um(v)).collect()),
        slider_um: slider.iter().map(|&p| um(p)).collect(),
        substrate_um: scene
            .substrate_spheres()
            .iter()
            .map(|p| um([p[0], p[1]]))
            .collect(),
        contacts: eq
            .contacts
            .iter()
            .map(|c| (um([c.point[0], c.point[1]]), pa_to_gpa(c.p0), c.failed))
            .collect(),
        p_crit_gpa: pa_to_gpa(scene.coating.p_crit),
    };
    contact_map(path, &data)
}

/// Heat map of Δz (nm, `dz_nm` row-major, x fastest) over the cell of `stats`, axes in µm.
pub fn landscape_png(
    path: &Path,
    scene: &Scene,
    load: f64,
    stats: &LandscapeStats,
    dz_nm: &[f64],
) -> Result<()> {
    let d = (stats.n - 1) as f64;
    let cell = &stats.cell;
    let title = format!(
        "Δz landscape, {}, θ = {}°, W = {} mN (range {:.3} nm)",
        scene.pattern,
        fmt_num(rad_to_deg(scene.slider.theta)),
        fmt_num(n_to_mn(load)),
        m_to_nm(stats.range)
    );
    heat_map(
        path,
        &HeatMap {
            title,
            x_label: "slider shift x (µm)".into(),
            y_label: "slider shift y (µm)".into(),
            value_label: "Δz = z − min z (nm)".into(),
            n: [stats.n, stats.n],
            origin: [0.0, 0.0],
            da: [m_to_um(cell.a[0]) / d, m_to_um(cell.a[1]) / d],
            db: [m_to_um(cell.b[0]) / d, m_to_um(cell.b[1]) / d],
            values: dz_nm,
            free_aspect: false,
            outlines: Vec::new(),
            marks: Vec::new(),
        },
    )
}

/// Corrugation (nm) versus α of one (θ, W): a single line plot.
pub fn corrugation_png(
    path: &Path,
    scene: &Scene,
    rows: &[CorrugationRow],
    distance_um: f64,
) -> Result<()> {
    let (theta, load) = rows
        .first()
        .map_or((0.0, 0.0), |r| (r.theta_deg, r.load_mn));
    super::line_plot(
        path,
        (1000, 650),
        &LinePlot {
            title: format!(
                "Corrugation, {}, θ = {}°, W = {} mN, {} µm paths",
                scene.pattern,
                fmt_num(theta),
                fmt_num(load),
                fmt_num(distance_um)
            ),
            x_label: "pulling angle α from the contact line (°)".into(),
            y_label: "corrugation, peak-to-peak z (nm)".into(),
            series: vec![Series {
                name: "corrugation".into(),
                points: rows
                    .iter()
                    .map(|r| (r.alpha_deg, r.corrugation_nm))
                    .collect(),
            }],
            hlines: vec![],
            log_y: false,
        },
    )
}

/// The corrugation figure: corrugation (top) and static-friction barrier in µN (bottom) versus
/// α, one series per (θ, W) in the order of the rows.
pub fn corrugation_figure_png(path: &Path, rows: &[CorrugationRow], distance: f64) -> Result<()> {
    let mut corr: Vec<Series> = Vec::new();
    let mut force: Vec<Series> = Vec::new();
    let mut key = None;
    for r in rows {
        if key != Some((r.theta_deg, r.load_mn)) {
            key = Some((r.theta_deg, r.load_mn));
            let name = format!(
                "θ = {}°, W = {} mN",
                fmt_num(r.theta_deg),
                fmt_num(r.load_mn)
            );
            corr.push(Series {
                name: name.clone(),
                points: vec![],
            });
            force.push(Series {
                name,
                points: vec![],
            });
        }
        let (c, f) = (corr.last_mut(), force.last_mut());
        if let (Some(c), Some(f)) = (c, f) {
            c.points.push((r.alpha_deg, r.corrugation_nm));
            f.points
                .push((r.alpha_deg, mn_to_un(r.max_lateral_force_mn)));
        }
    }
    let c = LinePlot {
        title: format!(
            "square-tri: corrugation along pulling angle α ({} µm paths)",
            fmt_num(m_to_um(distance))
        ),
        x_label: "pulling angle α from the contact line (°)".into(),
        y_label: "corrugation, peak-to-peak z (nm)".into(),
        series: corr,
        hlines: vec![],
        log_y: false,
    };
    let f = LinePlot {
        title: "square-tri: static-friction barrier along α".into(),
        x_label: "pulling angle α from the contact line (°)".into(),
        y_label: "max lateral force (µN)".into(),
        series: force,
        hlines: vec![],
        log_y: false,
    };
    stacked_line_plots(path, (1100, 1150), &[&c, &f])
}
