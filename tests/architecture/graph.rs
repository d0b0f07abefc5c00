//! The file-level import graph of one crate: file A depends on file B where A names an item of
//! B through a `use` or a path in its code (`crate::…`, `super::…`, `self::…`, or a child
//! module's name). Paths are resolved the way rustc does for these forms: a name re-exported by
//! a module (`pub use x::Y` in a `mod.rs`, also `pub use x::*`) leads to the file that
//! defines it, so a `mod.rs` that only declares and re-exports is no one's dependency; a
//! `pub use` is no edge of the file that holds it unless that file's own code names the
//! re-exported item too; `mod x;` is no edge.

use crate::lex;
use std::collections::{BTreeMap, BTreeSet};

/// One source file of a crate: its path (as given, e.g. `src/study/verdict.rs`) and its code
/// ([`lex::code`]: no comments, literals or test modules).
pub struct File {
    pub path: String,
    pub code: String,
}

/// One `use` leaf: the name it binds in its module (`None` for a glob), the path it names
/// (absolute, from the crate root), whether it is a re-export (`pub …`), and its line.
#[derive(Debug, Clone)]
struct Binding {
    name: Option<String>,
    target: Vec<String>,
    public: bool,
    line: usize,
}

/// An import edge: `from` names an item of `to` (file indices) at line `line` of `from`.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct Edge {
    pub from: usize,
    pub to: usize,
    pub line: usize,
}

/// A crate's files, modules and import edges.
pub struct Graph {
    pub files: Vec<File>,
    /// Module path (segments below the crate root) → file index.
    modules: BTreeMap<Vec<String>, usize>,
    /// Per file: its module path, its `use` bindings, the item names it defines.
    module_of: Vec<Vec<String>>,
    bindings: Vec<Vec<Binding>>,
    defines: Vec<BTreeSet<String>>,
    pub edges: Vec<Edge>,
}

/// The module path of a file below the crate's source root `root` (`src`): `lib.rs` and
/// `main.rs` are the root, `a/mod.rs` is `a`, `a/b.rs` is `a::b`. `None` outside `root`.
fn module_path(root: &str, path: &str) -> Option<Vec<String>> {
    let rel = path.strip_prefix(root)?.strip_prefix('/')?;
    let rel = rel.strip_suffix(".rs")?;
    let mut segs: Vec<String> = rel.split('/').map(str::to_string).collect();
    let last = segs.last().map(String::as_str);
    if matches!(last, Some("mod")) || (segs.len() == 1 && matches!(last, Some("lib" | "main"))) {
        segs.pop();
    }
    Some(segs)
}

fn is_ident_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// A `use` declaration: whether it is `pub` (any visibility), its tree (the text after `use`),
/// its line, and its byte range in the code (from `use` to before the `;`).
struct UseDecl {
    public: bool,
    tree: String,
    line: usize,
    range: std::ops::Range<usize>,
}

/// The `use` declarations of `code`.
fn use_decls(code: &str) -> Vec<UseDecl> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    let mut from = 0;
    while let Some(k) = code[from..].find("use") {
        let at = from + k;
        from = at + 3;
        let before_ok = at == 0 || !is_ident_char(code[..at].chars().last().unwrap_or(' '));
        let after_ok = bytes.get(at + 3).is_some_and(|b| b.is_ascii_whitespace());
        if !before_ok || !after_ok {
            continue;
        }
        let Some(end) = code[at..].find(';') else {
            continue;
        };
        // `pub`, `pub(crate)`, `pub(super)` between the statement's start and `use`
        let start = code[..at].rfind([';', '}', '{']).map_or(0, |p| p + 1);
        let public = code[start..at]
            .split(|c: char| !is_ident_char(c))
            .any(|w| w == "pub");
        out.push(UseDecl {
            public,
            tree: code[at + 3..at + end].to_string(),
            line: lex::line_of(code, at),
            range: at..at + end,
        });
        from = at + end;
    }
    out
}

