//! Tips for a mistyped flag where clap's nearest-spelling guess points at the wrong idea: on
//! `yield` a typed `--alpha-deg` is nearest to `--theta-deg` in spelling, but the pull there is
//! `--direction-deg`. One table, [`TIPS`]; `main` applies [`better`] to clap's error.

/// (command, flag as typed without `--`, the tip that replaces clap's guess).
pub const TIPS: [(&str, &str, &str); 4] = [
    (
        "yield",
        "alpha-deg",
        "the pull here is `--direction-deg DEG`, in degrees from the substrate x axis (the design's direction_deg), not α from the contact line",
    ),
    (
        "yield",
        "alpha",
        "the pull here is `--direction-deg DEG`, in degrees from the substrate x axis (the design's direction_deg), not α from the contact line",
    ),
    (
        "design",
        "alpha-deg",
        "design scans α itself: `--scan-distance-um`, `--alpha-step-deg`; its answer's pull is reported as direction_deg",
    ),
    (
        "design",
        "direction-deg",
        "design finds the pulling direction itself (its answer's direction_deg); `--direction-tol-deg` sets its tolerance",
    ),
];

/// The tip of [`TIPS`] for the command line `args` (program name first, then the command),
/// if one of its flags is listed for that command.
pub fn tip(args: &[String]) -> Option<(&'static str, &'static str)> {
    let sub = args.get(1)?;
    args.iter().skip(2).find_map(|a| {
        let name = a.strip_prefix("--")?.split('=').next()?;
        TIPS.iter()
            .find(|(c, f, _)| *c == sub.as_str() && *f == name)
            .map(|(_, f, t)| (*f, *t))
    })
}

/// Clap's rendered error `rendered` for `args` with its "tip:" lines replaced by ours, when
/// [`tip`] has one; `None` otherwise (clap's error stands).
pub fn better(rendered: &str, args: &[String]) -> Option<String> {
    let (flag, t) = tip(args)?;
    if !rendered.contains(&format!("'--{flag}'")) {
        return None;
    }
    let mut out = String::new();
    let mut added = false;
    for line in rendered.lines() {
        if line.trim_start().starts_with("tip:") {
            if !added {
                out.push_str(&format!("  tip: {t}\n"));
                added = true;
            }
            continue;
        }
        if !added && line.starts_with("Usage:") {
            out.push_str(&format!("  tip: {t}\n\n"));
            added = true;
        }
        out.push_str(line);
        out.push('\n');
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    fn args(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    /// Each tip is for a flag the command does not have, and names flags it does have.
    #[test]
    fn every_tip_is_for_a_missing_flag_and_names_real_ones() {
        let cli = super::super::Cli::command();
        for (sub, flag, t) in TIPS {
            let cmd = cli.find_subcommand(sub).unwrap();
            let has = |f: &str| {
                cmd.get_arguments().any(|a| {
                    a.get_long() == Some(f) || a.get_all_aliases().unwrap_or_default().contains(&f)
                })
            };
            assert!(!has(flag), "{sub} has --{flag}");
            for named in t.split('`').skip(1).step_by(2) {
                let f = named.split(' ').next().unwrap().trim_start_matches("--");
                assert!(has(f), "{sub}: the tip names --{f}, which it lacks");
            }
        }
    }

    #[test]
    fn yield_alpha_points_at_direction() {
        let a = args(&["superlube", "yield", "--alpha-deg", "30", "--out-dir", "y"]);
        let e = super::super::Cli::command()
            .try_get_matches_from(&a)
            .unwrap_err()
            .render()
            .to_string();
        let b = better(&e, &a).unwrap();
        assert!(
            b.contains("--direction-deg") && !b.contains("'--theta-deg'"),
            "{b}"
        );
        assert!(b.contains("Usage:"), "{b}");
        assert!(better(&e, &args(&["superlube", "screen", "--alpha-deg"])).is_none());
    }
}
