//! `superlube slide` (not yet implemented).

use super::SceneArgs;
use anyhow::{bail, Result};

/// Options of `superlube slide`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
}

/// Runs `superlube slide`.
pub fn run(args: Args) -> Result<()> {
    let _ = args.scene.scene()?;
    bail!("`superlube slide` is not implemented yet")
}