/// The leaves of a use tree: (path segments, bound name; `None` name for `*`).
fn use_leaves(tree: &str) -> Vec<(Vec<String>, Option<String>)> {
    let tree: String = tree
        .chars()
        .filter(|c| !c.is_whitespace() || *c == ' ')
        .collect();
    let mut out = Vec::new();
    expand(&tree, &mut Vec::new(), &mut out);
    out
}

fn expand(tree: &str, prefix: &mut Vec<String>, out: &mut Vec<(Vec<String>, Option<String>)>) {
    let tree = tree.trim();
    if tree.is_empty() {
        return;
    }
    if let Some(open) = tree.find('{') {
        // `a::b::{…}`: split the group at its top-level commas
        let head = tree[..open].trim().trim_end_matches("::");
        let close = tree.rfind('}').unwrap_or(tree.len());
        let n = prefix.len();
        prefix.extend(
            head.split("::")
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .map(str::to_string),
        );
        let inner = &tree[open + 1..close];
        let mut depth = 0;
        let mut start = 0;
        for (k, ch) in inner.char_indices() {
            match ch {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    expand(&inner[start..k], prefix, out);
                    start = k + 1;
                }
                _ => {}
            }
        }
        expand(&inner[start..], prefix, out);
        prefix.truncate(n);
        return;
    }
    let (path, alias) = match tree.split_once(" as ") {
        Some((p, a)) => (p.trim(), Some(a.trim().to_string())),
        None => (tree, None),
    };
    let mut segs: Vec<String> = prefix.clone();
    segs.extend(
        path.split("::")
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .map(str::to_string),
    );
    match segs.last().map(String::as_str) {
        Some("*") => {
            segs.pop();
            out.push((segs, None));
        }
        Some("self") => {
            segs.pop();
            let name = alias.or_else(|| segs.last().cloned());
            out.push((segs, name));
        }
        Some(last) => {
            let name = alias.unwrap_or_else(|| last.to_string());
            out.push((segs, Some(name)));
        }
        None => {}
    }
}

/// Item names a file defines (functions, types, traits, constants, statics, macros), read
/// loosely: every `fn|struct|enum|trait|type|const|static|union NAME` and `macro_rules! NAME`.
fn defined_names(code: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let words: Vec<&str> = code
        .split(|c: char| !is_ident_char(c) && c != '!')
        .filter(|w| !w.is_empty())
        .collect();
    for w in words.windows(2) {
        if matches!(
            w[0],
            "fn" | "struct"
                | "enum"
                | "trait"
                | "type"
                | "const"
                | "static"
                | "union"
                | "macro_rules!"
        ) {
            out.insert(w[1].trim_end_matches('!').to_string());
        }
    }
    out
}

/// The identifiers of `code` outside its `use` declarations and module names (what a
/// re-exported name is looked up in: a file that re-exports a name and also uses it depends on
/// it).
fn names_outside_uses(code: &str) -> BTreeSet<String> {
    let mut text = code.to_string();
    for d in use_decls(code) {
        let blanked: String = text[d.range.clone()]
            .chars()
            .map(|c| if c == '\n' { '\n' } else { ' ' })
            .collect();
        text.replace_range(d.range, &blanked);
    }
    // (word, the character before it); a module's declaration (`mod law;`) names the module,
    // not the item re-exported from it, and `.map(…)` a method or field, not an item
    let mut words: Vec<(&str, char)> = Vec::new();
    let mut start = None;
    for (k, c) in text
        .char_indices()
        .chain(std::iter::once((text.len(), ' ')))
    {
        match (is_ident_char(c), start) {
            (true, None) => start = Some(k),
            (false, Some(s)) => {
                let before = text[..s].trim_end().chars().last().unwrap_or(' ');
                words.push((&text[s..k], before));
                start = None;
            }
            _ => {}
        }
    }
    words
        .iter()
        .enumerate()
        .filter(|&(k, &(_, before))| before != '.' && (k == 0 || words[k - 1].0 != "mod"))
        .map(|(_, (w, _))| w.to_string())
        .collect()
}

