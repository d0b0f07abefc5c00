//! Each rule fails on a planted violation in small in-memory sources, and holds on the same
//! sources without it.

use crate::graph::{File, Graph};
use crate::{lex, rules};

/// A crate under `src` made of `(path, source)` files.
fn graph(files: &[(&str, &str)]) -> Graph {
    let files = files
        .iter()
        .map(|(p, s)| File {
            path: p.to_string(),
            code: lex::code(s),
        })
        .collect();
    Graph::new("src", files)
}

fn study_circles(files: &[(&str, &str)], allowed: &[&[&str]]) -> Vec<String> {
    rules::circles(&graph(files), |p| p.starts_with("src/study/"), allowed)
}

const STUDY: (&str, &str) = (
    "src/study/mod.rs",
    "mod a;\nmod b;\npub use a::A;\npub use b::B;\n",
);

#[test]
fn a_circle_of_two_uses_is_found() {
    let a = ("src/study/a.rs", "use super::b::B;\npub struct A(B);\n");
    let b = (
        "src/study/b.rs",
        "use crate::study::a::A;\npub struct B;\nfn f(_: A) {}\n",
    );
    let found = study_circles(&[STUDY, a, b], &[]);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        found[0].contains("src/study/a.rs:1 → src/study/b.rs:1 → src/study/a.rs"),
        "{found:?}"
    );
    // one way only: no circle
    let b = ("src/study/b.rs", "pub struct B;\n");
    assert!(study_circles(&[STUDY, a, b], &[]).is_empty());
}

#[test]
fn re_exports_lead_to_the_defining_file() {
    // `super::B` is b.rs's (re-exported by mod.rs): a circle a ↔ b, none through mod.rs
    let a = ("src/study/a.rs", "use super::B;\npub struct A(B);\n");
    let b = (
        "src/study/b.rs",
        "use super::{A, a};\npub struct B;\nfn f(_: A) {}\n",
    );
    let found = study_circles(&[STUDY, a, b], &[]);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(!found[0].contains("mod.rs"), "{found:?}");
    // a mod.rs that declares and re-exports is no one's dependency
    let b = ("src/study/b.rs", "pub struct B;\n");
    assert!(study_circles(&[STUDY, a, b], &[]).is_empty());
    // but a mod.rs whose code calls a child, and a child that uses the mod.rs's own item, are
    let m = (
        "src/study/mod.rs",
        "mod a;\npub struct M;\nfn run() { a::go(); }\n",
    );
    let a = ("src/study/a.rs", "pub fn go() { let _ = super::M; }\n");
    assert_eq!(study_circles(&[m, a], &[]).len(), 1);
}

#[test]
fn paths_in_code_and_child_modules_count() {
    // an inline `super::b::f()` is an import; so is a child module's path `k::take()`
    let a = ("src/study/a.rs", "pub fn g() { super::b::f(); }\n");
    let b = (
        "src/study/b.rs",
        "use super::a::g;\npub fn f() {}\nfn h() { g() }\n",
    );
    assert_eq!(study_circles(&[STUDY, a, b], &[]).len(), 1);
    let p = (
        "src/study/p.rs",
        "mod k;\npub struct P;\nfn f() { k::take(); }\n",
    );
    let k = ("src/study/p/k.rs", "use super::P;\npub fn take() {}\n");
    let m = ("src/study/mod.rs", "mod p;\n");
    assert_eq!(study_circles(&[m, p, k], &[]).len(), 1);
    // `use super::law;` then `law::f()` reaches law.rs
    let x = (
        "src/study/x.rs",
        "use super::law;\npub fn g() { law::f(); }\n",
    );
    let law = ("src/study/law.rs", "use super::x::g;\npub fn f() {}\n");
    let m = ("src/study/mod.rs", "mod law;\nmod x;\n");
    assert_eq!(study_circles(&[m, x, law], &[]).len(), 1);
}

