//! The comments of a course file, found in its text (the front ends skip them), so that the
//! rtc version carries them next to the items they precede.

/// One comment: where its marker starts, its text without the marker, and whether it has a line
/// of its own (else it trails a value on the same line).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Comment {
    /// Byte offset of the `#`.
    pub(crate) start: usize,
    /// The text after `#`, without the line end.
    pub(crate) text: String,
    /// Nothing but blanks before it on its line.
    pub(crate) own_line: bool,
    /// A blank line comes right before it (comments keep their paragraphs).
    pub(crate) after_gap: bool,
}

/// The course formats' comment rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Syntax {
    /// `.in`: a `#` anywhere starts a comment (COURSE.md §1).
    In,
    /// YAML: a `#` at the start of a line or after a blank, outside quotes.
    Yaml,
}

/// Every comment of `text`, in order.
pub(crate) fn scan(text: &str, syntax: Syntax) -> Vec<Comment> {
    let mut out = Vec::new();
    let mut line_start = 0;
    let mut blank_before = false;
    for line in text.split_inclusive('\n') {
        if let Some(at) = marker(line, syntax) {
            let body = line[at + 1..].trim_end_matches(['\n', '\r']);
            out.push(Comment {
                start: line_start + at,
                text: body.to_string(),
                own_line: line[..at].trim().is_empty(),
                after_gap: blank_before,
            });
        }
        blank_before = line.trim().is_empty();
        line_start += line.len();
    }
    out
}

/// The offset of the comment marker on one line, if any.
fn marker(line: &str, syntax: Syntax) -> Option<usize> {
    let bytes = line.as_bytes();
    let mut quote = None;
    for (i, &b) in bytes.iter().enumerate() {
        match (syntax, quote) {
            (Syntax::In, _) if b == b'#' => return Some(i),
            (Syntax::Yaml, Some(q)) if b == q => quote = None,
            (Syntax::Yaml, Some(_)) => {}
            (Syntax::Yaml, None) if b == b'"' || b == b'\'' => quote = Some(b),
            (Syntax::Yaml, None) if b == b'#' && (i == 0 || bytes[i - 1].is_ascii_whitespace()) => {
                return Some(i);
            }
            _ => {}
        }
    }
    None
}

/// A decorative comment (a rule of `#`, `-` or `=`) that says nothing once the marker is gone.
pub(crate) fn is_rule(text: &str) -> bool {
    let t = text.trim();
    !t.is_empty() && t.chars().all(|c| matches!(c, '#' | '-' | '=' | '*'))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn yaml_comments_skip_quotes_and_words() {
        let text = "# head\nEye: [1,2,3] # eye\nname: \"a # b\" # real\nx: a#b\n";
        let found = scan(text, Syntax::Yaml);
        let texts: Vec<&str> = found.iter().map(|c| c.text.as_str()).collect();
        assert_eq!(texts, [" head", " eye", " real"]);
        assert!(found[0].own_line && !found[1].own_line);
        assert_eq!(&text[found[1].start..found[1].start + 1], "#");
    }

    #[test]
    fn in_comments_start_anywhere() {
        let found = scan("Eye 1 2 3#eye\n  #Blue sphere\n", Syntax::In);
        assert_eq!(found.len(), 2);
        assert_eq!(found[0].text, "eye");
        assert!(!found[0].own_line && found[1].own_line);
        assert!(is_rule("#####") && !is_rule("# Bert's"));
    }
}
