//! [`render`]: the deck, section by section.

use super::inputs::DeckInputs;
use super::{contacts, fixes, groups, numerics, observables, phases, preamble, ties};

/// Renders the deck: its sections in LAMMPS order. Cost: O(1) text (the atoms are in the data
/// file).
pub fn render(d: &DeckInputs) -> String {
    let mut s = String::new();
    preamble::header(&mut s, d);
    preamble::setup(&mut s, d);
    groups::groups(&mut s);
    contacts::contacts(&mut s, &d.contact, d.numerics.skin);
    ties::ties(&mut s, &d.ties);
    numerics::timestep(&mut s, &d.numerics);
    fixes::fixes(&mut s, d);
    observables::observables(&mut s, d);
    phases::phases(&mut s, d);
    s
}
