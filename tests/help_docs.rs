//! The command pages cannot drift from `--help`: every long flag of every subcommand's help
//! (hidden aliases aside) is on its page `docs/commands/<command>.md` (the scene flags, shared
//! by every command, on screen.md's, which the other pages point to as "scene flags"); no help
//! text prints a default twice; and the examples the help gives for a scene flag run.

mod common;
use clap::{Args, CommandFactory};
use common::{assert_ok, bin};
use std::collections::BTreeSet;
use std::path::Path;
use superlube::cli::{Cli, SceneArgs};

/// The page that documents `command` (`equilibrate` shares `slide`'s page).
fn page(command: &str) -> String {
    let name = match command {
        "equilibrate" => "slide",
        c => c,
    };
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs/commands")
        .join(format!("{name}.md"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Whether `text` names `--flag` as a whole flag (not as the start of a longer one).
fn names_flag(text: &str, flag: &str) -> bool {
    let needle = format!("--{flag}");
    text.match_indices(&needle).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + needle.len()..].chars().next();
        !before.is_some_and(|c| c.is_alphanumeric() || c == '-')
            && !after.is_some_and(|c| c.is_alphanumeric() || c == '-' || c == '_')
    })
}

/// The long names of the scene flags (the same group in every command).
fn scene_flags() -> BTreeSet<String> {
    SceneArgs::augment_args(clap::Command::new("scene"))
        .get_arguments()
        .filter_map(|a| a.get_long().map(str::to_string))
        .collect()
}

