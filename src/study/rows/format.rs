//! Number formatting of row values: labels (θ in degrees, W in mN) rounded to 12 significant
//! digits, grid coordinates cleaned of binary noise, and exact µm text for lengths that must
//! read back bit for bit.

use serde::{Deserialize, Deserializer, Serializer};

/// Rounds a grid or range coordinate to 1e-9 of its unit, removing the binary noise of
/// `start + k·step` (0.06000000000000001 → 0.06). Used for the landscape grid (µm) and the
/// pulling angles α and directions (degrees): 1e-9 µm and 1e-9° are far below any physical
/// resolution.
pub fn clean(v: f64) -> f64 {
    (v * 1e9).round() / 1e9
}

/// A value converted to user units for a row label (θ in degrees, W in mN), rounded to 12
/// significant digits: removes the noise of the SI round trip (10.200000000000001 → 10.2) at
/// any magnitude, so a load of 1e-20 mN prints as `1e-20`, never `0.0`.
pub fn label(v: f64) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    format!("{v:.11e}").parse().unwrap_or(v)
}

/// The exact decimal text of a length `v` (m) in µm: the shortest decimal that reads back as
/// exactly `v` in metres (Rust's round-trip `{:e}`), with its decimal point moved six places
/// (plain notation while the exponent is in −7..21, else `d.ddde±N`). So the text is `v` in µm
/// to ≤ 1 ulp for any reader, and [`parse_exact_um`] gives back `v` bit for bit — which
/// `m_to_um`/`um_to_m` do not guarantee (×10⁶ then ×10⁻⁶ is not an identity on doubles).
pub fn exact_um(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return format!("{v}"); // NaN, inf, 0, -0
    }
    let s = format!("{v:e}");
    let (mant, exp) = s.split_once('e').unwrap_or((&s, "0"));
    let exp = exp.parse::<i32>().unwrap_or(0) + 6;
    let (sign, mant) = match mant.strip_prefix('-') {
        Some(m) => ("-", m),
        None => ("", mant),
    };
    // value = d0.d1d2… × 10^exp
    let digits: String = mant.chars().filter(|c| *c != '.').collect();
    if !(-7..21).contains(&exp) {
        return format!("{sign}{mant}e{exp}");
    }
    if exp < 0 {
        let zeros = "0".repeat((-exp - 1) as usize);
        return format!("{sign}0.{zeros}{digits}");
    }
    let int_len = exp as usize + 1;
    if digits.len() <= int_len {
        format!("{sign}{digits}{}", "0".repeat(int_len - digits.len()))
    } else {
        format!("{sign}{}.{}", &digits[..int_len], &digits[int_len..])
    }
}

/// Reads [`exact_um`]'s text (µm) back to the exact length in metres. Errors name `what`.
pub fn parse_exact_um(text: &str, what: &str) -> anyhow::Result<f64> {
    let t = text.trim();
    let bad = || anyhow::anyhow!("{what}: `{t}` is not a length in µm");
    // Move the decimal point back six places in the text, then parse once (correctly rounded):
    // the decimal read is the one written, so the double is the one written.
    let m_text = match t.split_once(['e', 'E']) {
        Some((m, e)) => format!("{m}e{}", e.parse::<i32>().map_err(|_| bad())? - 6),
        None if t.chars().any(|c| c.is_ascii_digit()) => format!("{t}e-6"),
        None => t.to_string(), // NaN, inf
    };
    m_text.parse::<f64>().map_err(|_| bad())
}

pub(super) fn ser_exact_um<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&exact_um(*v))
}

pub(super) fn de_exact_um<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    let t = String::deserialize(d)?;
    parse_exact_um(&t, "z_um").map_err(serde::de::Error::custom)
}
