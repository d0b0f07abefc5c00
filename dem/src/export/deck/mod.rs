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

use super::meta::Steps;

macro_rules! w {
    ($s:expr, $($t:tt)*) => {{ let _ = writeln!($s, $($t)*); }};
}

mod contacts;
mod control;
mod fixes;
mod groups;
mod numerics;
mod observables;
mod phases;
mod preamble;
mod ties;

pub use contacts::{DeckContact, DeckPair};
pub use control::{DeckControl, DeckMount};
pub use numerics::{DeckNumerics, DeckViscous};
pub use phases::DeckDrive;
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

/// Everything the deck needs, in LAMMPS micro units (µm, µs, pg, nN, 10³ Pa, nN/µm), one
/// field per part of the model.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckInputs {
    /// Header lines (without `#`), e.g. the scene and the command.
    pub header: Vec<String>,
    /// Step counts.
    pub steps: Steps,
    /// Time step, skin, viscous bath ([`crate::NumericsParams`]).
    pub numerics: DeckNumerics,
    /// The contact law ([`crate::ContactParams`] and the materials).
    pub contact: DeckContact,
    /// The slider ties and substrate tethers ([`crate::MountParams`]).
    pub ties: DeckTies,
    /// The control layer: the scene's mount, halves, θ.
    pub control: DeckControl,
    /// Load and drive ([`crate::ProtocolParams`]).
    pub drive: DeckDrive,
    /// Per-site sphere sizes (then `contact_distance` is the largest radius sum, for the
    /// communication cutoff); `None`: one size per body.
    pub sizes: Option<super::deck_sizes::DeckSizes>,
}

/// A number as LAMMPS reads it: the shortest text that round-trips (`1e-5`, `0.1`, `1e8`).
struct N(f64);

impl std::fmt::Display for N {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let t = format!("{:?}", self.0);
        f.write_str(t.strip_suffix(".0").unwrap_or(&t))
    }
}

fn on(b: bool) -> &'static str {
    if b {
        "on"
    } else {
        "off"
    }
}

/// Renders the deck: its sections in LAMMPS order. Cost: O(1) text (the atoms are in the data
/// file).
pub fn render(d: &DeckInputs) -> String {
    let mut s = String::new();
    preamble::header(&mut s, d);
    preamble::setup(&mut s, d);
    groups::groups(&mut s);
    contacts::contacts(&mut s, d);
    ties::ties(&mut s, d);
    numerics::timestep(&mut s, d);
    fixes::fixes(&mut s, d);
    observables::observables(&mut s, d);
    phases::phases(&mut s, d);
    s
}