#[test]
fn every_flag_of_every_help_is_on_its_command_page() {
    let scene = scene_flags();
    assert!(scene.contains("slider-lattice") && scene.contains("pattern"));
    let screen = page("screen");
    let mut missing = Vec::new();
    for sub in Cli::command().get_subcommands() {
        let name = sub.get_name();
        let text = page(name);
        for arg in sub.get_arguments() {
            let Some(long) = arg.get_long() else { continue };
            if arg.is_hide_set() || long == "help" || long == "version" {
                continue;
            }
            if scene.contains(long) {
                if !names_flag(&screen, long) {
                    missing.push(format!("screen.md: --{long} (scene flag)"));
                }
                if name != "screen" && !text.contains("scene flags") && !names_flag(&text, long) {
                    missing.push(format!("{name}: --{long} (no \"scene flags\" on the page)"));
                }
            } else if !names_flag(&text, long) {
                missing.push(format!("{name}: --{long}"));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "flags in --help but not on their docs/commands page:\n{}",
        missing.join("\n")
    );
}

/// An old name is a hidden alias, never a visible flag, so the pages need not list it; the
/// current name of θ and α carries its unit in every command.
#[test]
fn theta_and_alpha_carry_their_unit_everywhere() {
    for sub in Cli::command().get_subcommands() {
        for arg in sub.get_arguments() {
            if let Some(long) = arg.get_long() {
                assert!(
                    long != "theta" && long != "alpha",
                    "`{} --{long}` has no unit in its name",
                    sub.get_name()
                );
            }
        }
    }
}

#[test]
fn no_help_prints_a_default_twice() {
    for sub in Cli::command().get_subcommands_mut() {
        let name = sub.get_name().to_string();
        let help = sub.render_long_help().to_string();
        // one entry per option: from a line starting with a flag to the next such line
        let mut entries: Vec<String> = Vec::new();
        for line in help.lines() {
            let t = line.trim_start();
            if t.starts_with("--") || (t.starts_with('-') && t.get(2..4) == Some(", ")) {
                entries.push(String::new());
            }
            if let Some(e) = entries.last_mut() {
                e.push_str(line);
                e.push('\n');
            }
        }
        assert!(!entries.is_empty(), "{name}: no options found in\n{help}");
        for e in entries {
            assert!(
                e.matches("[default:").count() <= 1,
                "`{name} --help` prints a default twice:\n{e}"
            );
        }
    }
}

/// Every `KIND:SPACING` example of `--slider-lattice`'s help makes a scene that runs with the
/// default (3 µm) spheres.
#[test]
fn the_slider_lattice_examples_of_the_help_run() {
    let cmd = Cli::command();
    let screen = cmd.find_subcommand("screen").unwrap();
    let arg = screen
        .get_arguments()
        .find(|a| a.get_long() == Some("slider-lattice"))
        .unwrap();
    let help = arg.get_help().unwrap().to_string();
    let examples: Vec<&str> = help
        .split('`')
        .skip(1)
        .step_by(2)
        .filter(|t| t.contains(':') && !t.contains('_'))
        .collect();
    assert!(examples.len() >= 5, "{examples:?} in {help}");
    for ex in examples {
        let out = bin()
            .args(["screen", "--pattern", "square-tri", "--slider-lattice", ex])
            .args(["--slider-radius-um", "20", "--substrate-um", "80x60"])
            .args(["--theta-deg", "0", "--load-mn", "0.1"])
            .output()
            .unwrap();
        assert_ok(&out);
    }
}

/// The `## Default` section of a command page: its `--flag VALUE` claims, from table rows
/// naming one flag (`| `--grid` | 51 |`) and from code spans (`` `--samples 59` ``). Values are
/// the first word of the cell or span, without backticks; cells that describe rather than
/// state a value ("the pattern's", "none") are left out.
fn claimed_defaults(page: &str) -> Vec<(String, String)> {
    let Some(sec) = page.split("\n## Default").nth(1) else {
        return Vec::new();
    };
    let sec = sec.split("\n## ").next().unwrap_or("");
    let mut out = Vec::new();
    for line in sec.lines() {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        if line.starts_with('|') && cells.len() >= 4 {
            let flags: Vec<&str> = cells[1].matches("`--").collect();
            let value = cells[2].trim_matches('`');
            let first = value.split([' ', '`']).next().unwrap_or("");
            if flags.len() == 1 && first.starts_with(|c: char| c.is_ascii_digit()) {
                let flag = cells[1].trim_matches('`').split([' ', '`']).next().unwrap();
                let v = first.trim_end_matches([',', ';']);
                out.push((flag.trim_start_matches("--").to_string(), v.to_string()));
            }
            continue;
        }
        for span in line.split('`').skip(1).step_by(2) {
            let words: Vec<&str> = span.split_whitespace().collect();
            for w in words.windows(2) {
                if let Some(f) = w[0].strip_prefix("--") {
                    if !w[1].starts_with("--") {
                        out.push((f.to_string(), w[1].to_string()));
                    }
                }
            }
        }
    }
    out
}

/// Whether a page's value `claimed` states clap's default `actual` (numbers compared as
/// numbers, lists and names as text).
fn same_default(claimed: &str, actual: &str) -> bool {
    match (claimed.parse::<f64>(), actual.parse::<f64>()) {
        (Ok(a), Ok(b)) => a == b,
        _ => claimed == actual,
    }
}

/// Where a command page claims a flag's default, `--help` (clap) has the same default: the
/// pages cannot drift from the code. `equilibrate` shares `slide`'s page, which states
/// `slide`'s defaults.
#[test]
fn every_default_a_page_claims_is_the_help_default() {
    let mut checked = 0;
    let mut wrong = Vec::new();
    for sub in Cli::command().get_subcommands() {
        let name = sub.get_name();
        if name == "equilibrate" {
            continue;
        }
        for (flag, claimed) in claimed_defaults(&page(name)) {
            let Some(arg) = sub
                .get_arguments()
                .find(|a| a.get_long() == Some(flag.as_str()))
            else {
                continue;
            };
            let defaults: Vec<String> = arg
                .get_default_values()
                .iter()
                .map(|v| v.to_string_lossy().to_string())
                .collect();
            let Some(actual) = defaults.first() else {
                continue;
            };
            checked += 1;
            if !same_default(&claimed, actual) {
                wrong.push(format!(
                    "{name}.md: --{flag} {claimed}, but --help: {actual}"
                ));
            }
        }
    }
    assert!(checked >= 20, "only {checked} defaults found on the pages");
    assert!(
        wrong.is_empty(),
        "defaults on the command pages that --help contradicts:\n{}",
        wrong.join("\n")
    );
}
