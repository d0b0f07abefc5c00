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

#[cfg(test)]
mod tests {
    use super::*;

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
