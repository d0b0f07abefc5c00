//! A normal load as a typed value: N inside (SI), identified by its user-unit decimal; and the
//! load ladder of a workflow ([`Loads`]).
//!
//! Every row writes a load as its mN label ([`crate::study::rows::label`]: the value in mN to
//! 12 significant digits). [`Load`] gives a load its identity: two loads are the same load when
//! their labels are equal (compared exactly, as bits: [`Load::key`], a [`LoadKey`]), and a row
//! is joined to a load by the key of its `load_mN` ([`LoadKey::of_mn`]), never by comparing
//! floats. The label is for printing and for the rows; the identity is the key.

use super::rows::label;
use surrogate::units::{mn_to_n, n_to_mn};

/// A normal load W, held in N (SI). Equality and hashing are by [`Load::key`] (the exact mN
/// label), so 1.4 mN typed and 1.4 mN converted from N are one load. Cost: one format and
/// parse per key (the label's rounding).
#[derive(Debug, Clone, Copy)]
pub struct Load(f64);

/// The identity of a [`Load`]: the bits of its mN label (12 significant digits).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LoadKey(u64);

impl Load {
    /// The load `n` (N).
    pub fn from_n(n: f64) -> Load {
        Load(n)
    }
    /// The load `mn` (mN), converted to N with `surrogate::units`.
    pub fn from_mn(mn: f64) -> Load {
        Load(mn_to_n(mn))
    }
    /// The load in N (SI): what the solvers take.
    pub fn n(self) -> f64 {
        self.0
    }
    /// The label in mN (12 significant digits): what rows and messages print.
    pub fn mn(self) -> f64 {
        label(n_to_mn(self.0))
    }
    /// The exact identity (bits of [`Load::mn`]).
    pub fn key(self) -> LoadKey {
        LoadKey(self.mn().to_bits())
    }
    /// Whether a row's `load_mN` (a label) names this load.
    pub fn is(self, load_mn: f64) -> bool {
        self.mn().to_bits() == load_mn.to_bits()
    }
    /// The index of the load named `load_mn` (mN label) in `loads` (N), if there.
    pub fn position(loads: &[f64], load_mn: f64) -> Option<usize> {
        loads.iter().position(|&w| Load(w).is(load_mn))
    }
    /// How many of `loads` (N) are at most the load labelled `mn` (mN), compared by label.
    pub fn count_upto(loads: &[f64], mn: f64) -> usize {
        loads.iter().filter(|&&w| Load(w).mn() <= mn).count()
    }
}

impl LoadKey {
    /// The key of a load written as its mN label (a row's `load_mN`).
    pub fn of_mn(mn: f64) -> LoadKey {
        LoadKey(label(mn).to_bits())
    }
}

/// The load ladder of a workflow: loads in N (SI), strictly increasing, each one a [`Load`].
/// Derefs to the N slice the solvers take; the typed questions (which load a row's label
/// names, how many loads a limit counts, the label of the k-th) are its methods. Cost: a
/// `Vec<f64>`; each key lookup one format and parse per load.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Loads(Vec<f64>);

impl Loads {
    /// The ladder of `n` (N, strictly increasing: checked by the caller, which names its
    /// input).
    pub fn new(n: Vec<f64>) -> Loads {
        Loads(n)
    }
    /// The loads in N (SI).
    pub fn n(&self) -> &[f64] {
        &self.0
    }
    /// The `k`-th load.
    pub fn load(&self, k: usize) -> Load {
        Load(self.0[k])
    }
    /// The loads as their mN labels, in order (what rows and records print).
    pub fn labels_mn(&self) -> Vec<f64> {
        self.0.iter().map(|&w| Load(w).mn()).collect()
    }
    /// The index of the load whose key is `key`, if it is one of the ladder.
    pub fn position(&self, key: LoadKey) -> Option<usize> {
        self.0.iter().position(|&w| Load(w).key() == key)
    }
    /// How many loads are at most the load labelled `mn` (mN), compared by label.
    pub fn count_upto(&self, mn: f64) -> usize {
        Load::count_upto(&self.0, mn)
    }
    /// The label (mN) of a limit counted in loads: the `n`-th load's, 0 for none.
    pub fn limit_mn(&self, n: usize) -> f64 {
        if n == 0 {
            0.0
        } else {
            Load(self.0[n - 1]).mn()
        }
    }
}

impl std::ops::Deref for Loads {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        &self.0
    }
}

impl PartialEq for Load {
    fn eq(&self, other: &Load) -> bool {
        self.key() == other.key()
    }
}

impl Eq for Load {}

impl std::hash::Hash for Load {
    fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
        self.key().hash(h)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A load round-trips between mN and N with its identity, and rows find it by label.
    #[test]
    fn typed_load_round_trips() {
        for mn in [0.35, 0.7, 1.05, 1.4, 1.75, 2.1, 3.5, 3.86, 1e-12, 21.8] {
            let w = Load::from_mn(mn);
            assert_eq!(w.mn(), mn);
            assert_eq!(Load::from_n(w.n()), w);
            assert!(w.is(mn));
            assert_eq!(Load::from_mn(w.mn()).key(), w.key());
        }
        // 0.7 mN from a range step (0.35 + 0.35) and typed are one load
        let step = Load::from_n(mn_to_n(0.35) + mn_to_n(0.35));
        assert_eq!(step, Load::from_mn(0.7));
        assert_ne!(Load::from_mn(0.7), Load::from_mn(0.70000001));
        let loads: Vec<f64> = [0.35, 0.7, 1.4].iter().map(|&m| mn_to_n(m)).collect();
        assert_eq!(Load::position(&loads, 0.7), Some(1));
        assert_eq!(Load::position(&loads, 1.05), None);
        assert_eq!(Load::count_upto(&loads, 1.0), 2);
        let ladder = Loads::new(loads);
        assert_eq!(ladder.position(LoadKey::of_mn(0.7)), Some(1));
        assert_eq!(ladder.position(Load::from_mn(0.35).key()), Some(0));
        assert_eq!(ladder.position(LoadKey::of_mn(1.05)), None);
        assert_eq!(ladder.labels_mn(), vec![0.35, 0.7, 1.4]);
        assert_eq!((ladder.limit_mn(0), ladder.limit_mn(3)), (0.0, 1.4));
        assert_eq!(ladder.count_upto(1.4), 3);
    }
}
