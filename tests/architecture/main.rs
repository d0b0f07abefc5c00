//! The architecture rules of CONTRIBUTING.md ("The layers"), checked on the source tree:
//! - no import circle between the files of any crate (`src`, `surrogate/src`, `dem/src`);
//! - `src/study/rows` (the output rows, the bottom of the study layer) imports nothing else of
//!   `src/study`;
//! - no function over 100 lines in any crate.
//!
//! The import graph is file-level (`graph.rs`): a file depends on another where it names one of
//! its items through a `use` or a `crate::`/`super::`/`self::`/child-module path in its code,
//! re-exports followed to the file that defines the item. Comments, literals and `#[cfg(test)]`
//! modules are left out (`lex.rs`); so are `tests.rs` and `*_tests.rs` files. Today's known
//! violations are listed below; an entry that no longer violates fails the check too, so the
//! lists only shrink. `planted.rs` shows each rule failing on small in-memory sources.

mod graph;
mod lex;
mod planted;
mod rules;

use graph::{File, Graph};
use std::path::Path;

/// Groups of files allowed to import each other in a circle: none. A group added here must hold
/// every file of the circle, and a file on no circle any more fails the check, so the list can
/// only shrink.
const CIRCLES_ALLOWED: &[&[&str]] = &[];

/// Imports of the rest of `src/study` allowed to `src/study/rows`: none.
const ROWS_IMPORTS_ALLOWED: &[rules::AllowedEdge] = &[];

/// Functions allowed over [`MAX_FUNCTION_LINES`] (file, name): none.
const LONG_FUNCTIONS_ALLOWED: &[(&str, &str)] = &[];

/// The longest a function of the checked folders may be, in lines (`fn` to closing brace).
const MAX_FUNCTION_LINES: usize = 100;

/// The `.rs` files under `dir` (relative to the repository root), test files (`tests.rs`,
/// `*_tests.rs`) left out, in path order, with their code ([`lex::code`]).
fn sources(dir: &str) -> Vec<File> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = Vec::new();
    let mut stack = vec![root.join(dir)];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let p = entry.expect("a directory entry").path();
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if p.is_dir() {
                stack.push(p);
            } else if name.ends_with(".rs") && name != "tests.rs" && !name.ends_with("_tests.rs") {
                let text = std::fs::read_to_string(&p).expect("a source file");
                let rel = p.strip_prefix(root).expect("under the root");
                out.push(File {
                    path: rel.to_string_lossy().replace('\\', "/"),
                    code: lex::code(&text),
                });
            }
        }
    }
    out.sort_by(|a, b| a.path.cmp(&b.path));
    out
}

fn report(rule: &str, problems: Vec<String>) {
    assert!(
        problems.is_empty(),
        "{rule} (CONTRIBUTING.md, \"The layers\"):\n  {}",
        problems.join("\n  ")
    );
}

/// The source root of each crate of the workspace with more than one file: the library
/// `superlube` (`src`, its binary `src/main.rs` a crate of one file), `surrogate` and `dem`.
const CRATE_ROOTS: &[&str] = &["src", "surrogate/src", "dem/src"];

/// The sources of the crate under `root`: every file but the binary's `src/main.rs`, which is
/// a crate of its own (one file, no `mod`: it can close no circle; checked here).
fn crate_sources(root: &str) -> Vec<File> {
    let (bins, lib): (Vec<File>, Vec<File>) = sources(root)
        .into_iter()
        .partition(|f| f.path == format!("{root}/main.rs"));
    for bin in &bins {
        assert!(
            !bin.code.split_whitespace().any(|w| w == "mod"),
            "{} declares a module: check its crate for circles too",
            bin.path
        );
    }
    lib
}

/// The groups of [`CIRCLES_ALLOWED`] in the crate under `root` (each crate's graph is checked
/// on its own, so another crate's group is no stale entry of this one).
fn allowed_in(root: &str) -> Vec<&'static [&'static str]> {
    CIRCLES_ALLOWED
        .iter()
        .copied()
        .filter(|grp| grp.iter().all(|f| f.starts_with(&format!("{root}/"))))
        .collect()
}

#[test]
fn no_import_circle_in_any_crate() {
    let mut problems = Vec::new();
    for root in CRATE_ROOTS {
        let g = Graph::new(root, crate_sources(root));
        assert!(g.files.len() > 10, "{root}: the sources were read");
        problems.extend(rules::circles(&g, |_| true, &allowed_in(root)));
    }
    report("no import circle between the files of a crate", problems);
}

#[test]
fn rows_import_nothing_else_of_study() {
    let g = Graph::new("src", sources("src"));
    let problems = rules::imports_from(
        &g,
        "src/study/rows/",
        |p| p.starts_with("src/study/"),
        ROWS_IMPORTS_ALLOWED,
    );
    report(
        "src/study/rows: imports nothing else of src/study",
        problems,
    );
}

#[test]
fn no_function_over_100_lines() {
    let files: Vec<(String, String)> = CRATE_ROOTS
        .iter()
        .flat_map(|d| sources(d))
        .map(|f| (f.path, f.code))
        .collect();
    assert!(files.len() > 200, "the sources were read: {}", files.len());
    let problems = rules::long_functions(&files, MAX_FUNCTION_LINES, LONG_FUNCTIONS_ALLOWED);
    report("no function over 100 lines", problems);
}
