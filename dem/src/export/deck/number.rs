//! [`N`]: a number as the deck writes it, and [`on`], a switch as the deck writes it.

/// A number as LAMMPS reads it: the shortest text that round-trips (`1e-5`, `0.1`, `1e8`).
pub(super) struct N(pub(super) f64);

impl std::fmt::Display for N {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let t = format!("{:?}", self.0);
        f.write_str(t.strip_suffix(".0").unwrap_or(&t))
    }
}

/// `on` or `off`, as LAMMPS keywords take a switch.
pub(super) fn on(b: bool) -> &'static str {
    if b {
        "on"
    } else {
        "off"
    }
}
