//! The source reader behind tests/architecture.rs: a token scanner that skips comments and
//! literals, the paths a file names (`crate::`, `super::`, `self::` and its declared child
//! modules), and the module path of each file under `src/`.

use std::path::{Path, PathBuf};

pub mod graph;

/// One path found in a file, resolved to an absolute module path.
#[derive(Debug, Clone, PartialEq)]
pub struct Use {
    /// The path as written (`crate::geometry::shape::check`).
    pub written: String,
    /// Its segments from the crate root (`["geometry", "shape", "check"]`).
    pub absolute: Vec<String>,
    /// 1-based line.
    pub line: usize,
}

#[derive(Debug, Clone, PartialEq)]
struct Token {
    text: String,
    line: usize,
}

/// Identifiers, `::` and single punctuation characters, without comments, strings and chars.
fn tokens(src: &str) -> Vec<Token> {
    let b = src.as_bytes();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 1);
    while i < b.len() {
        let c = b[i];
        let next = b.get(i + 1).copied().unwrap_or(0);
        match c {
            b'\n' => {
                line += 1;
                i += 1;
            }
            b'/' if next == b'/' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if next == b'*' => {
                let mut depth = 0;
                while i < b.len() {
                    if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
                        depth += 1;
                        i += 2;
                    } else if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                        depth -= 1;
                        i += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        line += usize::from(b[i] == b'\n');
                        i += 1;
                    }
                }
            }
            b'"' => i = skip_string(b, i + 1, 0, &mut line),
            b'r' | b'b' if is_raw_string(b, i) => {
                let mut j = i + 1 + usize::from(c == b'b' && next == b'r');
                let mut hashes = 0;
                while b[j] == b'#' {
                    hashes += 1;
                    j += 1;
                }
                i = skip_string(b, j + 1, hashes, &mut line);
            }
            b'b' if next == b'"' => i = skip_string(b, i + 2, 0, &mut line),
            b'\'' => {
                // A char literal ('a', '\n', '\u{1F600}') or a lifetime ('a).
                if next == b'\\' {
                    i += 2;
                    while i < b.len() && b[i] != b'\'' {
                        i += 1;
                    }
                    i += 1;
                } else {
                    let len = src[i + 1..].chars().next().map_or(1, char::len_utf8);
                    i += if b.get(i + 1 + len) == Some(&b'\'') {
                        len + 2
                    } else {
                        1
                    };
                }
            }
            _ if c == b'_' || c.is_ascii_alphabetic() => {
                let start = i;
                while i < b.len() && (b[i] == b'_' || b[i].is_ascii_alphanumeric()) {
                    i += 1;
                }
                out.push(Token {
                    text: src[start..i].to_string(),
                    line,
                });
            }
            b':' if next == b':' => {
                out.push(Token {
                    text: "::".into(),
                    line,
                });
                i += 2;
            }
            _ if c.is_ascii_whitespace() || c.is_ascii_digit() || c >= 0x80 => i += 1,
            _ => {
                out.push(Token {
                    text: (c as char).to_string(),
                    line,
                });
                i += 1;
            }
        }
    }
    out
}

fn is_raw_string(b: &[u8], i: usize) -> bool {
    let j = if b[i] == b'b' && b.get(i + 1) == Some(&b'r') {
        i + 2
    } else if b[i] == b'r' {
        i + 1
    } else {
        return false;
    };
    // Not part of an identifier such as `for` or `br_x`.
    if i > 0 && (b[i - 1] == b'_' || b[i - 1].is_ascii_alphanumeric()) {
        return false;
    }
    let mut k = j;
    while b.get(k) == Some(&b'#') {
        k += 1;
    }
    b.get(k) == Some(&b'"')
}

/// The index after a string whose body starts at `i` and ends with `"` and `hashes` `#`s.
fn skip_string(b: &[u8], mut i: usize, hashes: usize, line: &mut usize) -> usize {
    while i < b.len() {
        match b[i] {
            b'\\' if hashes == 0 => i += 2,
            b'"' if b[i + 1..]
                .iter()
                .take(hashes)
                .filter(|&&c| c == b'#')
                .count()
                == hashes =>
            {
                return i + 1 + hashes;
            }
            c => {
                *line += usize::from(c == b'\n');
                i += 1;
            }
        }
    }
    i
}

