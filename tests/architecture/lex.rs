//! Rust source reduced to its code: comments, string and character literals blanked and the
//! `#[cfg(test)]` modules cut out, line breaks kept (so line numbers stay those of the file).

/// `src` with every comment, string and character literal replaced by spaces (line breaks
/// kept), then every inline `#[cfg(test)] mod … { … }` blanked the same way. O(length).
pub fn code(src: &str) -> String {
    drop_test_modules(&blank_literals(src))
}

/// Comments (`//`, nested `/* */`), strings (`"…"`, `b"…"`, `r#"…"#`) and characters (`'x'`,
/// `'\n'`, not lifetimes) replaced by spaces, line breaks kept.
fn blank_literals(src: &str) -> String {
    let c: Vec<char> = src.chars().collect();
    let mut out: Vec<char> = Vec::with_capacity(c.len());
    let blank = |out: &mut Vec<char>, s: &[char]| {
        out.extend(s.iter().map(|&ch| if ch == '\n' { '\n' } else { ' ' }))
    };
    let ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut i = 0;
    while i < c.len() {
        let start = i;
        if c[i] == '/' && c.get(i + 1) == Some(&'/') {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if c[i] == '/' && c.get(i + 1) == Some(&'*') {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if (c[i] == 'r' || (c[i] == 'b' && c.get(i + 1) == Some(&'r')))
            && (i == 0 || !ident(c[i - 1]))
            && matches!(
                c.get(i + 1 + usize::from(c[i] == 'b')),
                Some('"') | Some('#')
            )
        {
            // raw string r#"…"#: find the quote, count the hashes
            let mut j = i + 1 + usize::from(c[i] == 'b');
            let mut hashes = 0;
            while c.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if c.get(j) != Some(&'"') {
                out.push(c[i]);
                i += 1;
                continue;
            }
            j += 1;
            loop {
                if j >= c.len() {
                    break;
                }
                if c[j] == '"' && (0..hashes).all(|k| c.get(j + 1 + k) == Some(&'#')) {
                    j += 1 + hashes;
                    break;
                }
                j += 1;
            }
            i = j;
        } else if c[i] == '"' {
            i += 1;
            while i < c.len() && c[i] != '"' {
                i += if c[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
        } else if c[i] == '\'' {
            // a character literal ('x', '\n', '\u{..}'), else a lifetime or label
            if c.get(i + 1) == Some(&'\\') {
                i += 2;
                while i < c.len() && c[i] != '\'' {
                    i += 1;
                }
                i += 1;
            } else if c.get(i + 2) == Some(&'\'') {
                i += 3;
            } else {
                out.push(c[i]);
                i += 1;
                continue;
            }
        } else {
            out.push(c[i]);
            i += 1;
            continue;
        }
        let end = i.min(c.len());
        blank(&mut out, &c[start..end]);
        i = end;
    }
    out.into_iter().collect()
}

/// Every `#[cfg(test)]` module with a body (`mod tests { … }`) blanked, line breaks kept.
fn drop_test_modules(code: &str) -> String {
    let mut out: Vec<char> = code.chars().collect();
    let text: String = out.iter().collect();
    let mut from = 0;
    while let Some(k) = text[from..].find("#[cfg(test)]") {
        let at = from + k;
        from = at + 1;
        let rest = &text[at + "#[cfg(test)]".len()..];
        let words: Vec<&str> = rest.split_whitespace().take(4).collect();
        let is_mod = match words.as_slice() {
            [w, ..] if *w == "mod" => true,
            [p, w, ..] if p.starts_with("pub") && *w == "mod" => true,
            _ => false,
        };
        if !is_mod {
            continue;
        }
        // the body: from the first `{` before any `;`
        let (Some(open), semi) = (rest.find('{'), rest.find(';')) else {
            continue;
        };
        if semi.is_some_and(|s| s < open) {
            continue;
        }
        let open = at + "#[cfg(test)]".len() + open;
        let close = match_brace(&text, open).unwrap_or(text.len() - 1);
        // char indices equal byte indices only for ASCII; map through char offsets
        let a = text[..at].chars().count();
        let b = text[..=close].chars().count();
        for ch in &mut out[a..b] {
            if *ch != '\n' {
                *ch = ' ';
            }
        }
        from = close;
    }
    out.into_iter().collect()
}

/// The byte index of the `}` that closes the `{` at byte `open` of `code` (literals and
/// comments already blanked).
pub fn match_brace(code: &str, open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (k, ch) in code[open..].char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(open + k);
                }
            }
            _ => {}
        }
    }
    None
}

/// The 1-based line of byte index `at` of `code`.
pub fn line_of(code: &str, at: usize) -> usize {
    code[..at].matches('\n').count() + 1
}
