//! The small scene of the fast tests, shared by the integration tests (`tests/common`) and the
//! unit tests under `src/` that parse a command line (`src/cli/design/test_args.rs`).

/// A 15 µm square-tri slider (≈ 80 spheres) on a 60 × 60 µm substrate: the scene's flags.
pub const SMALL_SCENE: [&str; 6] = [
    "--pattern",
    "square-tri",
    "--slider-radius-um",
    "15",
    "--substrate-um",
    "60x60",
];
