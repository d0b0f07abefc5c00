//! [`Sample`]: one row of the time series (user units).

use serde::{Deserialize, Serialize};

/// One time-series row. Serialised (CSV) columns, in order:
/// `t_us,support_x_um,spring_force_mN,z_um,contacts,p_max_GPa,failed_contacts,p_max_peak_GPa`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct Sample {
    /// Simulated time since the start of the run (µs).
    pub t_us: f64,
    /// Support travel along α since the pulling spring was attached (µm).
    pub support_x_um: f64,
    /// Pulling-spring force along α (mN), `K0·((S − X)·α̂ − L0)`.
    #[serde(rename = "spring_force_mN")]
    pub spring_force_mn: f64,
    /// Mean height of the slider sphere centres above the substrate plane (µm).
    pub z_um: f64,
    /// Touching slider–substrate pairs.
    pub contacts: usize,
    /// Largest p0 over the contacts (GPa).
    #[serde(rename = "p_max_GPa")]
    pub p_max_gpa: f64,
    /// Contacts whose coating has failed now (p0 > P_crit).
    pub failed_contacts: usize,
    /// Largest p0 (GPa) at any step since the previous sample, this one included (≥
    /// `p_max_GPa`): the DEM's step is ~200× shorter than the default sampling interval, and
    /// the slider's vertical ringing during fast slips raises p0 for a few steps at a time.
    #[serde(rename = "p_max_peak_GPa")]
    pub p_max_peak_gpa: f64,
    /// Control-layer travel along α since the spring was attached (µm) (not in the CSV).
    #[serde(skip)]
    pub slider_x_um: f64,
    /// Σ vertical contact force on the slider (mN) (not in the CSV).
    #[serde(skip)]
    pub contact_fz_mn: f64,
}

impl Sample {
    /// Converts [`crate::integrator::Observables`] to user units.
    pub fn from_obs(o: &crate::integrator::Observables) -> Sample {
        use surrogate::units::*;
        Sample {
            t_us: s_to_us(o.t),
            support_x_um: m_to_um(o.support_travel),
            spring_force_mn: n_to_mn(o.spring_force),
            z_um: m_to_um(o.z),
            contacts: o.contacts,
            p_max_gpa: pa_to_gpa(o.p_max),
            failed_contacts: o.failed,
            p_max_peak_gpa: pa_to_gpa(o.p_max_peak),
            slider_x_um: m_to_um(o.slider_travel),
            contact_fz_mn: n_to_mn(o.contact_fz),
        }
    }
}
