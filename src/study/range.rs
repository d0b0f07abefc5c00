//! Parser of `--theta 0,21.8,30` (a list) and `--theta 0:30:0.1` (start:stop:step, inclusive).

use anyhow::{bail, Result};

/// Most values one list or range may expand to.
pub const MAX_VALUES: usize = 10_000_000;

/// Parses a comma-separated list (`0,21.8,30`: the values as typed) or an inclusive range
/// `start:stop:step` (`0:30:0.1` → 301 values). Range values are `start + k·step` rounded to 12
/// significant digits of the range's scale max(|start|, |stop|, step), so they are the decimal
/// numbers meant (0.3, not 0.30000000000000004) and a row of a range sweep is the same as a run
/// at that single value. `flag` names the option in errors.
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
        let n = ((b - a) / s + 1e-9).floor();
        if n >= MAX_VALUES as f64 {
            bail!(
                "`{flag}`: range `{text}` has {n:.0} values, more than {MAX_VALUES}; use a larger step"
            );
        }
        let scale = a.abs().max(b.abs()).max(s);
        let decimals = (11 - scale.log10().floor() as i32).clamp(0, 330) as usize;
        Ok((0..=n as usize)
            .map(|k| {
                let v = a + k as f64 * s;
                let c: f64 = format!("{v:.decimals$}").parse().unwrap_or(v);
                if c == 0.0 {
                    0.0
                } else {
                    c
                }
            })
            .collect())
    } else {
        let v: Vec<f64> = text.split(',').map(num).collect::<Result<_>>()?;
        Ok(v)
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
        assert_eq!(r[3], 0.3);
        assert_eq!(r[300], 30.0);
        for (k, v) in r.iter().enumerate() {
            assert_eq!(*v, format!("{}.{}", k / 10, k % 10).parse::<f64>().unwrap());
        }
        assert_eq!(
            parse_list_or_range("-1:1:0.5", "--alpha").unwrap(),
            vec![-1.0, -0.5, 0.0, 0.5, 1.0]
        );
        assert_eq!(parse_list_or_range("-1:1:0.1", "--alpha").unwrap()[10], 0.0);
        assert_eq!(
            parse_list_or_range("1e-20:3e-20:1e-20", "--load-mn").unwrap(),
            vec![1e-20, 2e-20, 3e-20]
        );
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
        assert!(parse_list_or_range("0:30:0.000000001", "--theta").is_err());
    }
}
