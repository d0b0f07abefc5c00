//! The rows of a screen: [`ScreenRow`] (one θ × W configuration) and [`ContactRow`] (one
//! contact of an equilibrium).

use super::format::label;
use serde::{Deserialize, Serialize};
use surrogate::solver::{ContactInfo, Equilibrium, Model};
use surrogate::units::{m_to_nm, m_to_um, n_to_mn, pa_to_gpa, rad_to_deg, rad_to_urad, UN};

/// One configuration (θ, W) of an orientation × load screen. The leading seven columns are the
/// screening answer; units in the names.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct ScreenRow {
    /// Pattern pair name (`slider-substrate`; `*` = a preset whose lattices a scene file changed,
    /// `custom` = lattices from a scene file without preset).
    pub pattern: String,
    /// Slider orientation θ (degrees).
    pub theta_deg: f64,
    /// Normal load W (mN).
    pub load_mN: f64,
    /// Contact number (pairs with overlap > 0).
    pub contacts: Option<usize>,
    /// Largest Hertz pressure p0 (GPa).
    pub p_max_GPa: Option<f64>,
    /// Slider sphere-centre plane height at the disc centre (µm), 3 µm at first on-top touch.
    pub z_um: Option<f64>,
    /// Whether P_max exceeds P_crit.
    pub coating_failed: Option<bool>,
    /// Number of contacts with p0 > P_crit.
    pub failed_contacts: Option<usize>,
    /// Tilt about x (µrad).
    pub tilt_x_urad: Option<f64>,
    /// Tilt about y (µrad).
    pub tilt_y_urad: Option<f64>,
    /// Model used.
    pub model: String,
    /// |ΣF_z − W| / W.
    pub residual_rel: Option<f64>,
    /// Solver iterations.
    pub iterations: Option<usize>,
    /// Empty, or why this configuration has no equilibrium (the other columns are then empty).
    pub error: String,
}

impl ScreenRow {
    /// The row of configuration (θ rad, W N) from the solver's answer; `model` is the model
    /// asked for (reported when the solve failed).
    pub fn new(
        pattern: &str,
        theta: f64,
        load: f64,
        r: &Result<Equilibrium, surrogate::SceneError>,
        model: Model,
    ) -> ScreenRow {
        let mut row = ScreenRow {
            pattern: pattern.to_string(),
            theta_deg: label(rad_to_deg(theta)),
            load_mN: label(n_to_mn(load)),
            contacts: None,
            p_max_GPa: None,
            z_um: None,
            coating_failed: None,
            failed_contacts: None,
            tilt_x_urad: None,
            tilt_y_urad: None,
            model: model.name().to_string(),
            residual_rel: None,
            iterations: None,
            error: String::new(),
        };
        match r {
            Ok(e) => {
                row.contacts = Some(e.contact_count());
                row.p_max_GPa = Some(pa_to_gpa(e.p_max));
                row.z_um = Some(m_to_um(e.z));
                row.coating_failed = Some(e.coating_failed());
                row.failed_contacts = Some(e.failed_count());
                row.tilt_x_urad = Some(rad_to_urad(e.tilt[0]));
                row.tilt_y_urad = Some(rad_to_urad(e.tilt[1]));
                row.model = e.model.name().to_string();
                row.residual_rel = Some(e.residual_rel());
                row.iterations = Some(e.iterations);
            }
            Err(err) => row.error = err.to_string(),
        }
        row
    }
}

/// One slider–substrate contact of an equilibrium (the per-contact list behind contact maps).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[allow(non_snake_case)]
pub struct ContactRow {
    /// Index of the slider sphere (order of `Scene::slider_sites_local`).
    pub slider_index: u32,
    /// Index of the substrate sphere (order of `Scene::substrate_spheres`).
    pub substrate_index: u32,
    /// Contact point x (µm, substrate frame).
    pub x_um: f64,
    /// Contact point y (µm).
    pub y_um: f64,
    /// Contact point z (µm).
    pub z_um: f64,
    /// Overlap δ (nm).
    pub overlap_nm: f64,
    /// Normal force F_n (µN).
    pub force_uN: f64,
    /// Hertz pressure p0 (GPa).
    pub p0_GPa: f64,
    /// Whether p0 > P_crit (coating failed at this contact).
    pub failed: bool,
}

impl ContactRow {
    /// The row of one contact.
    pub fn new(c: &ContactInfo) -> ContactRow {
        ContactRow {
            slider_index: c.slider,
            substrate_index: c.substrate,
            x_um: m_to_um(c.point[0]),
            y_um: m_to_um(c.point[1]),
            z_um: m_to_um(c.point[2]),
            overlap_nm: m_to_nm(c.overlap),
            force_uN: c.force_n / UN,
            p0_GPa: pa_to_gpa(c.p0),
            failed: c.failed,
        }
    }

    /// Every contact of an equilibrium, in the solver's order.
    pub fn all(eq: &Equilibrium) -> Vec<ContactRow> {
        eq.contacts.iter().map(ContactRow::new).collect()
    }
}
