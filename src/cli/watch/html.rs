//! Diagnostics as HTML for the watch page: the same facts as the terminal report (code, title,
//! location, the source line with the span marked, label, secondary labels, help, notes, trace).

use rtc::diag::{Diagnostic, Severity};
use rtc::source::{SourceMap, Span};

/// Escapes text for HTML element content and attribute values.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// Every diagnostic as one `<div class="diag">` block each.
pub(crate) fn diagnostics(diags: &[Diagnostic], sources: &SourceMap) -> String {
    diags.iter().map(|d| one(d, sources)).collect()
}

fn severity_name(s: Severity) -> &'static str {
    match s {
        Severity::Error => "error",
        Severity::Warning => "warning",
        _ => "note",
    }
}

fn one(d: &Diagnostic, sources: &SourceMap) -> String {
    let kind = severity_name(d.severity);
    let mut out = format!(
        "<div class=\"diag {kind}\"><div class=\"title\"><b>{kind}[{}]</b>: {}</div>",
        escape(d.code),
        escape(&d.message)
    );
    if let Some(span) = d.span {
        out += &format!("<div class=\"loc\">{}</div>", location(span, sources));
        out += &snippet(span, d.label.as_deref(), sources);
    }
    for l in &d.labels {
        out += &format!(
            "<div class=\"secondary\">{}: {}</div>",
            location(l.span, sources),
            escape(&l.message)
        );
        out += &snippet(l.span, None, sources);
    }
    if let Some(help) = &d.help {
        out += &format!("<div class=\"help\">help: {}</div>", escape(help));
    }
    for n in &d.notes {
        out += &format!("<div class=\"note\">note: {}</div>", escape(n));
    }
    for t in &d.trace {
        out += &format!(
            "<div class=\"trace\">in {} at {}</div>",
            escape(&t.message),
            location(t.span, sources)
        );
    }
    out + "</div>"
}

/// `path:line:col` of a span's start.
fn location(span: Span, sources: &SourceMap) -> String {
    let Some(file) = sources.files().get(span.file.0 as usize) else {
        return String::from("?");
    };
    let (line, col) = file.line_col(span.start as usize);
    escape(&format!("{}:{line}:{col}", file.path.display()))
}

/// The source line holding the span's start, numbered, with the span (up to the line's end)
/// in `<mark>` and the label under it.
fn snippet(span: Span, label: Option<&str>, sources: &SourceMap) -> String {
    let Some(file) = sources.files().get(span.file.0 as usize) else {
        return String::new();
    };
    let text = &file.text;
    let start = (span.start as usize).min(text.len());
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    let end = (span.end as usize).clamp(start, line_end);
    let (line, _) = file.line_col(start);
    let mut out = format!(
        "<pre class=\"snippet\"><span class=\"gutter\">{line:>4} | </span>{}<mark>{}</mark>{}",
        escape(&text[line_start..start]),
        escape(&text[start..end]),
        escape(&text[end..line_end])
    );
    if let Some(label) = label {
        out += &format!("\n<span class=\"label\">       {}</span>", escape(label));
    }
    out + "</pre>"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_span_is_marked_and_text_escaped() {
        let mut sources = SourceMap::new();
        let f = sources.add("a.rtc", "let x = 1\nsphere(radius: <-1>)\n");
        let d = Diagnostic::error(
            "rtc::param::out_of_range",
            Span::new(f, 25, 29),
            "bad <radius>",
        )
        .with_label("here")
        .with_help("use 1");
        let html = diagnostics(&[d], &sources);
        assert!(html.contains("a.rtc:2:16"), "{html}");
        assert!(html.contains("<mark>&lt;-1&gt;</mark>"), "{html}");
        assert!(html.contains("bad &lt;radius&gt;"), "{html}");
        assert!(html.contains("help: use 1"), "{html}");
    }
}