/// Paths written in code outside `use` declarations that start with `crate`, `super`, `self`
/// or a name in `firsts`: (segments, byte index).
fn code_paths(code: &str, firsts: &BTreeSet<String>) -> Vec<(Vec<String>, usize)> {
    // blank the use declarations (they are read as bindings)
    let mut text = code.to_string();
    for d in use_decls(code) {
        let blanked: String = text[d.range.clone()]
            .chars()
            .map(|c| if c == '\n' { '\n' } else { ' ' })
            .collect();
        text.replace_range(d.range, &blanked);
    }
    let mut out = Vec::new();
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let mut i = 0;
    while i < chars.len() {
        let (at, ch) = chars[i];
        let starts = is_ident_char(ch) && (i == 0 || !is_ident_char(chars[i - 1].1));
        if !starts || (i > 0 && chars[i - 1].1 == ':') {
            i += 1;
            continue;
        }
        // read `ident(::ident)*`
        let mut segs = Vec::new();
        let mut j = i;
        loop {
            let s = j;
            while j < chars.len() && is_ident_char(chars[j].1) {
                j += 1;
            }
            segs.push(chars[s..j].iter().map(|c| c.1).collect::<String>());
            let mut k = j;
            while k < chars.len() && chars[k].1 == ' ' {
                k += 1;
            }
            if k + 1 < chars.len() && chars[k].1 == ':' && chars[k + 1].1 == ':' {
                k += 2;
                while k < chars.len() && chars[k].1.is_whitespace() {
                    k += 1;
                }
                if k < chars.len() && is_ident_char(chars[k].1) {
                    j = k;
                    continue;
                }
            }
            break;
        }
        let first = segs[0].as_str();
        if segs.len() > 1 && (matches!(first, "crate" | "super" | "self") || firsts.contains(first))
        {
            out.push((segs, at));
        }
        i = j.max(i + 1);
    }
    out
}

impl Graph {
    /// The graph of the crate whose sources are `files`, under the source root `root` (`src`,
    /// `surrogate/src`). Files outside `root` are ignored.
    pub fn new(root: &str, files: Vec<File>) -> Graph {
        let files: Vec<File> = files
            .into_iter()
            .filter(|f| module_path(root, &f.path).is_some())
            .collect();
        let module_of: Vec<Vec<String>> = files
            .iter()
            .map(|f| module_path(root, &f.path).expect("under root"))
            .collect();
        let modules: BTreeMap<Vec<String>, usize> = module_of
            .iter()
            .enumerate()
            .map(|(i, m)| (m.clone(), i))
            .collect();
        let mut g = Graph {
            defines: files.iter().map(|f| defined_names(&f.code)).collect(),
            bindings: vec![Vec::new(); files.len()],
            files,
            modules,
            module_of,
            edges: Vec::new(),
        };
        for i in 0..g.files.len() {
            for d in use_decls(&g.files[i].code) {
                for (segs, name) in use_leaves(&d.tree) {
                    if let Some(target) = g.absolute(i, &segs) {
                        g.bindings[i].push(Binding {
                            name,
                            target,
                            public: d.public,
                            line: d.line,
                        });
                    }
                }
            }
        }
        let names_in_code: Vec<BTreeSet<String>> = g
            .files
            .iter()
            .map(|f| names_outside_uses(&f.code))
            .collect();
        let mut edges = BTreeSet::new();
        for (i, names) in names_in_code.iter().enumerate() {
            for b in &g.bindings[i] {
                // a re-export is no edge unless the file's own code names it too; a named module
                // is none either (the paths through it are); a glob is one to its module
                if b.name.is_some() && g.modules.contains_key(&b.target) {
                    continue;
                }
                if b.public && !b.name.as_ref().is_some_and(|n| names.contains(n)) {
                    continue;
                }
                if let Some(to) = g.resolve(&b.target, 0) {
                    if to != i {
                        edges.insert((i, to, b.line));
                    }
                }
            }
            let mut firsts = g.children(i);
            firsts.extend(g.bindings[i].iter().filter_map(|b| b.name.clone()));
            for (segs, at) in code_paths(&g.files[i].code, &firsts) {
                let Some(abs) = g.absolute(i, &segs) else {
                    continue;
                };
                if let Some(to) = g.resolve(&abs, 0) {
                    if to != i {
                        edges.insert((i, to, lex::line_of(&g.files[i].code, at)));
                    }
                }
            }
        }
        // one edge per pair of files, at its first line
        let mut first: BTreeMap<(usize, usize), usize> = BTreeMap::new();
        for (from, to, line) in edges {
            first.entry((from, to)).or_insert(line);
        }
        g.edges = first
            .into_iter()
            .map(|((from, to), line)| Edge { from, to, line })
            .collect();
        g
    }

