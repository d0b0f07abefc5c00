//! [`redraw`]: a figure drawn again only when it is missing or its data changed.

use crate::runs::output::Outputs;
use crate::study::design::store::Store;
use anyhow::Result;

/// Draws the figure `rel` of `store` with `draw` (given its path) when it is missing or `stale`
/// (its data changed), recording it in `outs` (sidecar, or the failure) and `wrote`.
pub(super) fn redraw(
    store: &Store,
    outs: &mut Outputs,
    wrote: &mut Vec<String>,
    rel: &str,
    stale: bool,
    draw: impl FnOnce(&std::path::Path) -> Result<()>,
) {
    let path = store.path(rel);
    if stale || !path.exists() {
        outs.attempt(rel, &path, || draw(&path));
        wrote.push(rel.to_string());
    }
}