#[test]
fn comments_literals_and_test_modules_are_no_imports() {
    let a = (
        "src/study/a.rs",
        "// use super::b::B;\n/* super::b::f() */\nconst S: &str = \"super::b::f()\";\n\
         #[cfg(test)]\nmod tests {\n    use super::super::b::B;\n}\n",
    );
    let b = ("src/study/b.rs", "use super::a::S;\npub struct B;\n");
    assert!(study_circles(&[STUDY, a, b], &[]).is_empty());
}

#[test]
fn the_circle_allowlist_only_shrinks() {
    let a = ("src/study/a.rs", "use super::b::B;\npub struct A(B);\n");
    let b = (
        "src/study/b.rs",
        "use super::a::A;\npub struct B;\nfn f(_: A) {}\n",
    );
    let c = ("src/study/c.rs", "use super::a::A;\npub struct C;\n");
    let m = ("src/study/mod.rs", "mod a;\nmod b;\nmod c;\n");
    let group: &[&str] = &["src/study/a.rs", "src/study/b.rs"];
    assert!(study_circles(&[m, a, b, c], &[group]).is_empty());
    // a file outside the group joins the circle: found
    let a3 = (
        "src/study/a.rs",
        "use super::{b::B, c::C};\npub struct A(B, C);\n",
    );
    let c3 = (
        "src/study/c.rs",
        "use super::a::A;\npub struct C;\nfn f(_: A) {}\n",
    );
    let found = study_circles(&[m, a3, b, c3], &[group]);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].starts_with("import circle"), "{found:?}");
    // the circle broken (a no longer imports b): both entries are stale
    let a2 = ("src/study/a.rs", "pub struct A;\n");
    let found = study_circles(&[m, a2, b, c], &[group]);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(
        found.iter().all(|f| f.contains("on no import circle")),
        "{found:?}"
    );
}

#[test]
fn rows_importing_the_rest_of_study_is_found() {
    let files = [
        ("src/study/mod.rs", "mod rows;\nmod verdict;\n"),
        ("src/study/rows/mod.rs", "mod friction;\nmod format;\n"),
        (
            "src/study/rows/friction.rs",
            "use super::format::f;\npub struct Row { v: crate::study::verdict::Verdict }\n",
        ),
        ("src/study/rows/format.rs", "pub fn f() {}\n"),
        ("src/study/verdict.rs", "pub struct Verdict;\n"),
    ];
    let check = |allowed: &[rules::AllowedEdge]| {
        rules::imports_from(
            &graph(&files),
            "src/study/rows/",
            |p| p.starts_with("src/study/"),
            allowed,
        )
    };
    let found = check(&[]);
    assert_eq!(
        found,
        ["src/study/rows/friction.rs:2 imports src/study/verdict.rs"]
    );
    assert!(check(&[("src/study/rows/friction.rs", "src/study/verdict.rs")]).is_empty());
    let stale = check(&[
        ("src/study/rows/friction.rs", "src/study/verdict.rs"),
        ("src/study/rows/format.rs", "src/study/verdict.rs"),
    ]);
    assert_eq!(stale.len(), 1, "{stale:?}");
}

/// A function `name` of `body_lines` lines between its `fn` line and its closing brace.
fn function(name: &str, body_lines: usize) -> String {
    let mut s = format!("pub fn {name}(x: &str) -> usize {{\n");
    for k in 0..body_lines {
        // braces in literals and comments do not count
        s += &format!("    let _ = \"{{ {k}\"; // }}\n");
    }
    s + "    0\n}\n"
}

