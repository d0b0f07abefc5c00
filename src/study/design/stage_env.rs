//! [`StageEnv`]: what every stage of a design runs with besides its own params: the knobs the
//! stages share ([`LimitKnobs`]), the store of finished stages and the one observer.

use super::limit::LimitKnobs;
use super::observer::Observer;
use super::store::Store;

/// The environment of a stage (shared, read-only; cheap to copy). Each stage value holds it
/// with its own params: `XStage::new(env, params).run(input)`.
#[derive(Clone, Copy)]
pub struct StageEnv<'a> {
    /// The shared limit knobs (SI): loads, μ_sl, contact line, estimate knobs, tolerance.
    pub limit: &'a LimitKnobs,
    /// Where finished stages are stored and reused from.
    pub store: &'a Store,
    /// Told of each stage entered and each event; the stages' progress bars.
    pub obs: &'a dyn Observer,
}
