//! docs/language.md's tables of built-ins against the schemas: every call a table writes
//! (`atan2(y, x)`, `checker(size: Float = 1, ...)`), every parameter cell of the object and
//! light tables (`center: Vec3 = [0, 0, 0]`) and every field of the material, camera and render
//! tables names the schema's parameters, and a default the table states is the schema's.

use std::collections::{BTreeMap, BTreeSet};

use crate::eval::methods::RECEIVERS;
use crate::eval::schema::{Absent, Sig};

/// The reference.
fn language_md() -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/language.md");
    std::fs::read_to_string(path).expect("read docs/language.md")
}

/// The text of the section whose heading starts with `heading` (`## 11.`, `### 13.1`), up to
/// the next heading.
fn section<'a>(doc: &'a str, heading: &str) -> &'a str {
    let start = doc
        .find(&format!("\n{heading} "))
        .unwrap_or_else(|| panic!("docs/language.md has no section `{heading}`"));
    let body = &doc[start + 1..];
    let body = &body[body.find('\n').map_or(body.len(), |n| n + 1)..];
    let end = body
        .find("\n## ")
        .into_iter()
        .chain(body.find("\n### "))
        .min();
    &body[..end.unwrap_or(body.len())]
}

/// The rows of the section's tables (header rows included, separator rows not), as cells.
fn rows(section: &str) -> Vec<Vec<String>> {
    section
        .lines()
        .filter(|l| l.starts_with('|') && !l.starts_with("|---"))
        .map(|l| {
            let mut cells = Vec::new();
            let mut cell = String::new();
            let mut prev = ' ';
            for c in l.trim().trim_matches('|').chars() {
                if c == '|' && prev != '\\' {
                    cells.push(cell.trim().to_string());
                    cell.clear();
                } else {
                    cell.push(c);
                }
                prev = c;
            }
            cells.push(cell.trim().to_string());
            cells
        })
        .collect()
}

/// The `code spans` of a cell.
fn spans(cell: &str) -> Vec<String> {
    cell.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

/// `text` split at the commas outside brackets.
fn split_top(text: &str) -> Vec<String> {
    let (mut out, mut cur, mut depth) = (Vec::new(), String::new(), 0i32);
    for c in text.chars() {
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' => depth -= 1,
            ',' if depth == 0 => {
                out.push(cur.trim().to_string());
                cur.clear();
                continue;
            }
            _ => {}
        }
        cur.push(c);
    }
    if !cur.trim().is_empty() {
        out.push(cur.trim().to_string());
    }
    out
}

/// A parameter as a table writes it: `name`, `name: Type`, `name: Type = default`,
/// `name = default`, `name:` or `name: value` (a named argument), `values...`.
struct Mention {
    name: String,
    /// The type, when written (`name: Type`).
    ty: Option<String>,
    /// The default, when written.
    default: Option<String>,
}

fn mention(token: &str) -> Mention {
    let (head, default) = match token.split_once('=') {
        Some((h, d)) => (h.trim(), Some(d.trim().to_string())),
        None => (token.trim(), None),
    };
    let (name, ty) = match head.split_once(':') {
        Some((n, t)) => (n.trim(), Some(t.trim().to_string())),
        None => (head, None),
    };
    Mention {
        name: name.trim_end_matches("...").to_string(),
        ty: ty.filter(|t| t.starts_with(|c: char| c.is_ascii_uppercase())),
        default,
    }
}

/// A default as written in the docs, without formatting and remarks: `` `[0, 0, 0]` ``,
/// `0.00015 (...)` and `none (an instant)` become `[0, 0, 0]`, `0.00015` and `none`.
fn plain(text: &str) -> String {
    let t = text.replace('`', "");
    let t = match t.find(" (") {
        Some(i) => &t[..i],
        None => &t,
    };
    t.trim().to_string()
}

/// Whether the docs' default `doc` is the schema's. A number may be written rounded (the
/// render table's cut-off is 0.00015 for 0.5 / (255 · 12.92)).
fn same_default(doc: &str, absent: Absent) -> bool {
    let doc = plain(doc);
    let schema = plain(&absent.show());
    if doc == schema {
        return true;
    }
    match (doc.parse::<f64>(), schema.parse::<f64>()) {
        (Ok(d), Ok(s)) => {
            let digits = doc
                .trim_start_matches(['0', '.', '-'])
                .replace('.', "")
                .len() as i32;
            let scale = 10f64.powi(digits - 1 - s.abs().log10().floor() as i32);
            (s * scale).round() / scale == d
        }
        _ => false,
    }
}

