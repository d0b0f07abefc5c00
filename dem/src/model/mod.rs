//! Contact model of a slider–substrate sphere pair, composed of one sub-model per concern
//! (as LAMMPS `pair granular`): [`normal`] (Hertz + viscoelastic damping), [`tangential`]
//! (Mindlin history spring capped by μ·F_n, viscous damping) and [`friction`] (the law μ(p0)).

pub mod constant;
pub mod contact;
pub mod contact_batch;
pub mod friction;
pub mod friction_law;
pub mod hertz;
pub mod mindlin;
pub mod mindlin_force;
pub mod mindlin_rescale;
pub mod normal;
pub mod pressure_switched;
pub mod tangential;

pub use constant::Constant;
pub use contact::{reduced_mass, ContactModel, PairOut};
pub use contact_batch::{BatchPair, ContactBatch, BATCH};
pub use friction::Friction;
pub use friction_law::FrictionLaw;
pub use hertz::HertzNormal;
pub use mindlin::Mindlin;
pub use mindlin_force::MindlinForce;
pub use mindlin_rescale::MindlinRescale;
pub use normal::{NormalModel, NormalOut};
pub use pressure_switched::PressureSwitched;
pub use tangential::TangentialModel;
