//! [`publish`] and [`write`]: the design's outputs, the answers logged first or the
//! per-pattern files written first.

use super::finish::finish;
use super::notes::answer_notes;
use super::pattern_files::Writer;
use crate::runs::meta::Inputs;
use crate::runs::progress::Progress;
use crate::study::design::store::Store;
use crate::study::design::{DesignOutcome, DesignParams};
use anyhow::Result;

/// Logs the answers through `progress`, then writes the design's global outputs
/// ([`finish`]) after the per-pattern files that `files` wrote while the design ran.
pub fn publish(files: Writer, o: &DesignOutcome, progress: &dyn Progress) -> Result<()> {
    for line in answer_notes(o, files.p) {
        progress.note(&line);
    }
    finish(files, o, progress)
}

/// Writes every final output of the design at once (see the module docs): each pattern's own
/// files, then the global ones. The patterns of `o` must not be trimmed (the design's hook
/// writes their files before trimming: [`Writer::pattern`]). Cost: as [`Writer::pattern`] per
/// pattern, then [`finish`].
pub fn write(
    store: &Store,
    record: &Inputs,
    p: &DesignParams,
    o: &DesignOutcome,
    progress: &dyn Progress,
) -> Result<()> {
    let files = Writer::new(store, record, p);
    for pr in &o.patterns {
        files.pattern(pr)?;
    }
    finish(files, o, progress)
}
