//! Test helper of the `design` unit tests: a command line parsed into [`Args`] as
//! `superlube design` parses it, and the small scene of the fast tests.

use super::Args;
use clap::Parser;
use std::path::Path;

#[path = "../../../tests/common/small_scene.rs"]
mod small_scene;

pub(super) use small_scene::SMALL_SCENE;

#[derive(Parser)]
struct Cli {
    #[command(flatten)]
    a: Args,
}

/// The [`Args`] of `superlube design`, each of `flags` in order, `--out-dir out`.
pub(super) fn design_args(flags: &[&[&str]], out: &Path) -> Args {
    let mut v: Vec<String> = ["design"]
        .iter()
        .chain(flags.concat().iter())
        .map(|s| s.to_string())
        .collect();
    v.push("--out-dir".into());
    v.push(out.display().to_string());
    Cli::try_parse_from(v).unwrap().a
}
