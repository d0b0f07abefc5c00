//! The LAMMPS data file (`atom_style hybrid sphere bond`, `units micro`) of a [`Layout`].

use super::layout::Layout;
use super::micro;
use std::fmt::Write;

/// Margin (m) around the atoms' extent for the initial box; the deck's boundaries are
/// shrink-wrapped (`s s s`), so the box follows the atoms afterwards.
const BOX_MARGIN: f64 = 5e-6;

/// Renders the data file. `title` becomes the first (comment) line. Positions in µm with
/// round-trip precision. O(N).
pub fn render(layout: &Layout, title: &str) -> String {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for a in &layout.atoms {
        for k in 0..3 {
            lo[k] = lo[k].min(a.pos[k]);
            hi[k] = hi[k].max(a.pos[k]);
        }
    }
    let mut s = String::with_capacity(64 * (layout.atoms.len() + layout.bonds.len()) + 512);
    let title = title.replace('\n', " ");
    let _ = writeln!(s, "{title}\n");
    let _ = writeln!(s, "{} atoms", layout.atoms.len());
    let _ = writeln!(s, "5 atom types");
    let _ = writeln!(s, "{} bonds", layout.bonds.len());
    let _ = writeln!(s, "2 bond types\n");
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        let _ = writeln!(
            s,
            "{} {} {name}lo {name}hi",
            micro::len(lo[k] - BOX_MARGIN),
            micro::len(hi[k] + BOX_MARGIN)
        );
    }
    let _ = writeln!(
        s,
        "\nAtoms # hybrid (id type x y z diameter density molecule)\n"
    );
    for a in &layout.atoms {
        let _ = writeln!(
            s,
            "{} {} {} {} {} {} {} {}",
            a.id,
            a.kind,
            micro::len(a.pos[0]),
            micro::len(a.pos[1]),
            micro::len(a.pos[2]),
            micro::len(a.diameter),
            micro::density(a.density),
            a.molecule
        );
    }
    let _ = writeln!(s, "\nBonds\n");
    for (k, b) in layout.bonds.iter().enumerate() {
        let _ = writeln!(s, "{} {} {} {}", k + 1, b.kind, b.a, b.b);
    }
    s
}
