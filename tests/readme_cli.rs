//! The README's worked examples run as written, so the guide cannot drift from the tool.
//!
//! Every fenced block opened with ```` ```sh quick ```` in README.md is run line by line in one
//! scratch folder (in order: later lines may read earlier outputs), with `superlube` replaced by
//! the binary under test. Each command must succeed, and every file the README names after an
//! output flag (`--out`, `--plot`, `--json`) must exist afterwards.

mod common;
use common::{assert_ok, bin, tmpdir};

/// The commands of the README's `sh quick` blocks, comments and blank lines dropped.
fn quick_commands(readme: &str) -> Vec<String> {
    let mut cmds = Vec::new();
    let mut inside = false;
    for line in readme.lines() {
        let t = line.trim();
        if !inside && t.starts_with("```sh quick") {
            inside = true;
        } else if inside && t.starts_with("```") {
            inside = false;
        } else if inside {
            let code = t.split(" #").next().unwrap().trim();
            if !code.is_empty() && !code.starts_with('#') {
                cmds.push(code.to_string());
            }
        }
    }
    cmds
}

#[test]
fn readme_quick_examples_run() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let cmds = quick_commands(&readme);
    assert!(
        cmds.len() >= 8,
        "README.md has {} `sh quick` commands: the worked examples are gone",
        cmds.len()
    );
    let dir = tmpdir("readme");
    for cmd in &cmds {
        let words: Vec<&str> = cmd.split_whitespace().collect();
        assert_eq!(
            words[0], "superlube",
            "a quick block runs only superlube: `{cmd}`"
        );
        assert!(
            !cmd.contains(['\\', '|', '>', '<', '&', ';', '$']),
            "quick commands are plain argument lists: `{cmd}`"
        );
        let out = bin().args(&words[1..]).current_dir(&dir).output().unwrap();
        assert_ok(&out);
        // each tier's example shows what the tier is for: the DEM example slides
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            !err.contains("LOCKED IN"),
            "`{cmd}` reads as a failure: {err}"
        );
        for w in words.windows(2) {
            if ["--out", "--plot", "--json"].contains(&w[0]) {
                assert!(dir.join(w[1]).exists(), "`{cmd}` did not write {}", w[1]);
            }
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}
