//! `superlube landscape` (not yet implemented).

use super::SceneArgs;
use anyhow::{bail, Result};

/// Options of `superlube landscape`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
}

/// Runs `superlube landscape`.
pub fn run(args: Args) -> Result<()> {
    let _ = args.scene.scene()?;
    bail!("`superlube landscape` is not implemented yet")
}
