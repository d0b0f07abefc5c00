//! `superlube corrugation` (not yet implemented).

use super::SceneArgs;
use anyhow::{bail, Result};

/// Options of `superlube corrugation`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
}

/// Runs `superlube corrugation`.
pub fn run(args: Args) -> Result<()> {
    let _ = args.scene.scene()?;
    bail!("`superlube corrugation` is not implemented yet")
}
