//! `superlube equilibrate` (not yet implemented).

use super::SceneArgs;
use anyhow::{bail, Result};

/// Options of `superlube equilibrate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
}

/// Runs `superlube equilibrate`.
pub fn run(args: Args) -> Result<()> {
    let _ = args.scene.scene()?;
    bail!("`superlube equilibrate` is not implemented yet")
}
