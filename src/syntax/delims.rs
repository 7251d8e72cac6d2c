//! A fast pre-scan of brackets, strings and comments. It finds unclosed and mismatched delimiters
//! precisely (pest alone would report them at the end of the file) and tells the statement
//! driver where top-level lines start, for recovery.

use crate::diag::Diagnostic;
use crate::source::{FileId, Span};

/// What the scan learned.
#[derive(Debug, PartialEq)]
pub(crate) struct Scan {
    /// Delimiter and string errors (at most one: later ones usually cascade).
    pub(crate) errors: Vec<Diagnostic>,
    /// Lexical warnings (`n // 2`, where `//` starts a comment).
    pub(crate) warnings: Vec<Diagnostic>,
    /// Byte offsets of line starts whose bracket depth is zero.
    pub(crate) top_level_lines: Vec<usize>,
    /// The deepest bracket nesting scanned (outside strings and comments).
    pub(crate) max_depth: usize,
}

fn closer_of(open: u8) -> u8 {
    match open {
        b'(' => b')',
        b'[' => b']',
        _ => b'}',
    }
}

/// The bytes the scan acts on; it steps over every other byte without looking further.
const SPECIAL: [bool; 256] = {
    let mut t = [false; 256];
    let mut k = 0;
    while k < 9 {
        t[b"\n/\"([{)]}"[k] as usize] = true;
        k += 1;
    }
    t
};

/// Texts from this size on are scanned in parts on every core.
const PARALLEL_BYTES: usize = 1 << 20;

/// Scans `text` for delimiter balance.
pub(crate) fn scan(file: FileId, text: &str) -> Scan {
    if text.len() < PARALLEL_BYTES {
        return scan_range(file, text, 0, text.len());
    }
    scan_in_parts(file, text, PARALLEL_BYTES / 4)
}

/// [`scan`] of parts of about `part` bytes, cut after newlines, on every core. Each part is
/// scanned as if it started at depth zero outside any comment; that holds when every part
/// ends at depth zero without an error (as in a file of one-line statements), and then the
/// parts' findings, in order, are the whole scan's. Otherwise the text is scanned whole.
fn scan_in_parts(file: FileId, text: &str, part: usize) -> Scan {
    use rayon::prelude::*;
    let mut cuts = vec![0];
    while let Some(&last) = cuts.last() {
        let want = last + part;
        if want >= text.len() {
            break;
        }
        match memchr::memchr(b'\n', &text.as_bytes()[want..]) {
            Some(nl) if want + nl + 1 < text.len() => cuts.push(want + nl + 1),
            _ => break,
        }
    }
    cuts.push(text.len());
    let parts: Vec<Scan> = cuts
        .par_windows(2)
        .map(|w| scan_range(file, text, w[0], w[1]))
        .collect();
    // A part scanned whole ends at depth zero: an unclosed opener would be an error.
    if parts.iter().any(|p| !p.errors.is_empty()) {
        return scan_range(file, text, 0, text.len());
    }
    let mut whole = Scan {
        errors: Vec::new(),
        warnings: Vec::new(),
        top_level_lines: Vec::with_capacity(parts.iter().map(|p| p.top_level_lines.len()).sum()),
        max_depth: 0,
    };
    for (k, p) in parts.into_iter().enumerate() {
        // A part's first line is the line the part before it ended with.
        let skip = usize::from(k > 0);
        whole.top_level_lines.extend(&p.top_level_lines[skip..]);
        whole.warnings.extend(p.warnings);
        whole.max_depth = whole.max_depth.max(p.max_depth);
    }
    whole
}