#[test]
fn a_function_over_the_limit_is_found() {
    // 98 body lines + `0` + the `fn` and `}` lines: 101
    let long = function("long", 98);
    let fine = function("fine", 97);
    let files = vec![(
        "src/study/design/x.rs".to_string(),
        lex::code(&format!("{fine}{long}")),
    )];
    let found = rules::long_functions(&files, 100, &[]);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("fn long is 101 lines"), "{found:?}");
    assert!(rules::long_functions(&files, 100, &[("src/study/design/x.rs", "long")]).is_empty());
    let stale = rules::long_functions(&files, 100, &[("src/study/design/x.rs", "fine")]);
    assert_eq!(stale.len(), 2, "{stale:?}");
    // a closure inside counts in its function's lines; test modules do not count
    let inner = format!(
        "fn outer() {{\n    let c = || {{\n{}    }};\n}}\n",
        "        1;\n".repeat(100)
    );
    let tests = format!("#[cfg(test)]\nmod tests {{\n{}}}\n", function("t", 200));
    let files = vec![(
        "src/study/design/y.rs".to_string(),
        lex::code(&format!("{inner}{tests}")),
    )];
    let found = rules::long_functions(&files, 100, &[]);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("fn outer"), "{found:?}");
}

/// The crate at `root` made of `(path, source)` files, every file in scope.
fn crate_circles(root: &str, files: &[(&str, &str)]) -> Vec<String> {
    let files = files
        .iter()
        .map(|(p, s)| File {
            path: p.to_string(),
            code: lex::code(s),
        })
        .collect();
    rules::circles(&Graph::new(root, files), |_| true, &[])
}

#[test]
fn a_circle_anywhere_in_any_crate_is_found() {
    // two sibling files of the DEM crate's model (the friction law and a law using it)
    let m = (
        "dem/src/model/mod.rs",
        "mod constant;\nmod friction;\npub use constant::Constant;\npub use friction::Law;\n",
    );
    let law = (
        "dem/src/model/friction.rs",
        "use super::Constant;\npub trait Law {}\npub enum F { C(Constant) }\n",
    );
    let constant = (
        "dem/src/model/constant.rs",
        "use super::Law;\npub struct Constant;\nimpl Law for Constant {}\n",
    );
    let lib = ("dem/src/lib.rs", "pub mod model;\n");
    let found = crate_circles("dem/src", &[lib, m, law, constant]);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("dem/src/model/friction.rs"), "{found:?}");
    // the trait in a file of its own: no circle
    let law = (
        "dem/src/model/friction.rs",
        "use super::Constant;\npub enum F { C(Constant) }\n",
    );
    let trait_file = ("dem/src/model/law.rs", "pub trait Law {}\n");
    let m = (
        "dem/src/model/mod.rs",
        "mod constant;\nmod friction;\nmod law;\npub use constant::Constant;\npub use law::Law;\n",
    );
    assert!(crate_circles("dem/src", &[lib, m, law, trait_file, constant]).is_empty());
}

#[test]
fn a_re_export_that_its_own_file_uses_is_an_import() {
    // deck/mod.rs re-exports `Part` and names it in its own struct; part.rs uses mod.rs's `N`
    let m = (
        "src/deck/mod.rs",
        "mod part;\npub use part::Part;\npub struct Inputs { pub part: Part }\npub struct N;\n",
    );
    let part = (
        "src/deck/part.rs",
        "use super::N;\npub struct Part;\nfn f(_: N) {}\n",
    );
    let lib = ("src/lib.rs", "mod deck;\n");
    let found = crate_circles("src", &[lib, m, part]);
    assert_eq!(found.len(), 1, "{found:?}");
    // only re-exported, not used by mod.rs's code: no import, no circle; nor is a module
    // declaration of the same name (`mod part; pub use part::part;`) or a method `.part()`
    let m = (
        "src/deck/mod.rs",
        "mod part;\npub use part::{part, Part};\npub struct N;\nfn g(x: &X) { x.part(); }\n",
    );
    assert!(crate_circles("src", &[lib, m, part]).is_empty());
}

#[test]
fn the_length_rule_holds_every_crate() {
    let long = lex::code(&function("long", 120));
    let files: Vec<(String, String)> = [
        "surrogate/src/friction/estimate.rs",
        "dem/src/integrator/step.rs",
        "src/plot/heat_map.rs",
        "src/study/design/pipeline/mod.rs",
    ]
    .iter()
    .map(|p| (p.to_string(), long.clone()))
    .collect();
    let found = rules::long_functions(&files, 100, &[]);
    assert_eq!(found.len(), 4, "{found:?}");
}
