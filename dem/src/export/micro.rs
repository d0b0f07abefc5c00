//! LAMMPS `units micro`, the unit system of the exported files, as SI multipliers.
//!
//! These are not user-facing units (those live in `surrogate::units`); they define the foreign
//! unit system LAMMPS reads: length µm, time µs, mass pg, force nN, pressure 10³ Pa, density
//! pg/µm³ (= g/cm³), velocity µm/µs (= m/s), stiffness nN/µm (= 10⁻³ N/m).

/// Metres per LAMMPS micro length unit (µm).
pub const LENGTH: f64 = 1e-6;
/// Seconds per LAMMPS micro time unit (µs).
pub const TIME: f64 = 1e-6;
/// Kilograms per LAMMPS micro mass unit (pg).
pub const MASS: f64 = 1e-15;
/// Newtons per LAMMPS micro force unit (nN = pg·µm/µs²).
pub const FORCE: f64 = 1e-9;
/// Pascals per LAMMPS micro pressure unit (pg/(µm·µs²) = 10³ Pa).
pub const PRESSURE: f64 = 1e3;
/// kg/m³ per LAMMPS micro density unit (pg/µm³ = g/cm³).
pub const DENSITY: f64 = 1e3;
/// N/m per LAMMPS micro stiffness unit (nN/µm).
pub const STIFFNESS: f64 = FORCE / LENGTH;
/// N·s/m per LAMMPS micro damping-coefficient unit (pg/µs, force per velocity).
pub const DRAG: f64 = MASS / TIME;
/// m/s per LAMMPS micro velocity unit (µm/µs).
pub const VELOCITY: f64 = LENGTH / TIME;

/// m → µm (LAMMPS length).
pub fn len(v: f64) -> f64 {
    v / LENGTH
}
/// s → µs (LAMMPS time).
pub fn time(v: f64) -> f64 {
    v / TIME
}
/// N → nN (LAMMPS force).
pub fn force(v: f64) -> f64 {
    v / FORCE
}
/// Pa → 10³ Pa (LAMMPS pressure).
pub fn pressure(v: f64) -> f64 {
    v / PRESSURE
}
/// kg/m³ → pg/µm³ (LAMMPS density).
pub fn density(v: f64) -> f64 {
    v / DENSITY
}
/// N/m → nN/µm (LAMMPS stiffness).
pub fn stiffness(v: f64) -> f64 {
    v / STIFFNESS
}
/// N·s/m → pg/µs (LAMMPS drag coefficient, e.g. `fix viscous` γ).
pub fn drag(v: f64) -> f64 {
    v / DRAG
}
/// m/s → µm/µs (LAMMPS velocity).
pub fn velocity(v: f64) -> f64 {
    v / VELOCITY
}