    /// The names of the child modules (with a file) of file `i`'s module.
    fn children(&self, i: usize) -> BTreeSet<String> {
        let m = &self.module_of[i];
        self.modules
            .keys()
            .filter(|k| k.len() == m.len() + 1 && k.starts_with(m))
            .map(|k| k[m.len()].clone())
            .collect()
    }

    /// `segs` written in file `i` as an absolute module path, `None` for another crate's path.
    fn absolute(&self, i: usize, segs: &[String]) -> Option<Vec<String>> {
        let mut cur = self.module_of[i].clone();
        let mut rest = segs;
        match rest.first().map(String::as_str) {
            Some("crate") => {
                cur.clear();
                rest = &rest[1..];
            }
            Some("self") => rest = &rest[1..],
            Some("super") => {
                while rest.first().map(String::as_str) == Some("super") {
                    cur.pop();
                    rest = &rest[1..];
                }
            }
            Some(first) => {
                let mut child = cur.clone();
                child.push(first.to_string());
                if !self.modules.contains_key(&child) {
                    // a name this file's `use` binds (`use super::law;` then `law::f`)
                    let b = self.bindings[i]
                        .iter()
                        .find(|b| b.name.as_deref() == Some(first))?;
                    let mut t = b.target.clone();
                    t.extend(rest[1..].iter().cloned());
                    return Some(t);
                }
            }
            None => return None,
        }
        cur.extend(rest.iter().cloned());
        Some(cur)
    }

    /// The file that defines what the absolute path `abs` names: walk down the modules; at the
    /// first segment that is no module, follow the module's binding of that name (a `use`,
    /// re-exported or not), else a glob's module that defines it, else the module's own file.
    fn resolve(&self, abs: &[String], depth: usize) -> Option<usize> {
        let mut cur: Vec<String> = Vec::new();
        for (k, seg) in abs.iter().enumerate() {
            let mut next = cur.clone();
            next.push(seg.clone());
            if self.modules.contains_key(&next) {
                cur = next;
                continue;
            }
            let file = *self.modules.get(&cur)?;
            if depth < 16 {
                if let Some(b) = self.bindings[file]
                    .iter()
                    .find(|b| b.name.as_deref() == Some(seg))
                {
                    let mut t = b.target.clone();
                    t.extend(abs[k + 1..].iter().cloned());
                    return self.resolve(&t, depth + 1);
                }
                for b in self.bindings[file].iter().filter(|b| b.name.is_none()) {
                    if let Some(&g) = self.modules.get(&b.target) {
                        if self.defines[g].contains(seg) {
                            return Some(g);
                        }
                    }
                }
            }
            return Some(file);
        }
        self.modules.get(&cur).copied()
    }

    /// The edges between files whose paths `keep` accepts.
    pub fn within<'g>(
        &'g self,
        keep: impl Fn(&str) -> bool + 'g,
    ) -> impl Iterator<Item = &'g Edge> {
        self.edges
            .iter()
            .filter(move |e| keep(&self.files[e.from].path) && keep(&self.files[e.to].path))
    }
}