/// Every `crate::`, `super::` and `self::` path of a file whose module path is `module`, and
/// every path through a child module the file declares (`mod shading;` … `shading::Ctx`).
pub fn uses(src: &str, module: &[String]) -> Vec<Use> {
    let toks = tokens(src);
    let children = child_modules(&toks);
    let mut out = Vec::new();
    // Inline modules: (name, brace depth inside them).
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0;
    let mut i = 0;
    while i < toks.len() {
        let t = toks[i].text.as_str();
        match t {
            "{" => depth += 1,
            "}" => {
                depth -= 1;
                while inline.last().is_some_and(|(_, d)| *d > depth) {
                    inline.pop();
                }
            }
            "mod" if toks.get(i + 2).is_some_and(|t| t.text == "{") => {
                inline.push((toks[i + 1].text.clone(), depth + 1));
            }
            _ if (matches!(t, "crate" | "super" | "self")
                || (inline.is_empty() && children.iter().any(|c| c == t)))
                && toks.get(i + 1).is_some_and(|t| t.text == "::")
                && (i == 0 || toks[i - 1].text != "::") =>
            {
                let mut here: Vec<String> = module.to_vec();
                here.extend(inline.iter().map(|(n, _)| n.clone()));
                let mut paths = Vec::new();
                let end = tree(&toks, i, Vec::new(), &mut paths);
                for p in paths {
                    out.push(Use {
                        written: p.join("::"),
                        absolute: resolve(&p, &here),
                        line: toks[i].line,
                    });
                }
                i = end;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    out
}

/// The modules a file declares in files of their own (`mod x;`, `pub(crate) mod x;`).
fn child_modules(toks: &[Token]) -> Vec<String> {
    let mut depth = 0usize;
    let mut out = Vec::new();
    for (i, t) in toks.iter().enumerate() {
        match t.text.as_str() {
            "{" => depth += 1,
            "}" => depth = depth.saturating_sub(1),
            "mod" if depth == 0 && toks.get(i + 2).is_some_and(|t| t.text == ";") => {
                out.push(toks[i + 1].text.clone());
            }
            _ => {}
        }
    }
    out
}

/// Parses a use tree starting at `i` (segments, `::`, `{ a, b::{c, d} }`, `*`, `self`),
/// appending each complete path after `prefix` to `out`; returns the index after it.
fn tree(
    toks: &[Token],
    mut i: usize,
    mut prefix: Vec<String>,
    out: &mut Vec<Vec<String>>,
) -> usize {
    loop {
        let Some(t) = toks.get(i) else {
            out.push(prefix);
            return i;
        };
        match t.text.as_str() {
            "{" => {
                i += 1;
                loop {
                    match toks.get(i).map(|t| t.text.as_str()) {
                        None => return i,
                        Some("}") => return i + 1,
                        Some(",") => i += 1,
                        Some("self") => {
                            out.push(prefix.clone());
                            i += 1;
                        }
                        Some(_) => i = tree(toks, i, prefix.clone(), out),
                    }
                }
            }
            "*" => {
                out.push(prefix);
                return i + 1;
            }
            s if s == "_"
                || s.chars()
                    .next()
                    .is_some_and(|c| c.is_alphabetic() || c == '_') =>
            {
                prefix.push(s.to_string());
                i += 1;
                if toks.get(i).is_some_and(|t| t.text == "::") {
                    i += 1;
                } else {
                    out.push(prefix);
                    return i;
                }
            }
            _ => {
                out.push(prefix);
                return i;
            }
        }
    }
}

/// A path as written, from the crate root.
fn resolve(path: &[String], here: &[String]) -> Vec<String> {
    let mut base: Vec<String> = here.to_vec();
    let mut rest = path;
    match rest.first().map(String::as_str) {
        Some("crate") => {
            base.clear();
            rest = &rest[1..];
        }
        Some("super") => {
            while rest.first().is_some_and(|s| s == "super") {
                base.pop();
                rest = &rest[1..];
            }
        }
        _ => {}
    }
    base.extend(rest.iter().filter(|s| *s != "self").cloned());
    base
}

/// The module path of a library file (`src/eval/builtins/mod.rs` → `eval::builtins`).
pub fn module_of(file: &Path, src: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).expect("under src");
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().unwrap_or_default();
    let stem = last.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        parts.push(stem.to_string());
    }
    parts
}

pub fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("read src")
        .map(|e| e.expect("entry").path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}
