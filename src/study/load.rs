//! A normal load as a typed value: N inside (SI), identified by its user-unit decimal.
//!
//! Every row writes a load as its mN label ([`crate::study::rows::label`]: the value in mN to
//! 12 significant digits), and the workflows used to find "the same load" by comparing such
//! labels at each call. [`Load`] does that in one place: two loads are the same load when
//! their labels are equal (compared exactly, as bits: [`Load::key`]), and [`Load::is`] matches
//! a row's `load_mN`. The label is for printing and for the rows; the identity is the key.

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
    }
}
