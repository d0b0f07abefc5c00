//! What every stage of a design runs with: the design's parameters, the store of its finished
//! stages and the one observer told of each stage and event.

use super::observer::Observer;
use super::params::DesignParams;
use super::store::Store;

/// The context a stage of the design runs in (shared, read-only; cheap to copy).
#[derive(Clone, Copy)]
pub struct Ctx<'a> {
    /// The design's parameters (SI).
    pub p: &'a DesignParams,
    /// Where finished stages are stored and reused from.
    pub store: &'a Store,
    /// Told of each stage entered and each event; the stages' progress bars.
    pub obs: &'a dyn Observer,
}
