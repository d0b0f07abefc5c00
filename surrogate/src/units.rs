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
/// s → ms.
pub fn s_to_ms(v: f64) -> f64 {
    v * 1e3
}
/// mN → µN.
pub fn mn_to_un(v: f64) -> f64 {
    v * 1e3
}
/// rad → µrad.
pub fn rad_to_urad(v: f64) -> f64 {
    v * 1e6
}

/// `v` rounded to `n` significant digits (0 stays 0), for messages: shows a difference without
/// the noise of the last bits. O(1).
pub fn significant(v: f64, n: i32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let k = n - 1 - v.abs().log10().floor() as i32;
    if k >= 0 {
        let p = 10f64.powi(k);
        (v * p).round() / p
    } else {
        let p = 10f64.powi(-k);
        (v / p).round() * p
    }
}

/// A length (m) as µm text for messages and TOML snippets: rounded to 1e-6 µm (1 pm), shortest
/// decimal (`9.999999999999999e-6` m → `10`, `1.4849999999999999e-6` m → `1.485`).
pub fn um_text(v: f64) -> String {
    let u = (m_to_um(v) * 1e6).round() / 1e6 + 0.0;
    format!("{u}")
}

/// A point (m) as the µm pair of a TOML file or a site file, `[x, y]` (see [`um_text`]).
pub fn um_pair_text(p: [f64; 2]) -> String {
    format!("[{}, {}]", um_text(p[0]), um_text(p[1]))
}

/// A length (m) as nm text with 4 significant digits (an overlap of 3 pm: `0.003`).
pub fn nm_text(v: f64) -> String {
    format!("{}", significant(m_to_nm(v), 4) + 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn message_texts_have_user_digits() {
        // the doubles next to 10 µm and 50 µm, and 1.485 µm as it arrives from a file
        let below = |v: f64| f64::from_bits(v.to_bits() - 1);
        assert_eq!(um_text(below(10e-6)), "10");
        assert_eq!(um_text(um_to_m(1.485)), "1.485");
        assert_eq!(um_text(below(50e-6)), "50");
        assert_eq!(um_text(-0.0), "0");
        assert_eq!(um_pair_text([2.598076e-6, 1.5e-6]), "[2.598076, 1.5]");
        assert_eq!(nm_text(3e-12), "0.003");
        assert_eq!(nm_text(3.0e-8), "30");
        assert_eq!(nm_text(1.51549e-6), "1515");
        assert_eq!(significant(123456.0, 2), 120000.0);
    }
}
