//! Flags renamed so that one concept has one name across commands (`--out` a file, `--out-dir`
//! a folder; `--solver` the surrogate's load-sharing model, `--model` only the DEM's). The old
//! names stay hidden aliases for a release; using one prints a note naming the new one.

/// (subcommand, old flag, new flag).
pub const RENAMED: &[(&str, &str, &str)] = &[
    ("design", "--out", "--out-dir"),
    ("design", "--scan-um", "--scan-distance-um"),
    ("tolerance", "--out", "--out-dir"),
    ("patterns", "--out", "--out-dir"),
    ("screen", "--model", "--solver"),
    ("slurm", "--out", "--out-dir"),
    ("export-lammps", "--out", "--out-dir"),
];

/// The notes for the old flag names in the command line `args` (program name first, then the
/// subcommand). Cost: one pass over the arguments.
pub fn notes(args: &[String]) -> Vec<String> {
    let Some(sub) = args.get(1) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for a in args.iter().skip(2) {
        if a == "--" {
            break;
        }
        let name = a.split('=').next().unwrap_or(a);
        for &(cmd, old, new) in RENAMED {
            if cmd == sub && name == old {
                out.push(format!(
                    "note: `superlube {cmd} {old}` is now `{new}`; the old name still works for this release"
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
    }
}
