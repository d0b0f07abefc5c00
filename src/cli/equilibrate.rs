//! `superlube equilibrate`: flags → [`crate::study::equilibrate::equilibrate`] → time series,
//! summary, sidecars.

use super::dem_args::DemArgs;
use super::protocol_args::ProtocolArgs;
use crate::runs::progress::Reporter;
use crate::study::equilibrate::equilibrate;
use anyhow::Result;

/// Options of `superlube equilibrate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    dem: DemArgs,
}

/// Runs `superlube equilibrate`.
pub fn run(a: Args) -> Result<()> {
    let (sc, params) = a.dem.setup(&ProtocolArgs::AT_REST)?;
    let rep = Reporter::stderr();
    sc.log(&rep);
    let outs = a.dem.outputs("equilibrate", &sc, &params);
    let (out, report) = equilibrate(&sc.scene, &params, &rep)?;
    a.dem.write(outs, out, report.as_ref())
}
