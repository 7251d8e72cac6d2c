//! The architecture test: every `crate::` and `super::` path in `src/` (in `use` items, grouped
//! `use` lists at any depth, `pub use` re-exports and inline paths in code) is resolved to the
//! top-level module it names, and each top-level module may only use the modules of its row in
//! [`ALLOWED`] (docs/architecture.md has the same table, with the reasons). Comments and string
//! literals are skipped; `super::` inside an inline `mod tests { ... }` resolves to the file's
//! own module. The binary (`src/main.rs`, `src/cli/`) may use everything and is used by nothing.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Leaves every module may use.
const LEAVES: &[&str] = &["diag", "source", "num"];

/// Who may import whom (besides the leaves). A new top-level module gets its row here first.
const ALLOWED: &[(&str, &[&str])] = &[
    ("source", &[]),
    ("diag", &[]),
    ("num", &[]),
    ("syntax", &[]),
    ("ir", &[]),
    ("assets", &["ir"]),
    ("eval", &["syntax", "ir", "assets", "geometry"]),
    ("compat", &["ir", "assets"]),
    ("geometry", &["ir"]),
    ("opt", &["ir", "geometry", "assets"]),
    ("render", &["opt", "geometry", "ir"]),
    ("check", &["ir", "opt", "geometry"]),
    ("loader", &["eval", "compat", "ir"]),
    ("metrics", &[]),
    ("accuracy", &["ir", "opt", "render", "metrics"]),
];

/// Narrower rules inside an allowed edge: `(module, target, the only paths under target it may
/// use)`. Evaluation asks geometry what a shape is (its validity and bounds), never anything
/// that builds or traces.
const ONLY: &[(&str, &str, &[&str])] = &[("eval", "geometry", &["shape", "csg", "aabb", "Aabb"])];

/// Items a module may not name although it may use their module: `(module, path)`. The
/// renderer reads the prepared scene, never the IR's shapes.
const FORBIDDEN: &[(&str, &[&str])] = &[("render", &["ir", "Shape"])];

