//! Helpers shared by the command-line integration tests.
#![allow(dead_code)] // each test binary uses a subset

pub mod lammps;
mod small_scene;

pub use small_scene::SMALL_SCENE;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `superlube` binary under test.
pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_superlube"))
}

/// Runs `superlube <command>` on the small scene: [`SMALL_SCENE`], then each of `flags` in
/// order, then `--out out`.
pub fn run_small(command: &str, flags: &[&[&str]], out: &Path) -> Output {
    bin()
        .arg(command)
        .args(SMALL_SCENE)
        .args(flags.concat())
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

/// A fresh scratch directory for one test (per process, so parallel test binaries do not clash).
pub fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("superlube-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Asserts that a finished command succeeded, showing its stderr otherwise.
pub fn assert_ok(out: &Output) {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Runs `superlube args…` and asserts that it fails with a message naming `field`.
pub fn fails_naming(args: &[&str], field: &str) {
    let out = bin().args(args).output().unwrap();
    assert!(!out.status.success(), "{args:?} should fail");
    assert_ne!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(field),
        "{args:?}: `{err}` does not name {field}"
    );
}
