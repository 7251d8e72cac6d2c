//! `rtc fmt`: the one canonical layout of a `.rtc` file (docs/fmt.md). The file is read into
//! tokens that know their role (tokens.rs), the layout is planned (layout.rs) and printed
//! (print.rs). Comments stay where they were; only spaces, indentation, line breaks inside
//! brackets and optional commas change. A file with syntax errors is not formatted, and a result
//! whose syntax tree differs from the input's (ignoring positions) is refused, so formatting
//! never changes what a file means.

mod layout;
mod print;
mod tokens;

use crate::diag::{Diagnostic, Severity};
use crate::source::FileId;

/// Code of the diagnostic for a file the formatter cannot safely lay out (a formatter bug).
pub const INTERNAL: &str = "rtc::fmt::internal";

/// Formats `text` (file `file`, for the diagnostics' spans). `Err` holds the syntax errors (and
/// the parser's warnings) when the file does not parse, or one `rtc::fmt::internal` error when
/// the formatter cannot lay it out without changing its meaning.
pub fn format(file: FileId, text: &str) -> Result<String, Vec<Diagnostic>> {
    let (ast, diags) = super::parse(file, text);
    let Some(ast) = ast else { return Err(diags) };
    let toks = tokens::tokenize(text).map_err(|e| vec![internal(&e)])?;
    let out = layout::layout(&toks);
    // The safety net: the result must parse to the same tree (positions aside).
    let same = match super::parse(file, &out) {
        (Some(again), _) => strip_spans(&format!("{again:?}")) == strip_spans(&format!("{ast:?}")),
        (None, _) => false,
    };
    if !same {
        return Err(vec![internal(
            "the formatted text would not parse to the same program",
        )]);
    }
    Ok(out)
}

fn internal(what: &str) -> Diagnostic {
    Diagnostic::new(
        Severity::Error,
        INTERNAL,
        None,
        format!("cannot format this file: {what}; it is left as it is"),
    )
    .with_help("this is a bug in `rtc fmt`: please report it with the file")
}

/// `text` (a `{:?}` rendering) with every `Span { .. }` replaced by `Span`, so two syntax trees
/// or scenes that differ only in source positions print the same.
pub fn strip_spans(text: &str) -> String {
    const MARK: &str = "Span {";
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(MARK) {
        out.push_str(&rest[..at + 4]);
        let after = &rest[at + MARK.len()..];
        // A span's fields hold no braces: skip to the first `}`.
        rest = after.find('}').map_or("", |e| &after[e + 1..]);
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests;