/// Scans `text[from..to]`, starting at depth zero outside any comment or string.
fn scan_range(file: FileId, text: &str, from: usize, to: usize) -> Scan {
    let b = &text.as_bytes()[..to];
    let mut stack: Vec<(u8, usize)> = Vec::new();
    let mut errors = Vec::new();
    let mut warnings = Vec::new();
    let mut top_level_lines = vec![from];
    let mut max_depth = 0;
    let mut i = from;
    let sp = |s: usize, e: usize| Span::new(file, s, e);
    while i < b.len() {
        if !SPECIAL[b[i] as usize] {
            i += 1;
            continue;
        }
        match b[i] {
            b'\n' => {
                if stack.is_empty() {
                    top_level_lines.push(i + 1);
                }
                i += 1;
            }
            b'/' if b.get(i + 1) == Some(&b'/') => {
                warnings.extend(division_comment(file, text, i));
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                let start = i;
                i += 2;
                while i < b.len() && !(b[i] == b'*' && b.get(i + 1) == Some(&b'/')) {
                    i += 1;
                }
                if i >= b.len() {
                    errors.push(
                        Diagnostic::error(
                            "rtc::syntax::unclosed",
                            sp(start, start + 2),
                            "unclosed comment",
                        )
                        .with_label("this comment is never closed")
                        .with_help("end it with `*/`"),
                    );
                    break;
                }
                i += 2;
            }
            b'"' => {
                let start = i;
                i += 1;
                while i < b.len() && b[i] != b'"' && b[i] != b'\n' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                if i >= b.len() || b[i] == b'\n' {
                    errors.push(
                        Diagnostic::error(
                            "rtc::syntax::unclosed",
                            sp(start, start + 1),
                            "unterminated string",
                        )
                        .with_label("this string is never closed")
                        .with_help("close it with `\"` on the same line"),
                    );
                    return Scan {
                        errors,
                        warnings,
                        top_level_lines,
                        max_depth,
                    };
                }
                i += 1;
            }
            c @ (b'(' | b'[' | b'{') => {
                stack.push((c, i));
                max_depth = max_depth.max(stack.len());
                i += 1;
            }
            c @ (b')' | b']' | b'}') => {
                match stack.pop() {
                    None => {
                        errors.push(
                            Diagnostic::error(
                                "rtc::syntax::unmatched",
                                sp(i, i + 1),
                                format!("unexpected `{}`", c as char),
                            )
                            .with_label("nothing is open here")
                            .with_help(format!("remove this `{}`", c as char)),
                        );
                        return Scan {
                            errors,
                            warnings,
                            top_level_lines,
                            max_depth,
                        };
                    }
                    Some((open, at)) if closer_of(open) != c => {
                        errors.push(
                            Diagnostic::error(
                                "rtc::syntax::unmatched",
                                sp(i, i + 1),
                                format!("mismatched `{}`", c as char),
                            )
                            .with_label(format!("expected `{}` here", closer_of(open) as char))
                            .with_secondary(
                                sp(at, at + 1),
                                format!("to close this `{}`", open as char),
                            )
                            .with_help(format!(
                                "write `{}` to close the `{}` first",
                                closer_of(open) as char,
                                open as char
                            )),
                        );
                        return Scan {
                            errors,
                            warnings,
                            top_level_lines,
                            max_depth,
                        };
                    }
                    Some(_) => {}
                }
                i += 1;
            }
            _ => i += 1,
        }
    }
    // The earliest opener still open: later ones are usually inside it.
    if let Some(&(open, at)) = stack.first() {
        let mut d = Diagnostic::error(
            "rtc::syntax::unclosed",
            sp(at, at + 1),
            format!("unclosed `{}`", open as char),
        )
        .with_label("this delimiter is never closed")
        .with_help(format!("add the missing `{}`", closer_of(open) as char));
        if let Some(line) = dedented_line_after(text, at) {
            // The label covers the line's first character whole (it may take several bytes).
            let first = text[line..].chars().next().map_or(0, char::len_utf8);
            d = d.with_secondary(
                sp(line, line + first.max(1)),
                format!(
                    "perhaps the `{}` belongs before this line",
                    closer_of(open) as char
                ),
            );
        }
        errors.push(d);
    }
    Scan {
        errors,
        warnings,
        top_level_lines,
        max_depth,
    }
}

