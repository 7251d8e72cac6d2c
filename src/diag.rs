//! Diagnostics as plain data. The library only builds them; the binary renders them in one place.

use crate::source::Span;

/// Diagnostic code for files that cannot be read or written (the CLI exits with 2 on these).
pub const IO_ERROR: &str = "rtc::io";

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// Extra information attached to a finding that is not a problem by itself.
    Note,
    /// Likely a mistake; the scene still renders (`--deny warnings` makes it fail).
    Warning,
    /// The scene cannot be rendered.
    Error,
}

impl Severity {
    /// Lower-case name as printed (`error`, `warning`, `note`).
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Note => "note",
            Severity::Warning => "warning",
            Severity::Error => "error",
        }
    }
}

/// A secondary span with a short message.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// Where.
    pub span: Span,
    /// What about it (short, lower case, no full stop).
    pub message: String,
}

/// One frame of an evaluation trace: "in call of `ball` at 25:5", "in iteration i = 3 of the `for`".
#[derive(Clone, Debug, PartialEq)]
pub struct TraceFrame {
    /// The call site or loop header.
    pub span: Span,
    /// The frame's description.
    pub message: String,
}

/// A finding: stable code, a short title, one primary span with its label, optional help and trace.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Error, warning or note.
    pub severity: Severity,
    /// A stable code such as `rtc::name::unknown`, documented in docs/diagnostics.md.
    pub code: &'static str,
    /// A short title, starting in lower case.
    pub message: String,
    /// The primary location; `None` only for problems with no source (an unreadable file).
    pub span: Option<Span>,
    /// The label on the primary span.
    pub label: Option<String>,
    /// Further labelled spans.
    pub labels: Vec<Label>,
    /// At most one concrete fix.
    pub help: Option<String>,
    /// Additional facts (e.g. where a parameter is declared).
    pub notes: Vec<String>,
    /// The evaluation trace, innermost frame first.
    pub trace: Vec<TraceFrame>,
}

impl Diagnostic {
    /// An error with a code, title and primary span.
    pub fn error(code: &'static str, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Error, code, Some(span), message)
    }

    /// A warning with a code, title and primary span.
    pub(crate) fn warning(
        code: &'static str,
        span: Span,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::new(Severity::Warning, code, Some(span), message)
    }

    /// A diagnostic of any severity.
    pub fn new(
        severity: Severity,
        code: &'static str,
        span: Option<Span>,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic {
            severity,
            code,
            message: message.into(),
            span,
            label: None,
            labels: Vec::new(),
            help: None,
            notes: Vec::new(),
            trace: Vec::new(),
        }
    }

    /// Sets the primary label.
    pub fn with_label(mut self, label: impl Into<String>) -> Diagnostic {
        self.label = Some(label.into());
        self
    }

    /// Adds a secondary label.
    pub fn with_secondary(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.labels.push(Label {
            span,
            message: message.into(),
        });
        self
    }

    /// Sets the help line (one concrete fix).
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    /// Adds a note.
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// True for errors.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// Errors one file's report shows (the rest are counted), and errors a front end keeps before
/// it only counts them (the syntax driver stops reading there): docs/language.md §24.
pub const MAX_ERRORS: usize = 100;

/// A list of diagnostics collected by one stage, which keeps going after the first.
#[derive(Clone, Debug, Default)]
pub struct Diagnostics {
    /// The findings in the order they were made.
    pub items: Vec<Diagnostic>,
    /// Errors [`Diagnostics::push`] counted but did not keep, past [`MAX_ERRORS`] (a file of
    /// garbage makes millions: each costs memory and nobody reads them).
    pub(crate) omitted_errors: usize,
}

impl Diagnostics {
    /// Records one finding; an error past the first [`MAX_ERRORS`] is only counted.
    pub(crate) fn push(&mut self, d: Diagnostic) {
        if d.is_error()
            && (self.omitted_errors > 0
                || (self.items.len() >= MAX_ERRORS
                    && self.items.iter().filter(|d| d.is_error()).count() >= MAX_ERRORS))
        {
            if self.omitted_errors == 0 {
                self.items.push(
                    Diagnostic::new(
                        Severity::Note,
                        "rtc::diag::omitted",
                        None,
                        format!("more than {MAX_ERRORS} errors: the rest are counted, not kept"),
                    )
                    .with_help("fix the first ones and run again"),
                );
            }
            self.omitted_errors += 1;
            return;
        }
        self.items.push(d);
    }

    /// True when at least one error was recorded.
    pub fn has_errors(&self) -> bool {
        self.items.iter().any(Diagnostic::is_error)
    }

    /// Number of errors (those only counted included).
    pub fn error_count(&self) -> usize {
        self.items.iter().filter(|d| d.is_error()).count() + self.omitted_errors
    }

    /// Number of warnings.
    pub fn warning_count(&self) -> usize {
        self.items
            .iter()
            .filter(|d| d.severity == Severity::Warning)
            .count()
    }

    /// Moves all of `other`'s findings into `self`.
    pub fn extend(&mut self, other: Diagnostics) {
        self.items.extend(other.items);
        self.omitted_errors += other.omitted_errors;
    }
}

/// A number as messages show it: integers without a fraction (`-1`, `64`), others with up to
/// six decimals and no trailing zeros (`1.5`, `0.333333`).
pub fn number(f: f64) -> String {
    if f == f.trunc() && f.abs() < 1e15 {
        format!("{}", f as i64)
    } else if f.abs() >= 1e15 {
        format!("{f:e}")
    } else {
        let s = format!("{f:.6}");
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    }
}

/// Closest candidate to `name` by Jaro-Winkler/Levenshtein, for "did you mean" help.
pub fn did_you_mean<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    let mut best: Option<(&str, f64)> = None;
    for c in candidates {
        let score = strsim::jaro_winkler(name, c);
        let close = score > 0.8 || strsim::levenshtein(name, c) <= name.len().min(c.len()) / 3;
        if close && best.is_none_or(|(_, s)| score > s) {
            best = Some((c, score));
        }
    }
    best.map(|(c, _)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_close_names_only() {
        let names = ["brushed_metal", "glass", "plastic"];
        assert_eq!(did_you_mean("brushed_metl", names), Some("brushed_metal"));
        assert_eq!(did_you_mean("zzz", names), None);
    }
}
