//! Command-line interface: one file per subcommand. Each parses its flags into a scene
//! ([`SceneArgs::resolve`], the same resolution for every command) and the parameters of one
//! workflow of [`crate::study`], checks the output paths and the run's size, calls that one
//! workflow function, and writes its files.

mod campaign;
mod checks;
mod contact_args;
mod corrugation;
mod dem_args;
mod design;
mod design_dem_args;
mod equilibrate;
mod export_lammps;
mod figures;
mod friction;
mod friction_args;
mod lammps_check;
mod landscape;
mod merge;
mod model_args;
mod patterns;
mod point_args;
mod prepared;
mod protocol_args;
mod recipe_args;
pub mod renamed;
mod scene_args;
mod screen;
mod slide;
mod slurm;
mod start_args;
mod sweep_args;
mod sweep_commands;
mod sweep_plan;
pub mod tips;
mod tolerance;
mod tolerance_args;
mod value_enums;
mod verdict_args;
mod work_precision;
mod yield_cmd;

pub use crate::study::range::parse_list_or_range;
pub use scene_args::{SceneArgs, SceneOverrides};
pub use sweep_plan::SweepPlan;

use anyhow::{bail, Result};
use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use sweep_commands::SweepCommands;

/// superlube: fast screening and DEM confirmation of patterned superlubric interfaces.
///
/// Units on the command line and in files: µm, nm, mN, µN, GPa, µs, degrees (names say so).
/// Every output file FILE gets a sidecar FILE.meta.json with the resolved scene, the parameters,
/// the command line and a hash of the inputs.
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
    /// Surrogate friction estimate μ_est per θ × α × load (coating + Prandtl–Tomlinson terms on
    /// the quasi-static path, with the slider's inertia where it sticks and slips).
    Friction(friction::Args),
    /// Tolerance map of one design: the superlubric limit load (friction estimate) over
    /// θ ± range × pulling direction ± range, with the fabrication tolerance box (CSV + PNG).
    Tolerance(tolerance::Args),
    /// Yield of one design: the fraction of fabricated devices (misalignment within the
    /// tolerance, fresh substrates) that stay superlubric at a load, the load a fraction q of
    /// them hold with its confidence bound, the DEM deciding where the estimate cannot.
    Yield(yield_cmd::Args),
    /// Design: screen → shortlist → α scan + friction estimate → ranking → DEM confirmation,
    /// with report.md (the best θ and α per pattern and the load up to which it stays
    /// superlubric).
    Design(design::Args),
    /// Regenerate the screening study's figures (PNG + CSV) into `figures/`.
    Figures(figures::Args),
    /// Dynamic DEM equilibration under load (orientation study), compared with the surrogate.
    Equilibrate(equilibrate::Args),
    /// Dynamic DEM sliding simulation: friction force and coefficient.
    Slide(slide::Args),
    /// Write the Tier 3 (DEM) model as a LAMMPS data file and input deck (run it with MPI LAMMPS).
    ExportLammps(export_lammps::Args),
    /// Contacts, P_max and the contacts above P_crit in the contact dump of an exported run.
    LammpsCheck(lammps_check::Args),
    /// Join the shard files of one sweep (`--shard i/n` outputs) into the unsharded output.
    Merge(merge::Args),
    /// Slider pattern candidates of a lattice family over the substrate, classified (lubric,
    /// directional, interlocked): one scene file each plus an index.
    Patterns(patterns::Args),
    /// Write Slurm scripts that run a sweep as an array job (one shard per task) plus a merge.
    Slurm(slurm::Args),
}

/// The sweep commands (those with `--shard`/`--resume`, which `superlube slurm` runs); each has
/// an arm in [`prepare_sweep`].
const SWEEP_COMMANDS: [&str; 4] = ["screen", "landscape", "corrugation", "friction"];

/// The sweep commands as `superlube slurm` sees them.
const SWEEPS: SweepCommands = SweepCommands {
    names: &SWEEP_COMMANDS,
    check: check_sweep,
};

/// Every check of a sweep command line (`screen`, `landscape`, `corrugation`, `friction`), as running it
/// would do them, without running it. `Ok(None)`: not a sweep command.
fn prepare_sweep(command: Command) -> Result<Option<(&'static str, SweepPlan)>> {
    Ok(Some(match command {
        Command::Screen(a) => ("screen", screen::prepare(a)?.plan()),
        Command::Landscape(a) => ("landscape", landscape::prepare(a)?.plan()),
        Command::Corrugation(a) => ("corrugation", corrugation::prepare(a)?.plan()),
        Command::Friction(a) => ("friction", friction::prepare(a)?.plan()),
        _ => return Ok(None),
    }))
}

