//! The one place where user-facing units (µm, mN, GPa, µs, nm, degrees, g/cm³) are converted to
//! and from the SI units used everywhere inside the code (m, N, Pa, s, rad, kg/m³).

/// Metres per micrometre.
pub const UM: f64 = 1e-6;
/// Metres per nanometre.
pub const NM: f64 = 1e-9;
/// Newtons per millinewton.
pub const MN: f64 = 1e-3;
/// Newtons per micronewton.
pub const UN: f64 = 1e-6;
/// Pascals per gigapascal.
pub const GPA: f64 = 1e9;
/// Seconds per microsecond.
pub const US: f64 = 1e-6;
/// kg/m³ per g/cm³.
pub const G_PER_CM3: f64 = 1e3;

/// µm → m.
pub fn um_to_m(v: f64) -> f64 {
    v * UM
}
/// m → µm.
pub fn m_to_um(v: f64) -> f64 {
    v / UM
}
/// m → nm.
pub fn m_to_nm(v: f64) -> f64 {
    v / NM
}
/// mN → N.
pub fn mn_to_n(v: f64) -> f64 {
    v * MN
}
/// N → mN.
pub fn n_to_mn(v: f64) -> f64 {
    v / MN
}
/// GPa → Pa.
pub fn gpa_to_pa(v: f64) -> f64 {
    v * GPA
}
/// Pa → kPa.
pub fn pa_to_kpa(v: f64) -> f64 {
    v * 1e-3
}
/// m² → µm².
pub fn m2_to_um2(v: f64) -> f64 {
    v / (UM * UM)
}
/// N → µN.
pub fn n_to_un(v: f64) -> f64 {
    v * 1e6
}
/// Pa → GPa.
pub fn pa_to_gpa(v: f64) -> f64 {
    v / GPA
}
/// µs → s.
pub fn us_to_s(v: f64) -> f64 {
    v * US
}
/// s → µs.
pub fn s_to_us(v: f64) -> f64 {
    v / US
}
/// g/cm³ → kg/m³.
pub fn gcm3_to_kgm3(v: f64) -> f64 {
    v * G_PER_CM3
}
/// kg/m³ → g/cm³.
pub fn kgm3_to_gcm3(v: f64) -> f64 {
    v / G_PER_CM3
}
/// degrees → radians.
pub fn deg_to_rad(v: f64) -> f64 {
    v.to_radians()
}
/// radians → degrees.
pub fn rad_to_deg(v: f64) -> f64 {
    v.to_degrees()
}
/// Joules per picojoule.
pub const PJ: f64 = 1e-12;
/// J → pJ.
pub fn j_to_pj(v: f64) -> f64 {
    v / PJ
}
