//! `superlube`: screen, map and confirm patterned superlubric interfaces.
//!
//! Data flows one way: scene (crate `surrogate::scene`) → contacts → load sharing
//! (`surrogate::solver`) or dynamics (crate `dem`) → results → reports and figures (this crate).

mod cli;
mod output;
mod plot;

use clap::Parser;

fn main() {
    let cli = cli::Cli::parse();
    if let Err(e) = cli::run(cli) {
        eprintln!("error: {e:#}");
        std::process::exit(2);
    }
}
