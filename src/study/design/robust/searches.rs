//! The state of the robust stage ([`super::RobustStage`]) across a pattern's shortlist
//! levels: [`Searches`], one [`RobustSearch`] per candidate keyed by its [`DesignKey`], reloaded
//! from and saved to the stored searches (`stages/<pattern>/robust.json`, [`StoredSearches`])
//! so that a resumed design replays each level exactly.

use crate::runs::meta::Inputs;
use crate::study::design::limit::LimitKnobs;
use crate::study::design::model::{Candidate, DesignScene};
use crate::study::design::store::Store;
use crate::study::rows::FrictionRow;
use crate::study::tolerance::{LimitParams, RobustSearch, RobustState, Snapshot, ToleranceBox};
use anyhow::Result;
use serde::{Deserialize, Serialize};
use serde_json::json;
use surrogate::solver::Solver;

/// One candidate's search as stored.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredSearch {
    /// θ (degrees).
    pub theta_deg: f64,
    /// α (degrees).
    pub alpha_deg: f64,
    /// Its nominal rows (the search is reused only for the same).
    pub nominal: Vec<FrictionRow>,
    /// The search's latest state (every estimate made).
    pub state: RobustState,
    /// The state after each shortlist level's robust stage: (level index, snapshot).
    pub levels: Vec<(usize, Snapshot)>,
}

/// The stored robust searches of one pattern (`stages/<pattern>/robust.json`, written after
/// each shortlist level).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct StoredSearches {
    /// Every search started so far.
    pub designs: Vec<StoredSearch>,
}

/// The identity of a design in the robust searches: its nominal (θ, α), degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DesignKey {
    /// θ (degrees).
    pub theta_deg: f64,
    /// α (degrees from the contact line).
    pub alpha_deg: f64,
}

impl DesignKey {
    /// The key of candidate `c`.
    pub fn of(c: &Candidate) -> DesignKey {
        DesignKey {
            theta_deg: c.theta_deg,
            alpha_deg: c.alpha_deg,
        }
    }
    /// The key of a stored search.
    fn of_stored(s: &StoredSearch) -> DesignKey {
        DesignKey {
            theta_deg: s.theta_deg,
            alpha_deg: s.alpha_deg,
        }
    }
}

/// The robust searches of one pattern's candidates, kept across the shortlist levels.
pub struct Searches<'a> {
    /// The substrates' solvers (one per seed).
    pub(super) solvers: &'a [Solver],
    limit: &'a LimitParams,
    /// The tolerance box.
    pub(super) bx: ToleranceBox,
    stored: StoredSearches,
    rel: String,
    inputs: Inputs,
    /// The searches of this run, by design.
    pub(super) live: Vec<(DesignKey, RobustSearch<'a>)>,
    /// Shortlist levels done so far in this run.
    level: usize,
}

impl<'a> Searches<'a> {
    /// The searches of `ds` (reloading those stored under `store`).
    pub fn new(
        ds: &DesignScene,
        knobs: &LimitKnobs,
        (solvers, limit): (&'a [Solver], &'a LimitParams),
        store: &Store,
    ) -> Result<Self> {
        let bx = knobs.tolerance_box();
        let inputs = Inputs {
            workflow: "design/robust".into(),
            scene: Some(crate::runs::meta::scene_file(&ds.scene)),
            params: json!({
                "theta_offsets_deg": bx.theta_offsets_deg,
                "direction_offsets_deg": bx.direction_offsets_deg,
                "seeds": knobs.tolerance.seeds,
                "limit": knobs.record(),
                "search": "best-first/v3",
            }),
        };
        let rel = format!("stages/{}/robust.json", ds.name);
        let stored = store
            .load_json::<StoredSearches>(&rel, &inputs)?
            .unwrap_or_default();
        Ok(Searches {
            solvers,
            limit,
            bx,
            stored,
            rel,
            inputs,
            live: Vec::new(),
            level: 0,
        })
    }