/// One path found in a file, resolved to an absolute module path.
#[derive(Debug, Clone, PartialEq)]
struct Use {
    /// The path as written (`crate::geometry::shape::check`).
    written: String,
    /// Its segments from the crate root (`["geometry", "shape", "check"]`).
    absolute: Vec<String>,
    /// 1-based line.
    line: usize,
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

/// Every `crate::`/`super::` path of a file whose module path is `module`.
fn uses(src: &str, module: &[String]) -> Vec<Use> {
    let toks = tokens(src);
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
            "crate" | "super"
                if toks.get(i + 1).is_some_and(|t| t.text == "::")
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
fn module_of(file: &Path, src: &Path) -> Vec<String> {
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

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
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

/// Why `from` may not use `u`, if it may not.
fn violation(from: &str, u: &Use) -> Option<String> {
    let target = u.absolute.first()?.as_str();
    if target == from || LEAVES.contains(&target) {
        return forbidden(from, u);
    }
    let Some((_, allowed)) = ALLOWED.iter().find(|(m, _)| *m == from) else {
        return Some(format!(
            "module `{from}` has no row in the allowed-imports table; add it first"
        ));
    };
    if !allowed.contains(&target) {
        return Some(format!(
            "module `{from}` may not import `{target}` (allowed: {})",
            allowed
                .iter()
                .chain(LEAVES)
                .copied()
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    if let Some((_, _, only)) = ONLY.iter().find(|(m, t, _)| *m == from && *t == target) {
        let under = u.absolute.get(1).map(String::as_str).unwrap_or("");
        if !only.contains(&under) {
            return Some(format!(
                "module `{from}` may use only `{target}::{{{}}}`",
                only.join(", ")
            ));
        }
    }
    forbidden(from, u)
}

fn forbidden(from: &str, u: &Use) -> Option<String> {
    FORBIDDEN
        .iter()
        .find(|(m, path)| {
            *m == from
                && u.absolute
                    .starts_with(&path.iter().map(|s| s.to_string()).collect::<Vec<_>>())
        })
        .map(|(_, path)| format!("module `{from}` may not name `{}`", path.join("::")))
}

#[test]
fn every_module_imports_only_what_its_row_allows() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let src = root.join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut problems = Vec::new();
    let mut seen = 0;
    let mut modules = BTreeSet::new();
    for file in &files {
        let rel = file
            .strip_prefix(root)
            .unwrap_or(file)
            .display()
            .to_string();
        if rel == "src/main.rs" || rel.starts_with("src/cli/") {
            continue; // the binary: uses everything through `rtc::`
        }
        let module = module_of(file, &src);
        let Some(top) = module.first().cloned() else {
            continue; // lib.rs: the module list
        };
        modules.insert(top.clone());
        let text = std::fs::read_to_string(file).expect("read source");
        for u in uses(&text, &module) {
            seen += 1;
            if u.absolute.first().is_some_and(|t| t == "cli") {
                problems.push(format!(
                    "{rel}:{}: `{}`: nothing imports the CLI",
                    u.line, u.written
                ));
            } else if let Some(why) = violation(&top, &u) {
                problems.push(format!("{rel}:{}: `{}`: {why}", u.line, u.written));
            }
        }
    }
    assert!(seen > 300, "only {seen} paths found: is the parser broken?");
    for m in &modules {
        assert!(
            ALLOWED.iter().any(|(a, _)| a == m),
            "top-level module `{m}` has no row in the allowed-imports table"
        );
    }
    assert!(
        problems.is_empty(),
        "{} forbidden import(s):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn the_allowed_table_has_no_cycles() {
    // Depth-first search over the allowed edges.
    fn visit(m: &str, stack: &mut Vec<String>) -> Result<(), String> {
        if let Some(at) = stack.iter().position(|s| s == m) {
            return Err(format!("{} -> {m}", stack[at..].join(" -> ")));
        }
        stack.push(m.to_string());
        let next = ALLOWED
            .iter()
            .find(|(a, _)| *a == m)
            .map_or(&[][..], |(_, b)| *b);
        for n in next {
            visit(n, stack)?;
        }
        stack.pop();
        Ok(())
    }
    for (m, _) in ALLOWED {
        visit(m, &mut Vec::new()).unwrap_or_else(|cycle| panic!("cycle: {cycle}"));
    }
}

#[test]
fn the_parser_finds_grouped_inline_and_reexported_paths() {
    let src = r#"
        use crate::geometry::{Aabb, shape::{self, check}, csg::*};
        pub use super::film::{Channel, Stats};
        // use crate::render::Not; a comment is no import
        /* crate::render::NotEither */
        fn f() -> u32 { let s = "crate::render::NorAString"; crate::opt::prepare(x); 'a' as u32 }
        fn g<'a>(x: &'a str) { super::super::ir::Shape::Sphere; }
        pub(crate) fn h() {}
        mod tests {
            use super::*;
            use super::inner::thing;
        }
        use crate::assets;
    "#;
    let module = vec!["render".to_string(), "texture".to_string()];
    let got: Vec<(String, String)> = uses(src, &module)
        .into_iter()
        .map(|u| (u.written, u.absolute.join("::")))
        .collect();
    let want = [
        ("crate::geometry::Aabb", "geometry::Aabb"),
        ("crate::geometry::shape", "geometry::shape"),
        ("crate::geometry::shape::check", "geometry::shape::check"),
        ("crate::geometry::csg", "geometry::csg"),
        ("super::film::Channel", "render::film::Channel"),
        ("super::film::Stats", "render::film::Stats"),
        ("crate::opt::prepare", "opt::prepare"),
        ("super::super::ir::Shape::Sphere", "ir::Shape::Sphere"),
        ("super", "render::texture"),
        ("super::inner::thing", "render::texture::inner::thing"),
        ("crate::assets", "assets"),
    ];
    let want: Vec<(String, String)> = want
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
    assert_eq!(got, want);
}

#[test]
fn a_wrong_import_is_a_violation() {
    let at = |written: &str| Use {
        written: written.to_string(),
        absolute: written.split("::").skip(1).map(String::from).collect(),
        line: 1,
    };
    assert!(violation("geometry", &at("crate::render::Film")).is_some());
    assert!(violation("eval", &at("crate::geometry::World")).is_some());
    assert!(violation("eval", &at("crate::geometry::shape::bounds")).is_none());
    assert!(violation("render", &at("crate::ir::Shape")).is_some());
    assert!(violation("render", &at("crate::ir::Material")).is_none());
    assert!(violation("compat", &at("crate::eval::value")).is_some());
    assert!(violation("ir", &at("crate::diag::Diagnostic")).is_none());
    assert!(violation("newthing", &at("crate::ir::Scene")).is_some());
}
