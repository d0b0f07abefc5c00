//! [`ExportOptions`]: the knobs of the LAMMPS export that are not part of the model.

/// Options of [`super::export_lammps`] (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct ExportOptions {
    /// The constant friction coefficient of every contact (–). Stock LAMMPS cannot switch μ per
    /// contact at P_crit; the study's μ1 is the natural choice (valid while no contact fails).
    pub mu: f64,
    /// Interval (s) of the contact dump (`contacts.dump`, read by `superlube lammps-check`);
    /// 0 = no dump.
    pub dump_interval: f64,
    /// Rest length (m) of the axial tie: the axial control spheres sit this far above the
    /// control-layer reference height. The bond's tension T adds a lateral stiffness T/L to the
    /// slider sphere (the Rust tie has none), so longer is closer; 3 µm (T/L < 1 % of the
    /// 10³ N/m lateral tie below 30 µN per contact) as in the earlier peer scripts.
    pub tie_length: f64,
    /// The command that made the export (recorded in the deck header and `export.json`).
    pub command: String,
    /// Pulling angle α from the contact line (rad) and the contact-line angle from the substrate
    /// x axis (rad), for the record (the model uses `ProtocolParams::alpha` = their sum).
    pub alpha_and_line: Option<(f64, f64)>,
}

impl Default for ExportOptions {
    /// μ = the study's μ1 = 0.01, a dump every 1 µs, 3 µm axial ties.
    fn default() -> Self {
        ExportOptions {
            mu: 0.01,
            dump_interval: 1e-6,
            tie_length: 3e-6,
            command: String::new(),
            alpha_and_line: None,
        }
    }
}