    /// Runs `f` on candidate `c`'s search (started or resumed as [`Searches::index`] does) and
    /// returns its result with the number of paths it solved.
    pub(super) fn counted<T>(
        &mut self,
        c: &Candidate,
        f: impl FnOnce(&mut RobustSearch<'a>) -> Result<T>,
    ) -> Result<(T, usize)> {
        let k = self.index(c);
        let s = &mut self.live[k].1;
        let before = s.state.paths;
        let v = f(s)?;
        Ok((v, s.state.paths - before))
    }

    /// The index in `live` of candidate `c`'s search, started (or resumed from the stored one)
    /// if it has none yet.
    pub(super) fn index(&mut self, c: &Candidate) -> usize {
        let key = DesignKey::of(c);
        if let Some(i) = self.live.iter().position(|(k, _)| *k == key) {
            return i;
        }
        let old = self.stored.designs.iter().find(|s| {
            DesignKey::of_stored(s) == key
                && s.nominal == c.friction
                && s.state.samples.len() == self.expected_samples()
                // a state from a later level than this one would use estimates this level did
                // not have (those levels are replayed from their snapshots instead)
                && s.levels.iter().all(|(l, _)| *l < self.level)
        });
        let s = match old {
            Some(s) => RobustSearch::resume(
                self.solvers,
                c.theta_deg,
                c.direction_deg,
                self.limit,
                s.state.clone(),
            ),
            None => RobustSearch::new(
                self.solvers,
                c.theta_deg,
                c.direction_deg,
                &c.friction,
                &self.bx,
                self.limit,
            ),
        };
        self.live.push((key, s));
        self.live.len() - 1
    }

    fn expected_samples(&self) -> usize {
        self.bx.theta_offsets_deg.len() * self.bx.direction_offsets_deg.len() * self.solvers.len()
    }

    /// Restores the searches as a stored run left them after this level (so a resumed design
    /// replays the level exactly, with no new estimate), where that run got this far.
    pub(super) fn begin_level(&mut self, ranking: &[Candidate]) {
        let level = self.level;
        for d in &self.stored.designs {
            let key = DesignKey::of_stored(d);
            let same = ranking
                .iter()
                .any(|c| DesignKey::of(c) == key && c.friction == d.nominal);
            let Some((_, snap)) = d.levels.iter().find(|(l, _)| *l == level) else {
                continue;
            };
            let Some(state) = d.state.at(snap).filter(|_| same) else {
                continue;
            };
            let Some(c) = ranking.iter().find(|c| DesignKey::of(c) == key) else {
                continue;
            };
            let s = RobustSearch::resume(
                self.solvers,
                c.theta_deg,
                c.direction_deg,
                self.limit,
                state,
            );
            match self.live.iter_mut().find(|(k, _)| *k == key) {
                Some(x) => x.1 = s,
                None => self.live.push((key, s)),
            }
        }
    }

    /// Stores the searches after this level (their latest states and this level's snapshots)
    /// and moves on to the next level.
    pub(super) fn save(&mut self, store: &Store, ranking: &[Candidate]) -> Result<()> {
        for (key, s) in &self.live {
            let Some(c) = ranking.iter().find(|c| DesignKey::of(c) == *key) else {
                continue;
            };
            let snap = (self.level, s.state.snapshot());
            match self
                .stored
                .designs
                .iter_mut()
                .find(|d| DesignKey::of_stored(d) == *key && d.nominal == c.friction)
            {
                Some(d) => {
                    // the latest state holds every estimate (a replayed level's is a subset)
                    if s.state.paths >= d.state.paths {
                        d.state = s.state.clone();
                    }
                    d.levels.retain(|(l, _)| *l != self.level);
                    d.levels.push(snap);
                }
                None => self.stored.designs.push(StoredSearch {
                    theta_deg: key.theta_deg,
                    alpha_deg: key.alpha_deg,
                    nominal: c.friction.clone(),
                    state: s.state.clone(),
                    levels: vec![snap],
                }),
            }
        }
        self.level += 1;
        store.save_json(&self.rel, &self.inputs, &self.stored)
    }
}