/// `n // 2`: a `//` right after a value, followed by a number, reads like division but starts a
/// comment. Warned, because the statement silently means `n`. A comment that starts with a word
/// (`r // radius`, `x // 2 spheres`), or that lists numbers (`x // 1, 2, 4`), is not warned.
fn division_comment(file: FileId, text: &str, at: usize) -> Option<Diagnostic> {
    let line_start = text[..at].rfind('\n').map_or(0, |p| p + 1);
    let before = text[line_start..at].trim_end();
    let operand = before
        .rsplit(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | ')' | ']')))
        .next()
        .filter(|w| !w.is_empty())?;
    // After a call or a bracket the word before `//` is not the whole operand: no guess.
    let operand = if operand.ends_with([')', ']']) || operand.contains(['(', '[']) {
        "x"
    } else {
        operand
    };
    let line_end = text[at..].find('\n').map_or(text.len(), |p| at + p);
    let comment = text[at + 2..line_end].trim();
    let digits = comment
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(comment.len());
    let (number, rest) = comment.split_at(digits);
    let rest = rest.trim_start();
    // A comma ends an item only at the end of the line (`n // 2,` in a list); a comma with more
    // after it (`// 1, 2, 4`) is an enumeration: clearly a comment.
    let reads_as_math = rest.is_empty()
        || rest.starts_with(['+', '-', '*', '/', ')', ']'])
        || rest.trim_end() == ",";
    if number.is_empty() || !number.starts_with(|c: char| c.is_ascii_digit()) || !reads_as_math {
        return None;
    }
    Some(
        Diagnostic::warning(
            "rtc::syntax::comment_division",
            Span::new(file, at, at + 2),
            format!("`//` starts a comment, so `// {number}` is ignored"),
        )
        .with_label("the rest of the line is a comment")
        .with_help(format!(
            "for integer division write `{operand} div {number}`; for a comment, start it with a word"
        )),
    )
}

fn indent_of(line: &str) -> usize {
    line.len() - line.trim_start().len()
}

/// The first non-blank line after `at`'s line that is indented no deeper than that line: a good
/// guess for where a missing closer belongs.
fn dedented_line_after(text: &str, at: usize) -> Option<usize> {
    let line_start = text[..at].rfind('\n').map_or(0, |p| p + 1);
    let open_indent = indent_of(text[line_start..].lines().next().unwrap_or(""));
    let mut offset = text[at..].find('\n').map(|p| at + p + 1)?;
    while offset < text.len() {
        let line = text[offset..].lines().next().unwrap_or("");
        let trimmed = line.trim_start();
        if !trimmed.is_empty() && !trimmed.starts_with("//") && indent_of(line) <= open_indent {
            return Some(offset + indent_of(line));
        }
        offset += line.len() + 1;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Found by the rtc_eval fuzzer: a label one byte long cut the line's first character,
    /// which takes two bytes in UTF-8.
    #[test]
    fn the_closer_hint_covers_a_multibyte_first_character() {
        let text = "rtc 1\nprint(1,\n\u{4d9}ssert(2)\n";
        let scan = scan(FileId(0), text);
        let d = &scan.errors[0];
        assert_eq!(d.code, "rtc::syntax::unclosed");
        let hint = d.labels[0].span;
        assert_eq!(&text[hint.start as usize..hint.end as usize], "\u{4d9}");
    }

    /// Scanning in parts gives the whole scan's findings, whatever the cut: where every part
    /// ends at depth zero (one-line statements, comments, strings with brackets, `n // 2`)
    /// and where one does not (a list over several lines, a block comment across a cut) or
    /// the text has an error (then the whole text is scanned).
    #[test]
    fn a_scan_in_parts_finds_what_the_whole_scan_finds() {
        let lines = [
            "sphere(center: [1, 2, 3], radius: 0.5).material(m)\n",
            "let n = 4 // 2\n",
            "print(\"(( [{\")\n",
            "// a comment (with [brackets]\n",
            "\n",
        ];
        let mut plain = String::from("rtc 1\n");
        for k in 0..200 {
            plain.push_str(lines[k % lines.len()]);
        }
        let mut texts = vec![plain.clone()];
        for odd in [
            "let xs = [\n  1,\n  2\n]\n",
            "/* a block comment\n over lines ( */\n",
            "let bad = (1, 2]\n",
            "let open = (1,\n",
            "print(\"unterminated)\n",
            "let stray = 1)\n",
        ] {
            let at = plain.len() / 2;
            let at = plain[at..].find('\n').map_or(at, |p| at + p + 1);
            texts.push(format!("{}{odd}{}", &plain[..at], &plain[at..]));
        }
        for text in &texts {
            let whole = scan_range(FileId(0), text, 0, text.len());
            for part in [1, 7, 64, 500] {
                assert_eq!(
                    scan_in_parts(FileId(0), text, part),
                    whole,
                    "parts of {part}"
                );
            }
        }
    }
}
