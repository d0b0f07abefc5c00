//! The architecture rules of CONTRIBUTING.md ("The layers"), checked on the source tree:
//! - no import circle between the files of `src/study` nor of `surrogate/src/solver`;
//! - `src/study/rows` (the output rows, the bottom of the study layer) imports nothing else of
//!   `src/study`;
//! - no function over 100 lines in `src/study/design`, `src/study/tolerance` and
//!   `surrogate/src/solver`.
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

/// Groups of files of `src/study` allowed to import each other in a circle: none. A group added
/// here must hold every file of the circle, and a file on no circle any more fails the check, so
/// the list can only shrink.
const STUDY_CIRCLES_ALLOWED: &[&[&str]] = &[];

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

#[test]
fn no_import_circle_between_files_of_study() {
    let g = Graph::new("src", sources("src"));
    let problems = rules::circles(&g, |p| p.starts_with("src/study/"), STUDY_CIRCLES_ALLOWED);
    report("src/study: no import circle between files", problems);
}

#[test]
fn no_import_circle_between_files_of_the_solver() {
    let g = Graph::new("surrogate/src", sources("surrogate/src"));
    let problems = rules::circles(&g, |p| p.starts_with("surrogate/src/solver/"), &[]);
    report(
        "surrogate/src/solver: no import circle between files",
        problems,
    );
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
    let files: Vec<(String, String)> = [
        "src/study/design",
        "src/study/tolerance",
        "surrogate/src/solver",
    ]
    .iter()
    .flat_map(|d| sources(d))
    .map(|f| (f.path, f.code))
    .collect();
    let problems = rules::long_functions(&files, MAX_FUNCTION_LINES, LONG_FUNCTIONS_ALLOWED);
    report("no function over 100 lines", problems);
}
