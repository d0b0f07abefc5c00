//! Parser of `--theta 0,21.8,30` (a list) and `--theta 0:30:0.1` (start:stop:step, inclusive).

use anyhow::{bail, Result};

/// Parses a comma-separated list (`0,21.8,30`) or an inclusive range `start:stop:step`
/// (`0:30:0.1` → 301 values, computed as `start + k·step` to avoid drift). `flag` names the
/// option in errors.
pub fn parse_list_or_range(text: &str, flag: &str) -> Result<Vec<f64>> {
    let text = text.trim();
    if text.is_empty() {
        bail!("`{flag}` is empty: give a list like 0,15,30 or a range like 0:30:0.1");
    }
    let num = |s: &str| -> Result<f64> {
        let v: f64 = s
            .trim()
            .parse()
            .map_err(|_| anyhow::anyhow!("`{flag}`: `{s}` is not a number"))?;
        if !v.is_finite() {
            bail!("`{flag}`: `{s}` is not finite");
        }
        Ok(v)
    };
    if text.contains(':') {
        let parts: Vec<&str> = text.split(':').collect();
        if parts.len() != 3 {
            bail!("`{flag}`: range `{text}` must be start:stop:step");
        }
        let (a, b, s) = (num(parts[0])?, num(parts[1])?, num(parts[2])?);
        if s <= 0.0 {
            bail!("`{flag}`: step in `{text}` must be positive");
        }
        if b < a {
            bail!("`{flag}`: stop < start in `{text}`");
        }
        let n = ((b - a) / s + 1e-9).floor() as usize;
        if n > 10_000_000 {
            bail!("`{flag}`: range `{text}` has too many values");
        }
        Ok((0..=n).map(|k| a + k as f64 * s).collect())
    } else {
        text.split(',').map(num).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_and_ranges() {
        assert_eq!(
            parse_list_or_range("0,21.8,30", "--theta").unwrap(),
            vec![0.0, 21.8, 30.0]
        );
        let r = parse_list_or_range("0:30:0.1", "--theta").unwrap();
        assert_eq!(r.len(), 301);
        assert!((r[300] - 30.0).abs() < 1e-9);
        assert!(parse_list_or_range("0:30", "--theta")
            .unwrap_err()
            .to_string()
            .contains("--theta"));
        assert!(parse_list_or_range("a,1", "--load-mn")
            .unwrap_err()
            .to_string()
            .contains("--load-mn"));
        assert!(parse_list_or_range("1:0:1", "--theta").is_err());
        assert!(parse_list_or_range("", "--theta").is_err());
    }
}
