//! `docs/builtins.md`, the reference of every built-in, written from the schemas: each
//! function, record form and method with its parameters' types, units, ranges, defaults and
//! docs. A test compares the file with what the schemas say (`RTC_BLESS=1` rewrites it), so the
//! reference cannot drift from the code.

use crate::eval::methods::RECEIVERS;
use crate::eval::schema::{Group, Sig};

/// Every schema: the functions in table order, then the methods that are no function, then
/// the records built-ins read. Each once.
pub(crate) fn all() -> Vec<&'static Sig> {
    let mut out: Vec<&'static Sig> = super::functions().into_iter().map(|(s, _)| s).collect();
    for (_, tables) in RECEIVERS {
        for m in tables.iter().flat_map(|t| t.iter()) {
            if !out.iter().any(|s| std::ptr::eq(*s, *m)) {
                out.push(m);
            }
        }
    }
    out.push(&crate::eval::shapes::BLOB_COMPONENT);
    out
}

/// The whole reference, as Markdown.
fn markdown() -> String {
    let mut out = String::from(HEADER);
    let sigs = all();
    let mut groups: Vec<Group> = sigs.iter().map(|s| s.group).collect();
    groups.sort();
    groups.dedup();
    for g in groups {
        if g == Group::Method {
            continue; // with the receivers below
        }
        out.push_str(&format!("\n## {}\n", g.title()));
        for s in sigs.iter().filter(|s| s.group == g) {
            let call = if g == Group::Record {
                let names: Vec<&str> = s.names().collect();
                format!("{{ {} }}", names.join(", "))
            } else {
                s.usage()
            };
            entry(&mut out, s, call);
        }
    }
    out.push_str(&format!("\n## {}\n", Group::Method.title()));
    out.push_str(METHODS);
    for (receiver, tables) in RECEIVERS {
        out.push_str(&format!(
            "\n### Methods of `{receiver}`\n\n| method | result | |\n|---|---|---|\n"
        ));
        for m in tables.iter().flat_map(|t| t.iter()) {
            out.push_str(&method_row(m));
        }
    }
    for (receiver, tables) in RECEIVERS {
        for m in tables.iter().flat_map(|t| t.iter()) {
            if m.group == Group::Method && first_receiver(m) == *receiver {
                entry(&mut out, m, format!(".{}", m.usage()));
            }
        }
    }
    out
}

/// A method's row in its receiver's table: a method of its own, a transform applied to the
/// receiver, or a function whose first parameter the receiver fills.
fn method_row(m: &Sig) -> String {
    let (call, result, doc) = match m.group {
        Group::Method => (m.usage(), result(m), m.doc.to_string()),
        Group::Transform => (
            m.usage(),
            "the receiver, transformed".to_string(),
            format!("applies `{}`", m.usage()),
        ),
        _ => {
            let rest: Vec<&str> = m.names().skip(1).collect();
            let first = m.params.first().map_or("", |p| p.name);
            (
                format!("{}({})", m.name, rest.join(", ")),
                result(m),
                format!("`{}` with the receiver as `{first}`", m.usage()),
            )
        }
    };
    format!("| `.{call}` | {result} | {} |\n", cell(&doc))
}

/// The receiver type under which a method's parameters are listed (the first that has it).
fn first_receiver(m: &Sig) -> &'static str {
    RECEIVERS
        .iter()
        .find(|(_, tables)| tables.iter().any(|t| t.iter().any(|x| std::ptr::eq(*x, m))))
        .map_or("", |(r, _)| r)
}

/// A signature's result, for a table cell: a type as code, words as they are.
fn result(s: &Sig) -> String {
    if s.result
        .starts_with(|c: char| c.is_ascii_uppercase() || c == '(')
    {
        format!("`{}`", s.result)
    } else {
        cell(s.result)
    }
}

/// Text for a table cell (a `|` would end the cell).
fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

/// One signature: its heading, doc and parameter table.
fn entry(out: &mut String, s: &Sig, call: String) {
    let arrow = if s.result.is_empty() {
        String::new()
    } else {
        format!(" → {}", result(s))
    };
    let title = if s.group == Group::Record {
        format!("A {}: `{call}`", s.name)
    } else {
        format!("`{call}`{arrow}")
    };
    out.push_str(&format!("\n### {title}\n\n{}\n", s.doc));
    if !s.examples.is_empty() {
        out.push_str(&format!("\n```rtc\n{}\n```\n", s.examples.join("\n")));
    }
    if s.params.is_empty() {
        return;
    }
    out.push_str("\n| parameter | type | unit | range | default | |\n|---|---|---|---|---|---|\n");
    for p in s.params {
        let range = p.range.show(p.ty);
        out.push_str(&format!(
            "| `{}` | `{}` | {} | {} | {} | {} |\n",
            p.name,
            p.ty.show(),
            p.unit.show(),
            range,
            cell(&p.absent.show()),
            cell(p.doc)
        ));
    }
}

/// What the methods section says first.
const METHODS: &str = "
A method's receiver comes before the dot. A transform method applies the transform of the same
name to the receiver (`o.rotate(y: 30deg)`); a method that is also a function takes the
function's parameters after its first, which the receiver fills (`l.sum()` is `sum(l)`,
`v.dot(w)` is `dot(v, w)`).
";

/// What the reference says of itself.
const HEADER: &str = "# Built-in reference

Every built-in function, record form and method of the rtc language with its parameters,
written from the schemas the evaluator checks arguments with (`src/eval/schema.rs`; each
schema is declared next to its function). Do not edit this file: after changing a built-in,
regenerate it with `RTC_BLESS=1 cargo test --release --lib builtins::reference`, which
`cargo test` otherwise checks. docs/language.md explains the language and each built-in.

Parameters are given positionally in the order listed, or by name, or as the fields of one
record (`material { kd: 0.5 }`). A `Float` parameter takes an `Int` too. An argument outside
its range is `rtc::param::out_of_range`; a missing required one `rtc::arg::missing`.
";

#[cfg(test)]
mod tests {
    use std::path::Path;

    /// `docs/builtins.md` is what the schemas say (`RTC_BLESS=1` writes it).
    #[test]
    fn the_reference_is_written_from_the_schemas() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/builtins.md");
        let want = super::markdown();
        if std::env::var_os("RTC_BLESS").is_some() {
            std::fs::write(&path, &want).expect("write docs/builtins.md");
            return;
        }
        let got = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            got == want,
            "docs/builtins.md is not what the schemas say; regenerate it with \
             `RTC_BLESS=1 cargo test --release --lib builtins::reference`"
        );
    }

    /// Every schema has a name, a doc and documented parameters, and no two parameters share
    /// a name.
    #[test]
    fn every_schema_is_documented() {
        for s in super::all() {
            assert!(!s.name.is_empty() && !s.doc.is_empty(), "{}", s.name);
            for (i, p) in s.params.iter().enumerate() {
                assert!(!p.doc.is_empty(), "`{}` of `{}`", p.name, s.name);
                assert!(
                    s.params[..i].iter().all(|q| q.name != p.name),
                    "`{}` twice in `{}`",
                    p.name,
                    s.name
                );
            }
        }
    }
}
