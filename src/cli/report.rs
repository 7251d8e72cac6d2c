//! The one place where diagnostics become text: human (miette), short (one block per finding,
//! stable for tests) and JSON (for editors and CI).

use std::fmt::{self, Display, Write as _};

use miette::{GraphicalReportHandler, GraphicalTheme, LabeledSpan, NamedSource, SourceSpan};
use rtc::diag::{Diagnostic, Severity};
use rtc::source::{SourceMap, Span};

/// Output style of diagnostics, chosen with `--format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum Format {
    /// Source snippets with labels (miette).
    Human,
    /// One compact block per diagnostic; stable, for tests and grep.
    Short,
    /// A JSON document for tools.
    Json,
}

/// Renders `diags` in `format`; `color` only affects the human format.
/// `subject` names the input file, shown for diagnostics that have no span.
pub(crate) fn render(
    diags: &[Diagnostic],
    sources: &SourceMap,
    subject: &str,
    format: Format,
    color: bool,
) -> String {
    let shown = capped(diags);
    let diags = &shown[..];
    match format {
        Format::Human => human(diags, sources, color),
        Format::Short => short(diags, sources, subject),
        Format::Json => json(diags, sources).to_string(),
    }
}

/// The diagnostics shown: at most [`MAX_SHOWN`] errors and as many warnings (notes all), in
/// their order, then a note that counts the rest. Printing a million errors helps nobody and
/// took minutes and hundreds of megabytes.
fn capped(diags: &[Diagnostic]) -> std::borrow::Cow<'_, [Diagnostic]> {
    let (mut errors, mut warnings) = (0usize, 0usize);
    let mut shown = Vec::new();
    let (mut more_errors, mut more_warnings) = (0usize, 0usize);
    for d in diags {
        let (count, more) = match d.severity {
            Severity::Error => (&mut errors, &mut more_errors),
            Severity::Warning => (&mut warnings, &mut more_warnings),
            Severity::Note => {
                shown.push(d);
                continue;
            }
        };
        if *count < MAX_SHOWN {
            *count += 1;
            shown.push(d);
        } else {
            *more += 1;
        }
    }
    if more_errors + more_warnings == 0 {
        return std::borrow::Cow::Borrowed(diags);
    }
    let mut out: Vec<Diagnostic> = shown.into_iter().cloned().collect();
    out.push(
        Diagnostic::new(
            Severity::Note,
            OMITTED,
            None,
            format!(
                "{more_errors} more error{} and {more_warnings} more warning{} not shown (at most {MAX_SHOWN} of each are)",
                if more_errors == 1 { "" } else { "s" },
                if more_warnings == 1 { "" } else { "s" },
            ),
        )
        .with_help("fix the first ones and run again; `--format short` lists one per line"),
    );
    std::borrow::Cow::Owned(out)
}

/// Errors, and warnings, a report shows at most (docs/language.md §24).
const MAX_SHOWN: usize = rtc::diag::MAX_ERRORS;

/// The code of the note that counts the diagnostics a report leaves out.
const OMITTED: &str = "rtc::diag::omitted";

fn position(sources: &SourceMap, span: Span) -> (String, usize, usize) {
    let file = sources.get(span.file);
    let (line, col) = file.line_col(span.start as usize);
    (file.path.display().to_string(), line, col)
}

/// `file:line:col` of the start of a span.
pub(crate) fn location(sources: &SourceMap, span: Span) -> String {
    let (path, line, col) = position(sources, span);
    format!("{path}:{line}:{col}")
}

fn short(diags: &[Diagnostic], sources: &SourceMap, subject: &str) -> String {
    let mut out = String::new();
    for (i, d) in diags.iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        let head = match d.span {
            Some(s) => location(sources, s),
            None => subject.to_string(),
        };
        let _ = writeln!(
            out,
            "{head}: {}[{}]: {}",
            d.severity.as_str(),
            d.code,
            d.message
        );
        if let Some(l) = &d.label {
            let _ = writeln!(out, "  label: {l}");
        }
        for l in &d.labels {
            let _ = writeln!(out, "  {}: {}", location(sources, l.span), l.message);
        }
        if let Some(h) = &d.help {
            let _ = writeln!(out, "  help: {h}");
        }
        for n in &d.notes {
            let _ = writeln!(out, "  note: {n}");
        }
        for t in &d.trace {
            let _ = writeln!(out, "  trace: {}: {}", location(sources, t.span), t.message);
        }
    }
    out
}

/// A span as JSON: `{"file", "line", "column", "end_line", "end_column"}` (1-based).
pub(crate) fn place(sources: &SourceMap, s: Span) -> serde_json::Value {
    let (path, line, col) = position(sources, s);
    let (end_line, end_col) = sources.get(s.file).line_col(s.end as usize);
    serde_json::json!({"file": path, "line": line, "column": col, "end_line": end_line, "end_column": end_col})
}

