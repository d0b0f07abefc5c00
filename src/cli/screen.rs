//! `superlube screen` (not yet implemented).

use super::SceneArgs;
use anyhow::{bail, Result};

/// Options of `superlube screen`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
}

/// Runs `superlube screen`.
pub fn run(args: Args) -> Result<()> {
    let _ = args.scene.scene()?;
    bail!("`superlube screen` is not implemented yet")
}
