//! The rules, each a function of the sources that returns what breaks it (empty: it holds):
//! no import circle between the files of a folder, no import from a folder to the rest of its
//! parent, no function longer than a limit. Each takes an allowlist of today's known
//! violations and also reports an entry that no longer violates (the list can only shrink).

use crate::graph::{Edge, Graph};
use crate::lex;
use std::collections::{BTreeMap, BTreeSet};

/// An allowed import edge: (importing file, imported file), paths as the graph's.
pub type AllowedEdge<'a> = (&'a str, &'a str);

/// Import circles between the files `scope` accepts: each strongly connected set of files (two
/// or more files that import each other, directly or not) that is not within one of the
/// `allowed` groups, written as one circle through it (`a.rs:12 → b.rs:30 → a.rs`) with every
/// import among its files; and each file of an allowed group that is on no circle any more.
pub fn circles(g: &Graph, scope: impl Fn(&str) -> bool, allowed: &[&[&str]]) -> Vec<String> {
    let edges: Vec<&Edge> = g.within(&scope).collect();
    let path = |i: usize| g.files[i].path.as_str();
    let mut out = Vec::new();
    let adj = adjacency(edges.iter().copied());
    let line: BTreeMap<(usize, usize), usize> =
        edges.iter().map(|e| ((e.from, e.to), e.line)).collect();
    let mut on_circle = BTreeSet::new();
    for comp in components(&adj) {
        if comp.len() < 2 {
            continue;
        }
        let files: BTreeSet<&str> = comp.iter().map(|&i| path(i)).collect();
        on_circle.extend(files.iter().map(|f| f.to_string()));
        if allowed
            .iter()
            .any(|grp| files.iter().all(|f| grp.contains(f)))
        {
            continue;
        }
        let cycle = cycle_in(&adj, &comp);
        let mut text = String::new();
        for w in cycle.windows(2) {
            text += &format!("{}:{} → ", path(w[0]), line[&(w[0], w[1])]);
        }
        text += path(cycle[0]);
        // every import among the circle's files: the ones to break it at
        let among: Vec<String> = edges
            .iter()
            .filter(|e| comp.contains(&e.from) && comp.contains(&e.to))
            .map(|e| format!("{}:{} → {}", path(e.from), e.line, path(e.to)))
            .collect();
        out.push(format!(
            "import circle: {text}\n    imports among its files:\n      {}",
            among.join("\n      ")
        ));
    }
    for group in allowed {
        for f in group.iter() {
            if !on_circle.contains(*f) {
                out.push(format!(
                    "allowlisted {f} is on no import circle any more: remove it"
                ));
            }
        }
    }
    out
}

/// Imports from the files under `folder` to the files that `outside` accepts, but the
/// `allowed` ones; and each allowed one that no longer exists.
pub fn imports_from(
    g: &Graph,
    folder: &str,
    outside: impl Fn(&str) -> bool,
    allowed: &[AllowedEdge],
) -> Vec<String> {
    let mut out = Vec::new();
    let mut seen = BTreeSet::new();
    for e in &g.edges {
        let (a, b) = (g.files[e.from].path.as_str(), g.files[e.to].path.as_str());
        if !a.starts_with(folder) || b.starts_with(folder) || !outside(b) {
            continue;
        }
        if allowed.contains(&(a, b)) {
            seen.insert((a, b));
            continue;
        }
        out.push(format!("{a}:{} imports {b}", e.line));
    }
    for &(a, b) in allowed {
        if !seen.contains(&(a, b)) {
            out.push(format!(
                "allowlisted import {a} → {b} no longer exists: remove it"
            ));
        }
    }
    out
}

/// A function of a file: its name, the line of `fn`, and its length in lines (from the `fn`
/// line to the closing brace).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Function {
    pub name: String,
    pub line: usize,
    pub lines: usize,
}

