//! [`Sweep`]: the contract behind `--shard`, `--resume` and `superlube merge`.
//!
//! A sweep is `items` work items in a fixed order (θ values of a screen, grid points of a
//! landscape, α values of a corrugation sweep, runs of a DEM batch…); item `i` gives exactly
//! `rows_per_item` rows, rows `i·r .. (i+1)·r` of the output, whatever process computes it. So:
//!
//! - a shard `i/n` ([`Shard`]) computes the items [`Shard::range`] and writes their rows; its
//!   sidecar records a [`ShardInfo`] (next to the sweep's unchanged `input_hash`);
//! - a resumed run keeps the complete items of its partial file (rows / r, a torn last line and
//!   the rows of an unfinished item cut off) and computes the rest ([`super::resume`]);
//! - `superlube merge` checks the shards' sidecars and joins them ([`crate::study::merge`]): by
//!   concatenation for row schemas that are final per item, or by the schema's own merge (the
//!   landscape's z rows become Δz rows, which need the global min z).

use super::shard::Shard;
use anyhow::{bail, Result};
use serde::{Deserialize, Serialize};
use std::ops::Range;

/// Schema name of the landscape's shard rows ([`crate::study::rows::LandscapeZRow`]), whose merge
/// writes the final [`crate::study::rows::LandscapeRow`]s.
pub const LANDSCAPE_Z: &str = "landscape-z";

/// A sweep's work items (see the module docs).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sweep {
    /// Work items of the whole sweep, in output order.
    pub items: usize,
    /// Rows each item gives (e.g. the loads of a screen's θ).
    pub rows_per_item: usize,
    /// What one item is, for messages (`θ`, `grid points`, `α`).
    pub unit: &'static str,
    /// Name of the row schema the sweep's (shard) output holds; `merge` concatenates any schema
    /// except those with a merge of their own ([`LANDSCAPE_Z`]).
    pub schema: &'static str,
}

/// A shard as recorded in its output's sidecar (`"shard": {…}`). The sweep's `input_hash` is
/// the same for every shard and the unsharded run: the shard is recorded here, not hashed.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ShardInfo {
    /// Which shard (zero-based).
    pub index: usize,
    /// Shards of the sweep.
    pub count: usize,
    /// Items of the whole sweep.
    pub items: usize,
    /// This shard's items `[first, end)` ([`Shard::range`]).
    pub item_range: [usize; 2],
    /// Rows per item.
    pub rows_per_item: usize,
    /// What one item is.
    pub unit: String,
    /// Row schema of the file.
    pub schema: String,
}

impl ShardInfo {
    /// This shard's items.
    pub fn range(&self) -> Range<usize> {
        self.item_range[0]..self.item_range[1]
    }

    /// Rows this shard's file holds when complete.
    pub fn rows(&self) -> u64 {
        (self.range().len() as u64).saturating_mul(self.rows_per_item as u64)
    }

    /// Rows of the whole sweep.
    pub fn total_rows(&self) -> u64 {
        (self.items as u64).saturating_mul(self.rows_per_item as u64)
    }

    /// `i/n`.
    pub fn label(&self) -> String {
        format!("{}/{}", self.index, self.count)
    }
}

impl Sweep {
    /// Rows of the whole sweep.
    pub fn rows(&self) -> u64 {
        (self.items as u64).saturating_mul(self.rows_per_item as u64)
    }

    /// The record of `shard` of this sweep. Errors (naming `flag`) when there are more shards
    /// than items: every shard must have work.
    pub fn shard(&self, shard: Shard, flag: &str) -> Result<ShardInfo> {
        if shard.count > self.items {
            bail!(
                "`{flag}`: {} shards but the sweep has only {} {}; use at most {} shards",
                shard.count,
                self.items,
                self.unit,
                self.items
            );
        }
        let r = shard.range(self.items);
        Ok(ShardInfo {
            index: shard.index,
            count: shard.count,
            items: self.items,
            item_range: [r.start, r.end],
            rows_per_item: self.rows_per_item,
            unit: self.unit.to_string(),
            schema: self.schema.to_string(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shard_records_its_block_and_refuses_empty_shards() {
        let s = Sweep {
            items: 31,
            rows_per_item: 2,
            unit: "θ",
            schema: "screen",
        };
        let i = s.shard(Shard { index: 6, count: 7 }, "--shard").unwrap();
        assert_eq!(i.range(), 26..31);
        assert_eq!(i.rows(), 10);
        assert_eq!(i.total_rows(), 62);
        let e = s
            .shard(
                Shard {
                    index: 0,
                    count: 32,
                },
                "--shards",
            )
            .unwrap_err()
            .to_string();
        assert!(e.contains("`--shards`") && e.contains("31 θ"), "{e}");
    }
}
