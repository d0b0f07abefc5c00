//! The report's stamp: the tool's version, the UTC time the report's content was made and the
//! command line that made it, one line under the title ([`STAMP_PREFIX`]). A rerun whose report
//! differs only in that line keeps the old file ([`keep_stamp`]), so an unchanged design rewrites
//! nothing and the stamp stays that of the run that made the content.

use crate::runs::meta::{command_line, VERSION};
use serde::Serialize;

/// How the stamp line of `report.md` starts (the template writes it; [`keep_stamp`] finds it).
pub const STAMP_PREFIX: &str = "Made by superlube ";

/// Who made the report, when and how: the template's stamp line.
#[derive(Debug, Clone, Serialize)]
pub struct Made {
    /// The tool's version (`0.1.0`).
    pub version: String,
    /// The time the report was rendered, UTC to the minute (`2026-11-28 12:55`).
    pub date_utc: String,
    /// The command line, the program written as `superlube`, arguments quoted for a POSIX shell
    /// where they need it.
    pub command: String,
}

impl Made {
    /// The stamp of this process: its version, the clock now, its command line
    /// ([`command_line`]). Cost: a clock read.
    pub fn now() -> Made {
        let secs = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs());
        Made {
            version: VERSION.to_string(),
            date_utc: utc_text(secs),
            command: shell_words(&command_line()),
        }
    }
}

/// `secs` since 1970-01-01 00:00 UTC as `YYYY-MM-DD HH:MM` (the proleptic Gregorian calendar;
/// days to a civil date by H. Hinnant's algorithm).
pub fn utc_text(secs: u64) -> String {
    let days = (secs / 86_400) as i64;
    let (h, m) = ((secs % 86_400) / 3600, (secs % 3600) / 60);
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let mo = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(mo <= 2);
    format!("{y:04}-{mo:02}-{d:02} {h:02}:{m:02}")
}

/// The arguments as one POSIX shell line: a word of letters, digits and `_-./:,=+@%^` as is,
/// any other in single quotes (a `'` inside written `'\''`).
pub fn shell_words(argv: &[String]) -> String {
    argv.iter()
        .map(|w| {
            let plain = !w.is_empty()
                && w.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "_-./:,=+@%^".contains(c));
            if plain {
                w.clone()
            } else {
                format!("'{}'", w.replace('\'', r"'\''"))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The report to write: `old` (the file there now) when it equals `new` but for the stamp line,
/// else `new`.
pub fn keep_stamp(old: Option<String>, new: String) -> String {
    let body = |s: &str| -> String {
        s.split_inclusive('\n')
            .filter(|l| !l.starts_with(STAMP_PREFIX))
            .collect()
    };
    match old {
        Some(old) if body(&old) == body(&new) => old,
        _ => new,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utc_dates_are_civil() {
        assert_eq!(utc_text(0), "1970-01-01 00:00");
        // 2000-02-29 (a leap day of a century leap year) 23:59
        assert_eq!(utc_text(951_868_740), "2000-02-29 23:59");
        // 2026-11-28 12:48
        assert_eq!(utc_text(1_795_870_080), "2026-11-28 12:48");
    }

    #[test]
    fn words_with_spaces_or_quotes_are_quoted() {
        let v = |a: &[&str]| a.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(
            shell_words(&v(&["superlube", "design", "--load-mn", "1.4,2.1"])),
            "superlube design --load-mn 1.4,2.1"
        );
        assert_eq!(
            shell_words(&v(&["superlube", "--out-dir", "my run", "it's", ""])),
            r"superlube --out-dir 'my run' 'it'\''s' ''"
        );
    }

    #[test]
    fn a_report_changed_only_in_its_stamp_is_kept() {
        let old = format!("# t\n\n{STAMP_PREFIX}0.1.0 on 2026-01-01 00:00\n\nbody\n");
        let new = format!("# t\n\n{STAMP_PREFIX}0.1.0 on 2026-02-02 00:00\n\nbody\n");
        assert_eq!(keep_stamp(Some(old.clone()), new.clone()), old);
        let changed = new.replace("body", "other");
        assert_eq!(keep_stamp(Some(old), changed.clone()), changed);
        assert_eq!(keep_stamp(None, new.clone()), new);
    }
}
