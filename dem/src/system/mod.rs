//! The particle system: static description ([`SystemSpec`], built from a scene by
//! [`from_scene`]) and the evolving [`State`].
//!
//! Particles: substrate spheres (x, y free and tethered to their sites, z fixed at their
//! height), slider spheres (x, y, z; or x, y only with `rigid_z`), one rigid control layer
//! (translation x, y, z only — the `locked` mount; see docs/validation/dem-engine.md "The slider mount (tilt)") and a kinematic support.

pub mod builder;
pub mod spec;
pub mod state;

pub use builder::{from_scene, from_scene_at, Start, StartInfo};
pub use spec::SystemSpec;
pub use state::{Active, ActiveStats, CommonMode, FrameMark, PairHist, PairList, Ringing, State};