/// Parses and checks a sweep command line (`superlube <words>`) exactly as running it would.
fn check_sweep(words: &[String]) -> Result<(&'static str, SweepPlan)> {
    let argv = std::iter::once("superlube".to_string()).chain(words.iter().cloned());
    let matches = Cli::command()
        .try_get_matches_from(argv)
        .map_err(checks::clap_error)?;
    let cli = Cli::from_arg_matches(&matches).map_err(|e| anyhow::anyhow!("{e}"))?;
    match prepare_sweep(cli.command)? {
        Some(p) => Ok(p),
        None => bail!(
            "`superlube slurm` runs sweeps: {} (got `{}`)",
            SWEEP_COMMANDS.join(", "),
            words.first().map_or("", String::as_str)
        ),
    }
}

/// Runs the parsed command line.
pub fn run(cli: Cli) -> Result<()> {
    use crate::present::inputs;
    crate::runs::progress::set_note_filter(inputs::to_flags);
    let r = match cli.command {
        Command::Screen(a) => screen::run(a),
        Command::Landscape(a) => landscape::run(a),
        Command::Corrugation(a) => corrugation::run(a),
        Command::Friction(a) => friction::run(a),
        Command::Tolerance(a) => tolerance::run(a),
        Command::Yield(a) => yield_cmd::run(a),
        Command::Design(a) => design::run(a),
        Command::Figures(a) => figures::run(a),
        Command::Equilibrate(a) => equilibrate::run(a),
        Command::Slide(a) => slide::run(a),
        Command::ExportLammps(a) => export_lammps::run(a),
        Command::LammpsCheck(a) => lammps_check::run(a),
        Command::Merge(a) => merge::run(a),
        Command::Patterns(a) => patterns::run(a),
        Command::Slurm(a) => slurm::run(a, &SWEEPS),
    };
    r.map_err(inputs::error_with_flags)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    /// Every workflow input that `src/study` names has a flag of some command.
    #[test]
    fn every_input_names_a_real_flag() {
        let cli = Cli::command();
        for i in crate::study::input::Input::ALL {
            let f = crate::present::inputs::flag(i).trim_start_matches("--");
            assert!(
                cli.get_subcommands()
                    .any(|c| c.get_arguments().any(|a| a.get_long() == Some(f))),
                "{f}"
            );
        }
    }

    /// The CLI's default load list (a clap default string formatted from the study's one
    /// definition) parses back to it exactly.
    #[test]
    fn the_default_loads_are_the_study_loads() {
        let v: Vec<f64> = point_args::STUDY_LOADS
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        assert_eq!(v, crate::study::campaign::STUDY_LOADS_MN.to_vec());
    }

    /// `--help` explains every option: each has a help text, and each physical quantity names
    /// its unit.
    #[test]
    fn every_option_has_help_with_units() {
        let cli = Cli::command();
        for sub in cli.get_subcommands() {
            for arg in sub.get_arguments() {
                let id = arg.get_id().as_str();
                if id == "help" || id == "version" {
                    continue;
                }
                let help = arg
                    .get_long_help()
                    .or(arg.get_help())
                    .map(|h| h.to_string())
                    .unwrap_or_default();
                assert!(
                    help.len() >= 20,
                    "`{} --{id}` has no real help text: `{help}`",
                    sub.get_name()
                );
                let long = arg.get_long().unwrap_or("");
                for (suffix, unit) in [
                    ("-um", "µm"),
                    ("-nm", "nm"),
                    ("-mn", "mN"),
                    ("-us", "µs"),
                    ("-gpa", "GPa"),
                    ("-deg", "degrees"),
                    ("theta", "degrees"),
                    ("alpha", "degrees"),
                ] {
                    if long.ends_with(suffix) {
                        assert!(
                            help.contains(unit),
                            "`{} --{long}`: help does not name the unit {unit}: `{help}`",
                            sub.get_name()
                        );
                    }
                }
                assert!(
                    !help.contains("\"Scene files\""),
                    "`{} --{long}` refers to a README section that does not exist",
                    sub.get_name()
                );
            }
        }
    }
}