fn json(diags: &[Diagnostic], sources: &SourceMap) -> serde_json::Value {
    use serde_json::json;
    let place = |s: Span| place(sources, s);
    let items: Vec<_> = diags
        .iter()
        .map(|d| {
            json!({
                "severity": d.severity.as_str(),
                "code": d.code,
                "message": d.message,
                "span": d.span.map(place),
                "label": d.label,
                "labels": d.labels.iter().map(|l| json!({"span": place(l.span), "message": l.message})).collect::<Vec<_>>(),
                "help": d.help,
                "notes": d.notes,
                "trace": d.trace.iter().map(|t| json!({"span": place(t.span), "message": t.message})).collect::<Vec<_>>(),
            })
        })
        .collect();
    json!({ "diagnostics": items })
}

fn human(diags: &[Diagnostic], sources: &SourceMap, color: bool) -> String {
    let theme = if color {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let handler = GraphicalReportHandler::new_themed(theme)
        .with_width(100)
        .with_links(false);
    let mut out = String::new();
    for (i, d) in diags.iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        let report = Report::build(d, sources);
        let _ = handler.render_report(&mut out, &report);
    }
    out
}

/// A `Diagnostic` (or one of its secondary locations) adapted to miette's trait.
#[derive(Debug)]
struct Report {
    severity: Severity,
    code: Option<String>,
    message: String,
    source: Option<NamedSource<std::sync::Arc<String>>>,
    labels: Vec<LabeledSpan>,
    help: Option<String>,
    related: Vec<Report>,
}

impl Report {
    fn build(d: &Diagnostic, sources: &SourceMap) -> Report {
        let file = d.span.map(|s| s.file);
        let mut labels = Vec::new();
        let mut related = Vec::new();
        if let Some(span) = d.span {
            labels.push(LabeledSpan::new_primary_with_span(
                d.label.clone(),
                miette_span(span),
            ));
        }
        for l in &d.labels {
            if Some(l.span.file) == file {
                labels.push(LabeledSpan::new_with_span(
                    Some(l.message.clone()),
                    miette_span(l.span),
                ));
            } else {
                related.push(Report::secondary(sources, l.span, "see also", &l.message));
            }
        }
        for t in &d.trace {
            related.push(Report::secondary(sources, t.span, &t.message, "here"));
        }
        let mut help = d.help.clone();
        if !d.notes.is_empty() {
            let notes = d
                .notes
                .iter()
                .map(|n| format!("note: {n}"))
                .collect::<Vec<_>>()
                .join("\n");
            help = Some(match help {
                Some(h) => format!("{h}\n{notes}"),
                None => notes,
            });
        }
        Report {
            severity: d.severity,
            code: Some(d.code.to_string()),
            message: d.message.clone(),
            source: file.map(|f| named_source(sources, f)),
            labels,
            help,
            related,
        }
    }

    fn secondary(sources: &SourceMap, span: Span, message: &str, label: &str) -> Report {
        Report {
            severity: Severity::Note,
            code: None,
            message: message.to_string(),
            source: Some(named_source(sources, span.file)),
            labels: vec![LabeledSpan::new_primary_with_span(
                Some(label.to_string()),
                miette_span(span),
            )],
            help: None,
            related: Vec::new(),
        }
    }
}

fn named_source(
    sources: &SourceMap,
    file: rtc::source::FileId,
) -> NamedSource<std::sync::Arc<String>> {
    let f = sources.get(file);
    // Shared, not copied: a report per diagnostic must not copy a file of megabytes.
    NamedSource::new(f.path.display().to_string(), std::sync::Arc::clone(&f.text))
}

fn miette_span(s: Span) -> SourceSpan {
    SourceSpan::new((s.start as usize).into(), s.len())
}

impl Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Report {}

impl miette::Diagnostic for Report {
    fn code<'a>(&'a self) -> Option<Box<dyn Display + 'a>> {
        self.code.as_ref().map(|c| Box::new(c) as Box<dyn Display>)
    }

    fn severity(&self) -> Option<miette::Severity> {
        Some(match self.severity {
            Severity::Error => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
            Severity::Note => miette::Severity::Advice,
        })
    }

    fn help<'a>(&'a self) -> Option<Box<dyn Display + 'a>> {
        self.help.as_ref().map(|h| Box::new(h) as Box<dyn Display>)
    }

    fn source_code(&self) -> Option<&dyn miette::SourceCode> {
        self.source.as_ref().map(|s| s as &dyn miette::SourceCode)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        if self.labels.is_empty() {
            None
        } else {
            Some(Box::new(self.labels.iter().cloned()))
        }
    }

    fn related<'a>(&'a self) -> Option<Box<dyn Iterator<Item = &'a dyn miette::Diagnostic> + 'a>> {
        if self.related.is_empty() {
            None
        } else {
            Some(Box::new(
                self.related.iter().map(|r| r as &dyn miette::Diagnostic),
            ))
        }
    }
}
