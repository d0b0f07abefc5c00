//! The friction estimate's path flags, shared by `superlube friction` and `superlube design`.

use super::checks;
use anyhow::{bail, Result};
use surrogate::friction::FrictionParams;
use surrogate::units::um_to_m;

/// Path and spring knobs of the surrogate friction estimate (µm, N/m).
#[derive(clap::Args, Debug)]
pub struct FrictionKnobArgs {
    /// Friction estimate: path length in µm along a pulling direction that is not a substrate
    /// lattice direction (quasi-periodic landscape); lattice directions use one exact period
    /// (≤ --max-period-um).
    #[arg(
        long = "length-um",
        value_name = "UM",
        default_value_t = 12.0,
        allow_hyphen_values = true
    )]
    pub length_um: f64,
    /// Friction estimate: longest substrate lattice period in µm used as an exact periodic path.
    #[arg(
        long = "max-period-um",
        value_name = "UM",
        default_value_t = 12.0,
        allow_hyphen_values = true
    )]
    pub max_period_um: f64,
    /// Friction estimate: largest sample spacing along the path in µm.
    #[arg(
        long = "step-um",
        value_name = "UM",
        default_value_t = 0.05,
        allow_hyphen_values = true
    )]
    pub step_um: f64,
    /// Friction estimate: start of a quasi-periodic path in µm skipped by the
    /// Prandtl–Tomlinson term (the spring loading from rest); < --length-um.
    #[arg(
        long = "transient-um",
        value_name = "UM",
        default_value_t = 3.0,
        allow_hyphen_values = true
    )]
    pub transient_um: f64,
    /// Friction estimate: pulling spring stiffness K0 in N/m (study: 50; DEM runs keep 50).
    #[arg(
        long = "k0-n-m",
        value_name = "N_M",
        default_value_t = 50.0,
        allow_hyphen_values = true
    )]
    pub k0_n_m: f64,
    /// Friction estimate: how far in µm across the pull the path's start is searched. Only K0
    /// holds the DEM's slider across the pull, so where the placement is a crest of the
    /// landscape and the pull pushes the slider off it (not on a mirror line of the scene, not
    /// where the coating has failed at the placement), it drifts into the groove beside it; the
    /// path then starts at the lowest V + ½K0y² on that side (column
    /// transverse_offset_um). 0 keeps the path through the placement.
    #[arg(
        long = "transverse-um",
        value_name = "UM",
        default_value_t = 1.5,
        allow_hyphen_values = true
    )]
    pub transverse_um: f64,
}

impl FrictionKnobArgs {
    /// The estimate's knobs in SI (errors name the flag).
    pub fn params(&self) -> Result<FrictionParams> {
        let um = |v: f64, flag: &str| checks::positive(v, flag).map(um_to_m);
        let k = FrictionParams {
            length: um(self.length_um, "--length-um")?,
            max_period: um(self.max_period_um, "--max-period-um")?,
            step: um(self.step_um, "--step-um")?,
            transient: um_to_m(checks::non_negative(self.transient_um, "--transient-um")?),
            k0: checks::positive(self.k0_n_m, "--k0-n-m")?,
            transverse: um_to_m(checks::non_negative(self.transverse_um, "--transverse-um")?),
            ..FrictionParams::default()
        };
        if k.step > k.length.min(k.max_period) {
            bail!(
                "`--step-um`: {} must not exceed --length-um or --max-period-um",
                self.step_um
            );
        }
        if k.transient >= k.length {
            bail!(
                "`--transient-um`: {} must be shorter than --length-um {}",
                self.transient_um,
                self.length_um
            );
        }
        k.validate()?;
        Ok(k)
    }
}