/// Every function by name.
fn functions() -> BTreeMap<&'static str, &'static Sig> {
    super::functions()
        .into_iter()
        .map(|(s, _)| (s.name, s))
        .collect()
}

/// The methods of `receiver` by name.
fn methods(receiver: &str) -> BTreeMap<&'static str, &'static Sig> {
    RECEIVERS
        .iter()
        .filter(|(r, _)| *r == receiver)
        .flat_map(|(_, tables)| tables.iter().flat_map(|t| t.iter()))
        .map(|s| (s.name, *s))
        .collect()
}

/// Checks the mentions of `sig`'s parameters: each names one, and a stated default is the
/// schema's (`typed_means_required`: a `name: Type` without a default says it has none).
fn check_mentions(
    where_: &str,
    sig: &Sig,
    ms: &[Mention],
    typed_means_required: bool,
    problems: &mut Vec<String>,
) {
    for m in ms {
        let Some(p) = sig.param(&m.name) else {
            problems.push(format!(
                "{where_}: `{}` has no parameter `{}`",
                sig.name, m.name
            ));
            continue;
        };
        match &m.default {
            Some(d) if !same_default(d, p.absent) => problems.push(format!(
                "{where_}: `{}`'s `{}` defaults to {} in the schema, `{d}` in the docs",
                sig.name,
                p.name,
                p.absent.show()
            )),
            None if typed_means_required && m.ty.is_some() && matches!(p.absent, Absent::Is(_)) => {
                problems.push(format!(
                    "{where_}: `{}`'s `{}` defaults to {} in the schema, to nothing in the docs",
                    sig.name,
                    p.name,
                    p.absent.show()
                ))
            }
            _ => {}
        }
    }
}

/// Adds `found` to `seen[sig]`.
fn note(
    seen: &mut BTreeMap<&'static str, (&'static Sig, BTreeSet<String>)>,
    sig: &'static Sig,
    found: &[Mention],
) {
    let entry = seen.entry(sig.name).or_insert((sig, BTreeSet::new()));
    entry.1.extend(found.iter().map(|m| m.name.clone()));
}

/// Reports the functions whose parameters the tables name only in part.
fn check_complete(
    where_: &str,
    seen: &BTreeMap<&'static str, (&'static Sig, BTreeSet<String>)>,
    problems: &mut Vec<String>,
) {
    for (sig, names) in seen.values() {
        let want: BTreeSet<String> = sig.names().map(String::from).collect();
        if *names != want && !sig.variadic {
            problems.push(format!(
                "{where_}: the tables give `{}` the parameters {names:?}, the schema {want:?}",
                sig.name
            ));
        }
    }
}

/// The call tables (§11, §12, §14, §16): `f(a, b)` names every parameter (over the rows of the
/// section), `f(a: T = d)` states defaults.
fn check_calls(doc: &str, heading: &str, problems: &mut Vec<String>) {
    let fns = functions();
    let mut seen = BTreeMap::new();
    for row in rows(section(doc, heading)).iter().skip(1) {
        for span in spans(&row[0]) {
            let Some((name, args)) = span.split_once('(') else {
                continue; // `flatten`, `a | b`: no parameters written
            };
            let Some(sig) = fns.get(name.trim()) else {
                problems.push(format!("{heading}: `{span}` is no built-in"));
                continue;
            };
            let ms: Vec<Mention> = split_top(args.strip_suffix(')').unwrap_or(args))
                .iter()
                .filter(|t| *t != "...")
                .map(|t| mention(t))
                .collect();
            if !sig.variadic {
                check_mentions(heading, sig, &ms, false, problems);
            }
            note(&mut seen, sig, &ms);
        }
    }
    check_complete(heading, &seen, problems);
}

/// The method tables (§13.2 of objects, §20 of random streams): `o.m(...)` is a method of the
/// receiver; named arguments (`up:`) are parameters, and with `positional`, every argument.
fn check_methods(
    doc: &str,
    heading: &str,
    receiver: &str,
    positional: bool,
    problems: &mut Vec<String>,
) {
    let ms = methods(receiver);
    for row in rows(section(doc, heading)).iter().skip(1) {
        for span in spans(&row[0]) {
            let Some((head, args)) = span.split_once('(') else {
                continue; // `o.bounds`: a member
            };
            let name = head.rsplit('.').next().unwrap_or(head);
            let Some(sig) = ms.get(name) else {
                problems.push(format!("{heading}: `{span}` is no method of `{receiver}`"));
                continue;
            };
            let found: Vec<Mention> = split_top(args.strip_suffix(')').unwrap_or(args))
                .iter()
                .filter(|t| positional || t.contains(':'))
                .filter(|t| *t != "..")
                .map(|t| mention(t))
                .collect();
            check_mentions(heading, sig, &found, false, problems);
        }
    }
}

