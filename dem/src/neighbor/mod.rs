//! Neighbour search: a cell list over the substrate spheres ([`CellList`]) and the Verlet pair
//! list with skin ([`build_pairs`]), rebuilt only when some particle has moved more than half
//! the skin ([`needs_rebuild`]). Contact history is carried across rebuilds keyed by (i, j).

pub mod cell_list;
pub mod pairs;

pub use cell_list::CellList;
pub use pairs::{build_pairs, needs_rebuild};
