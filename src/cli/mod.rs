//! Command-line interface: one file per subcommand, sharing [`SceneArgs`] and the range parser.

mod corrugation;
mod dem_args;
mod equilibrate;
mod export_lammps;
mod figures;
mod lammps_check;
mod landscape;
mod range;
mod scene_args;
mod screen;
mod slide;

pub use range::parse_list_or_range;
pub use scene_args::SceneArgs;

use anyhow::Result;
use clap::{Parser, Subcommand};

/// superlube: fast screening and DEM confirmation of patterned superlubric interfaces.
///
/// Units on the command line and in files: µm, mN, GPa, µs, degrees (names say so).
#[derive(Parser, Debug)]
#[command(name = "superlube", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Orientation × load screen: contacts, P_max, height, coating failure (quasi-static).
    Screen(screen::Args),
    /// Height landscape Δz over the substrate repeat cell (quasi-static).
    Landscape(landscape::Args),
    /// Corrugation and static-friction barrier along pulling directions α (quasi-static).
    Corrugation(corrugation::Args),
    /// Regenerate the screening study's figures into `figures/`.
    Figures(figures::Args),
    /// Dynamic DEM equilibration under load (orientation study), compared with the surrogate.
    Equilibrate(equilibrate::Args),
    /// Dynamic DEM sliding simulation: friction force and coefficient.
    Slide(slide::Args),
    /// Write the Tier-2 model as a LAMMPS data file and input deck (run it with MPI LAMMPS).
    ExportLammps(export_lammps::Args),
    /// Contacts, P_max and the contacts above P_crit in the contact dump of an exported run.
    LammpsCheck(lammps_check::Args),
}

/// Runs the parsed command line.
pub fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Command::Screen(a) => screen::run(a),
        Command::Landscape(a) => landscape::run(a),
        Command::Corrugation(a) => corrugation::run(a),
        Command::Figures(a) => figures::run(a),
        Command::Equilibrate(a) => equilibrate::run(a),
        Command::Slide(a) => slide::run(a),
        Command::ExportLammps(a) => export_lammps::run(a),
        Command::LammpsCheck(a) => lammps_check::run(a),
    }
}
