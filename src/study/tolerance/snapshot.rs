//! A compact record of a robust search at one moment ([`Snapshot`]): which (sample, load)
//! estimates existed and what followed from them. With the search's final state (which holds
//! every estimate ever made) a snapshot restores the search exactly as it was, so a resumed
//! design replays each shortlist level with the states the first run had there.

use super::robust::RobustState;
use serde::{Deserialize, Serialize};

/// What a [`RobustState`] knew at one moment, without its rows.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Snapshot {
    /// Which rows existed: one bit per (sample, load), sample-major, as hex digits.
    pub known: String,
    /// [`RobustState::bound`].
    pub bound: usize,
    /// [`RobustState::worst`].
    pub worst: usize,
    /// [`RobustState::exact`].
    pub exact: bool,
    /// [`RobustState::theta_window_deg`].
    pub theta_window_deg: Option<f64>,
    /// [`RobustState::direction_window_deg`].
    pub direction_window_deg: Option<f64>,
    /// [`RobustState::paths`].
    pub paths: usize,
    /// [`RobustState::loads_estimated`].
    pub loads_estimated: usize,
}

impl RobustState {
    /// This state's snapshot. Cost: one bit per (sample, load).
    pub fn snapshot(&self) -> Snapshot {
        let bits: Vec<bool> = self
            .samples
            .iter()
            .flat_map(|s| s.rows.iter().map(|r| r.is_some()))
            .collect();
        let known = bits
            .chunks(4)
            .map(|c| {
                let v = c
                    .iter()
                    .enumerate()
                    .fold(0u32, |v, (i, &b)| v | (u32::from(b) << i));
                char::from_digit(v, 16).unwrap_or('0')
            })
            .collect();
        Snapshot {
            known,
            bound: self.bound,
            worst: self.worst,
            exact: self.exact,
            theta_window_deg: self.theta_window_deg,
            direction_window_deg: self.direction_window_deg,
            paths: self.paths,
            loads_estimated: self.loads_estimated,
        }
    }

    /// The state as it was at `snap`, from this later state (which must hold every row the
    /// snapshot names); `None` when it does not.
    pub fn at(&self, snap: &Snapshot) -> Option<RobustState> {
        let digits: Vec<u32> = snap
            .known
            .chars()
            .map(|c| c.to_digit(16))
            .collect::<Option<_>>()?;
        let bit = |k: usize| digits.get(k / 4).map(|d| d >> (k % 4) & 1 == 1);
        let mut st = self.clone();
        let mut k = 0;
        for s in &mut st.samples {
            for r in &mut s.rows {
                match (bit(k)?, r.is_some()) {
                    (true, false) => return None,
                    (false, true) => *r = None,
                    _ => {}
                }
                k += 1;
            }
        }
        st.bound = snap.bound;
        st.worst = snap.worst;
        st.exact = snap.exact;
        st.theta_window_deg = snap.theta_window_deg;
        st.direction_window_deg = snap.direction_window_deg;
        st.paths = snap.paths;
        st.loads_estimated = snap.loads_estimated;
        Some(st)
    }
}
