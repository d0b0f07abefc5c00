//! `superlube figures` (not yet implemented).

use super::SceneArgs;
use anyhow::{bail, Result};

/// Options of `superlube figures`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
}

/// Runs `superlube figures`.
pub fn run(args: Args) -> Result<()> {
    let _ = args.scene.scene()?;
    bail!("`superlube figures` is not implemented yet")
}
