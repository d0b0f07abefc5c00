//! Flags renamed so that one concept has one name across commands (`--out` a file, `--out-dir`
//! a folder; `--solver` the surrogate's load-sharing model, `--model` only the DEM's). The old
//! names stay hidden clap aliases (`#[arg(long = "new", alias = "old")]`) for a release; using
//! one prints a note naming the new one. The aliases are the one list: a new rename needs no
//! entry here.

use clap::CommandFactory;

/// The notes for the old flag names in the command line `args` (program name first, then the
/// subcommand): each `--old` that is a hidden alias of a flag of that subcommand. Cost: one
/// build of the clap command tree (well under a millisecond) and one pass over the arguments.
pub fn notes(args: &[String]) -> Vec<String> {
    let Some(sub) = args.get(1) else {
        return Vec::new();
    };
    let cli = super::Cli::command();
    let Some(cmd) = cli.find_subcommand(sub) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for a in args.iter().skip(2) {
        if a == "--" {
            break;
        }
        let Some(old) = a.split('=').next().and_then(|n| n.strip_prefix("--")) else {
            continue;
        };
        for arg in cmd.get_arguments() {
            let (Some(new), Some(aliases)) = (arg.get_long(), arg.get_all_aliases()) else {
                continue;
            };
            if aliases.contains(&old) {
                out.push(format!(
                    "note: `superlube {sub} --{old}` is now `--{new}`; the old name still works for this release"
                ));
            }
        }
    }
    out
}

/// The retired flag names: every hidden alias that is no flag of any command today (`--out`
/// is retired in `tolerance` but a file in `slide`, so it is not listed). Sorted, without `--`.
pub fn retired() -> Vec<String> {
    let cli = super::Cli::command();
    let current: std::collections::BTreeSet<&str> = cli
        .get_subcommands()
        .flat_map(|c| c.get_arguments().filter_map(|a| a.get_long()))
        .collect();
    let mut out: Vec<String> = cli
        .get_subcommands()
        .flat_map(|c| {
            c.get_arguments()
                .flat_map(|a| a.get_all_aliases().unwrap_or_default())
        })
        .filter(|a| !current.contains(a))
        .map(str::to_string)
        .collect();
    out.sort();
    out.dedup();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The code outside tests of `dir` (`.rs` and `.j2` files, recursively): each file's text
    /// before its `#[cfg(test)]`, without comment lines; `tests.rs` files and this one skipped.
    fn code(dir: &std::path::Path, out: &mut Vec<(String, String)>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                code(&p, out);
                continue;
            }
            let name = p.file_name().unwrap().to_string_lossy().to_string();
            let ext = p.extension().map(|x| x.to_string_lossy().to_string());
            if !matches!(ext.as_deref(), Some("rs" | "j2")) || name == "tests.rs" {
                continue;
            }
            if p.ends_with("cli/renamed.rs") {
                continue;
            }
            let text = std::fs::read_to_string(&p).unwrap();
            let text = text.split("#[cfg(test)]").next().unwrap_or("");
            let kept: Vec<&str> = text
                .lines()
                .filter(|l| !l.trim_start().starts_with("//"))
                .collect();
            out.push((p.display().to_string(), kept.join("\n")));
        }
    }

    /// No message, template or help text of the program names a retired flag: each points the
    /// user at today's name. Scans `src/`, `surrogate/src/` and `dem/src/`.
    #[test]
    fn no_message_names_a_retired_flag() {
        let retired = retired();
        assert!(retired.contains(&"alpha".to_string()), "{retired:?}");
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut files = Vec::new();
        for d in ["src", "surrogate/src", "dem/src"] {
            code(&root.join(d), &mut files);
        }
        let mut found = Vec::new();
        for (path, text) in &files {
            for old in &retired {
                let pat = format!("--{old}");
                for (i, _) in text.match_indices(&pat) {
                    let next = text[i + pat.len()..].chars().next();
                    if !next.is_some_and(|c| c.is_ascii_alphanumeric() || c == '-') {
                        found.push(format!("{path}: {pat}"));
                    }
                }
            }
        }
        assert!(
            found.is_empty(),
            "retired flag names in messages: {found:?}"
        );
    }

    fn args(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn old_names_get_a_note_and_new_or_other_commands_do_not() {
        let n = notes(&args(&[
            "superlube",
            "design",
            "--no-dem",
            "--out",
            "d",
            "--scan-um=4",
        ]));
        assert_eq!(n.len(), 2, "{n:?}");
        assert!(n[0].contains("`--out-dir`") && n[1].contains("`--scan-distance-um`"));
        assert!(notes(&args(&["superlube", "design", "--out-dir", "d"])).is_empty());
        // `--out` is a file in slide, `--model` the DEM's model there.
        assert!(notes(&args(&[
            "superlube",
            "slide",
            "--out",
            "s.csv",
            "--model",
            "full"
        ]))
        .is_empty());
        assert!(notes(&args(&["superlube"])).is_empty());
        // every renamed flag of the issue has its note
        for (sub, old) in [
            ("tolerance", "--out"),
            ("patterns", "--out"),
            ("export-lammps", "--out"),
            ("slurm", "--out"),
            ("screen", "--model"),
            ("figures", "--corrugation-method"),
            ("slurm", "--threads"),
            // flags whose names now carry their unit (issue 34)
            ("design", "--theta-tol"),
            ("design", "--direction-tol"),
            ("design", "--theta-tol-step"),
            ("design", "--direction-tol-step"),
            ("design", "--confirm-loads"),
            ("tolerance", "--theta-tol"),
            ("tolerance", "--direction-tol"),
            ("tolerance", "--theta-range"),
            ("tolerance", "--direction-range"),
            ("figures", "--theta-step"),
            // θ and α carry their unit; one name per idea (issue 48)
            ("screen", "--theta"),
            ("landscape", "--theta"),
            ("corrugation", "--alpha"),
            ("friction", "--alpha"),
            ("tolerance", "--alpha"),
            ("design", "--theta"),
            ("equilibrate", "--theta"),
            ("slide", "--alpha"),
            ("export-lammps", "--alpha"),
            ("figures", "--alpha"),
            ("patterns", "--normalize"),
            ("design", "--normalize"),
            ("design", "--seeds"),
        ] {
            assert_eq!(
                notes(&args(&["superlube", sub, old, "x"])).len(),
                1,
                "{sub} {old}"
            );
        }
    }
}
