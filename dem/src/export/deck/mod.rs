//! The LAMMPS input deck (`in.superlube.lmp`) of the exported model.
//!
//! Every number is computed in Rust from the same [`crate::SimParams`] and scene the Rust tier
//! uses and written in LAMMPS `units micro` (see [`super::micro`]); the deck has no lattice or
//! model logic of its own. Each part of [`crate::SimParams`] has its section, in its own file
//! (`contacts.rs`, `ties.rs`, `numerics.rs`, `phases.rs`; the control layer in `control.rs`).
//! Structure: variables (`nsteps`, file names, `extra`) → data →
//! groups → contact law → bonds → fixes (integration, tethers, damping, load, mount, rigid
//! control layer last) → observables and outputs → the protocol's phases, each a `run` whose
//! length is capped by `nsteps` (so `-var nsteps 0` sets everything up and stops).

macro_rules! w {
    ($s:expr, $($t:tt)*) => {{ let _ = writeln!($s, $($t)*); }};
}

mod contacts;
mod control;
mod drive;
mod fixes;
mod groups;
mod inputs;
mod number;
mod numerics;
mod observables;
mod phases;
mod preamble;
mod render;
mod ties;

pub use contacts::{DeckContact, DeckPair};
pub use control::{DeckControl, DeckMount};
pub use drive::DeckDrive;
pub use inputs::DeckInputs;
pub use numerics::{DeckNumerics, DeckViscous};
pub use render::render;
pub use ties::DeckTies;

/// Names of the dump's columns (`dump local`): pair distance, then the two atom IDs.
pub const DUMP_COLUMNS: [&str; 3] = ["c_cpl", "c_cpa[1]", "c_cpa[2]"];

/// Columns of the deck's time series CSV.
pub const TIMESERIES_HEADER: &str =
    "t_us,support_x_um,spring_force_mN,z_um,contacts,p_max_GPa,tilt_x_urad,tilt_y_urad";

/// File names the export writes and the deck reads/writes.
pub mod files {
    /// The data file.
    pub const DATA: &str = "scene.data";
    /// The input deck.
    pub const DECK: &str = "in.superlube.lmp";
    /// The README of the export directory.
    pub const README: &str = "README.md";
    /// The metadata `superlube lammps-check` reads.
    pub const META: &str = "export.json";
    /// The time series the deck writes.
    pub const TIMESERIES: &str = "timeseries.csv";
    /// The contact dump the deck writes.
    pub const DUMP: &str = "contacts.dump";
}
