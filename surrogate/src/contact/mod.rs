//! Contact mechanics between slider and substrate spheres: the Hertz normal law and the search
//! for candidate sphere pairs ([`BvhSearch`], parry3d; [`GridSearch`], a uniform bucket grid on a [`CellList`]).

mod bvh_search;
mod candidates;
mod cell_list;
mod coating_law;
mod hertz;

pub use bvh_search::BvhSearch;
pub(crate) use candidates::swept_distance2;
pub use candidates::{CandidatePair, CandidateSearch, GridSearch};
pub use cell_list::CellList;
pub use coating_law::{coating_failed, coating_mu};
pub use hertz::Hertz;