/// Every function with a body in `code` ([`lex::code`]), nested ones too (a nested function's
/// lines count in its parent's).
pub fn functions(code: &str) -> Vec<Function> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    let ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let mut from = 0;
    while let Some(k) = code[from..].find("fn") {
        let at = from + k;
        from = at + 2;
        if (at > 0 && ident(bytes[at - 1]))
            || !bytes.get(at + 2).is_some_and(|b| b.is_ascii_whitespace())
        {
            continue;
        }
        let rest = &code[at + 2..];
        let name: String = rest
            .trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if name.is_empty() {
            continue;
        }
        // the body: the first `{` before any `;` (none: a declaration without a body)
        let (open, semi) = (rest.find('{'), rest.find(';'));
        let Some(open) = open.filter(|o| semi.is_none_or(|s| s > *o)) else {
            continue;
        };
        let open = at + 2 + open;
        let Some(close) = lex::match_brace(code, open) else {
            continue;
        };
        let line = lex::line_of(code, at);
        out.push(Function {
            name,
            line,
            lines: lex::line_of(code, close) - line + 1,
        });
    }
    out
}

/// Functions over `limit` lines in `files` (path, code), but the `allowed` ones (path, name);
/// and each allowed one that is no longer over the limit.
pub fn long_functions(
    files: &[(String, String)],
    limit: usize,
    allowed: &[(&str, &str)],
) -> Vec<String> {
    let mut out = Vec::new();
    let mut seen = BTreeSet::new();
    for (path, code) in files {
        for f in functions(code) {
            if f.lines <= limit {
                continue;
            }
            if allowed.contains(&(path.as_str(), f.name.as_str())) {
                seen.insert((path.as_str(), f.name.clone()));
                continue;
            }
            out.push(format!(
                "{path}:{} fn {} is {} lines (at most {limit})",
                f.line, f.name, f.lines
            ));
        }
    }
    for &(path, name) in allowed {
        if !seen.contains(&(path, name.to_string())) {
            out.push(format!(
                "allowlisted fn {name} of {path} is no longer over {limit} lines: remove it"
            ));
        }
    }
    out
}

fn adjacency<'e>(edges: impl Iterator<Item = &'e Edge>) -> BTreeMap<usize, Vec<usize>> {
    let mut adj: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for e in edges {
        adj.entry(e.from).or_default().push(e.to);
        adj.entry(e.to).or_default();
    }
    adj
}

/// Whether `to` is reachable from `from`.
fn reaches(adj: &BTreeMap<usize, Vec<usize>>, from: usize, to: usize) -> bool {
    let mut seen = BTreeSet::from([from]);
    let mut stack = vec![from];
    while let Some(n) = stack.pop() {
        if n == to {
            return true;
        }
        for &m in adj.get(&n).into_iter().flatten() {
            if seen.insert(m) {
                stack.push(m);
            }
        }
    }
    false
}

/// The strongly connected components (mutual reachability; the graphs are small).
fn components(adj: &BTreeMap<usize, Vec<usize>>) -> Vec<Vec<usize>> {
    let mut done = BTreeSet::new();
    let mut out = Vec::new();
    for &n in adj.keys() {
        if done.contains(&n) {
            continue;
        }
        let comp: Vec<usize> = adj
            .keys()
            .copied()
            .filter(|&m| !done.contains(&m) && reaches(adj, n, m) && reaches(adj, m, n))
            .collect();
        done.extend(comp.iter().copied());
        out.push(comp);
    }
    out
}

/// One circle through the component `comp` (≥ 2 nodes), from its first node and back: the
/// shortest path back, breadth first.
fn cycle_in(adj: &BTreeMap<usize, Vec<usize>>, comp: &[usize]) -> Vec<usize> {
    let start = comp[0];
    let inside: BTreeSet<usize> = comp.iter().copied().collect();
    let mut prev: BTreeMap<usize, usize> = BTreeMap::new();
    let mut queue = std::collections::VecDeque::from([start]);
    while let Some(n) = queue.pop_front() {
        for &m in adj.get(&n).into_iter().flatten() {
            if m == start {
                let mut path = vec![n];
                while let Some(&p) = prev.get(path.last().expect("non-empty")) {
                    path.push(p);
                }
                path.reverse();
                if path[0] != start {
                    path.insert(0, start);
                }
                path.push(start);
                return path;
            }
            if inside.contains(&m) && m != start && !prev.contains_key(&m) {
                prev.insert(m, n);
                queue.push_back(m);
            }
        }
    }
    vec![start, start]
}