/// The parameter tables (§13.1 objects, §17 lights): the first column names the built-in, the
/// second its parameters as `name: Type = default` spans (a `{ ... }` span is a blob
/// component's fields, a bare name a mention, another built-in's name a cross-reference).
fn check_kinds(doc: &str, heading: &str, problems: &mut Vec<String>) {
    let fns = functions();
    let mut seen = BTreeMap::new();
    for row in rows(section(doc, heading)).iter().skip(1) {
        let kind = spans(&row[0]).concat();
        let Some(sig) = fns.get(kind.as_str()) else {
            problems.push(format!("{heading}: `{kind}` is no built-in"));
            continue;
        };
        let mut found = Vec::new();
        for span in spans(&row[1]) {
            if let Some(fields) = span.strip_prefix('{') {
                let record = &super::super::shapes::BLOB_COMPONENT;
                let ms: Vec<Mention> = split_top(fields.trim_end_matches('}'))
                    .iter()
                    .map(|t| mention(t))
                    .collect();
                check_mentions(heading, record, &ms, true, problems);
                note(&mut seen, record, &ms);
                continue;
            }
            let m = mention(&span);
            let is_type = m.name.starts_with(|c: char| c.is_ascii_uppercase());
            if is_type || (sig.param(&m.name).is_none() && fns.contains_key(m.name.as_str())) {
                continue;
            }
            found.push(m);
        }
        check_mentions(heading, sig, &found, true, problems);
        note(&mut seen, sig, &found);
    }
    check_complete(heading, &seen, problems);
}

/// The field tables (§15 materials, §18 camera, §19 render): one row per field (or several,
/// `eye_close`, `center_close`), and a `default` column.
fn check_fields(doc: &str, heading: &str, sig: &str, problems: &mut Vec<String>) {
    let sig = functions()[sig];
    let rows = rows(section(doc, heading));
    let column = rows[0]
        .iter()
        .position(|h| h == "default")
        .unwrap_or_else(|| panic!("{heading}: no `default` column"));
    let mut seen = BTreeMap::new();
    for row in rows.iter().skip(1) {
        let names = spans(&row[0]);
        let defaults = if names.len() > 1 {
            split_top(&row[column])
        } else {
            vec![row[column].clone()]
        };
        let ms: Vec<Mention> = names
            .iter()
            .zip(defaults.iter().chain(std::iter::repeat(&String::new())))
            .map(|(n, d)| Mention {
                name: n.clone(),
                ty: None,
                default: Some(d.clone()),
            })
            .collect();
        check_mentions(heading, sig, &ms, false, problems);
        note(&mut seen, sig, &ms);
    }
    check_complete(heading, &seen, problems);
}

#[test]
fn the_language_reference_tables_agree_with_the_schemas() {
    let doc = language_md();
    let mut problems = Vec::new();
    for heading in [
        "## 11.", "## 12.", "## 14.", "## 16.", "### 16.1", "### 16.3",
    ] {
        check_calls(&doc, heading, &mut problems);
    }
    check_methods(&doc, "### 13.2", "Object", false, &mut problems);
    check_methods(&doc, "## 20.", "Rng", true, &mut problems);
    check_methods(&doc, "### 16.2", "Texture", false, &mut problems);
    check_kinds(&doc, "### 13.1", &mut problems);
    check_kinds(&doc, "## 17.", &mut problems);
    check_fields(&doc, "## 15.", "material", &mut problems);
    check_fields(&doc, "## 18.", "camera", &mut problems);
    check_fields(&doc, "## 19.", "render", &mut problems);
    check_fields(&doc, "### 19.1", "fog", &mut problems);
    assert!(
        problems.is_empty(),
        "docs/language.md disagrees with the schemas (the code is the truth):\n{}",
        problems.join("\n")
    );
}

#[test]
fn a_default_may_be_rounded_but_not_wrong() {
    let cutoff = Absent::Is(crate::eval::schema::Lit::Float(0.5 / (255.0 * 12.92)));
    assert!(same_default("0.00015 (`0.5 / (255 · 12.92)`)", cutoff));
    assert!(!same_default("0.00016", cutoff));
    let one = Absent::Is(crate::eval::schema::Lit::Float(1.0));
    assert!(same_default("1", one) && !same_default("2", one));
    assert!(same_default("none (an instant)", Absent::Optional));
}
