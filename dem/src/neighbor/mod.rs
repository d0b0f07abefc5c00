//! Neighbour search: a cell list over the substrate spheres ([`CellList`]) and the Verlet pair
//! list with skin ([`build_pairs`]), rebuilt only when some particle has moved more than half
//! the skin ([`needs_rebuild`]). Contact history is carried across rebuilds keyed by (i, j).

pub mod pairs;

pub use pairs::{build_pairs, needs_rebuild};
/// The cell list is shared with the quasi-static pair search.
pub use surrogate::contact::CellList;
