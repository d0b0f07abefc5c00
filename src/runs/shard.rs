//! [`Shard`]: which part of a sweep one process computes (`--shard i/n`, zero-based).
//!
//! A sweep of `N` work items (rows, runs) in its fixed order is cut into `n` contiguous blocks of
//! nearly equal size: shard `i` computes items `⌊N·i/n⌋ .. ⌊N·(i+1)/n⌋`. The split depends only on
//! `N`, `i` and `n`, so every process agrees on it, and concatenating the shards' rows in shard
//! order gives exactly the rows of the unsharded sweep, in the same order.

use anyhow::{bail, Result};
use serde::{Deserialize, Serialize};
use std::ops::Range;

/// Shard `index` of `count` (zero-based); `0/1` is the whole sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Shard {
    /// Which shard, `0 ≤ index < count`.
    pub index: usize,
    /// How many shards the sweep is cut into, ≥ 1.
    pub count: usize,
}

impl Default for Shard {
    fn default() -> Self {
        Shard::ALL
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Shard {
    /// The whole sweep (`0/1`).
    pub const ALL: Shard = Shard { index: 0, count: 1 };

    /// Parses `i/n` (zero-based `i`, `0 ≤ i < n`, `n ≥ 1`); errors name `flag`.
    pub fn parse(text: &str, flag: &str) -> Result<Shard> {
        let Some((i, n)) = text.split_once('/') else {
            bail!("`{flag}`: `{text}` must be i/n (zero-based shard i of n, e.g. 0/4)");
        };
        let num = |s: &str, what: &str| -> Result<usize> {
            s.trim().parse::<usize>().map_err(|_| {
                anyhow::anyhow!(
                    "`{flag}`: {what} `{}` in `{text}` must be a whole number ≥ 0",
                    s.trim()
                )
            })
        };
        let (index, count) = (num(i, "shard index")?, num(n, "shard count")?);
        if count == 0 {
            bail!("`{flag}`: `{text}`: the shard count must be at least 1");
        }
        if index >= count {
            bail!(
                "`{flag}`: `{text}`: shards are numbered from 0, so the index must be below the count {count} (the last shard is {}/{count})",
                count - 1
            );
        }
        Ok(Shard { index, count })
    }

    /// Whether this is the whole sweep.
    pub fn is_all(&self) -> bool {
        self.count == 1
    }

    /// The items `⌊n·i/count⌋ .. ⌊n·(i+1)/count⌋` of a sweep of `n` items that this shard
    /// computes (block sizes differ by at most one).
    pub fn range(&self, n: usize) -> Range<usize> {
        let at = |k: usize| ((n as u128 * k as u128) / self.count as u128) as usize;
        at(self.index)..at(self.index + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_accepts_and_refuses() {
        assert_eq!(
            Shard::parse("2/7", "--shard").unwrap(),
            Shard { index: 2, count: 7 }
        );
        assert!(Shard::parse("0/1", "--shard").unwrap().is_all());
        for bad in ["3/3", "-1/2", "1/0", "1", "a/2", "1/b", ""] {
            let e = Shard::parse(bad, "--shard").unwrap_err().to_string();
            assert!(e.contains("`--shard`"), "{bad}: {e}");
        }
    }

    #[test]
    fn ranges_cover_the_sweep_once_in_order() {
        for n in [0usize, 1, 5, 31, 100] {
            for count in [1usize, 2, 3, 7, 40] {
                let mut next = 0;
                for index in 0..count {
                    let r = Shard { index, count }.range(n);
                    assert_eq!(r.start, next);
                    assert!(r.len() <= n / count + 1);
                    next = r.end;
                }
                assert_eq!(next, n);
            }
        }
    }
}
