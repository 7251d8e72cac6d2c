//! Printing a [`Plan`]: spaces between tokens by their roles, line breaks as planned or written
//! (at most one blank line, none after an opener or before a closer), four spaces of indent
//! per open bracket line plus one level for a continued expression, comments where they were.

use super::layout::{Brk, Plan};
use super::tokens::{Kind, Tok, Tokens, Trivia};

/// One indentation level.
const INDENT: &str = "    ";

/// The printed text and the output line of every token (for the width check).
pub(super) struct Printed {
    /// The formatted file.
    pub(crate) text: String,
    /// 0-based output line of each token.
    pub(crate) tok_line: Vec<usize>,
}

/// Prints the tokens as `plan` says.
pub(super) fn print(t: &Tokens, plan: &Plan) -> Printed {
    let mut p = Printer {
        t,
        out: String::new(),
        line: 0,
        tok_line: vec![0; t.toks.len()],
        stack: Vec::new(),
        line_indent: 0,
        prev: None,
        after_open: false,
        trailing: Vec::new(),
    };
    let mut carried: Vec<Trivia> = Vec::new();
    for (i, tok) in t.toks.iter().enumerate() {
        if plan.skip[i] {
            carried.extend(tok.before.iter().cloned());
            continue;
        }
        let trivia: Vec<Trivia> = carried
            .drain(..)
            .chain(tok.before.iter().cloned())
            .collect();
        p.gap(&trivia, Some(i), plan.brk[i]);
        p.tok_line[i] = p.line;
        p.out.push_str(&tok.text);
        if plan.comma_after[i] {
            p.out.push(',');
        }
        match tok.kind {
            Kind::Open(_) => p.stack.push(p.line_indent + 1),
            Kind::Close(_) => {
                p.stack.pop();
            }
            _ => {}
        }
        p.after_open = matches!(tok.kind, Kind::Open(_));
        p.prev = Some(i);
    }
    let tail: Vec<Trivia> = carried.into_iter().chain(t.tail.iter().cloned()).collect();
    p.gap(&tail, None, Brk::Auto);
    let mut text = align_trailing(p.out.trim_end(), &p.trailing);
    text.push('\n');
    Printed {
        text,
        tok_line: p.tok_line,
    }
}

struct Printer<'a> {
    t: &'a Tokens,
    out: String,
    /// Current output line (0-based).
    line: usize,
    tok_line: Vec<usize>,
    /// The indent of the lines inside each open bracket: its opener line's indent plus one.
    stack: Vec<usize>,
    /// Indent of the current output line.
    line_indent: usize,
    /// The last token printed.
    prev: Option<usize>,
    /// Nothing but an opener printed since the line began or the last comment.
    after_open: bool,
    /// `(line, byte in line)` of every `//` comment that follows code on its line.
    trailing: Vec<(usize, usize)>,
}

impl Printer<'_> {
    fn tok(&self, i: usize) -> &Tok {
        &self.t.toks[i]
    }

    /// Prints the trivia before token `next` (or the end of the file) and the gap to it.
    fn gap(&mut self, trivia: &[Trivia], next: Option<usize>, brk: Brk) {
        let mut newlines = 0;
        let mut after_comment = false;
        let mut after_line_comment = false;
        for tv in trivia {
            match tv {
                Trivia::Newline => newlines += 1,
                Trivia::Comment { text, line } => {
                    if newlines > 0 {
                        self.newlines(newlines, next);
                        let indent = self.comment_indent(next);
                        self.indent(indent);
                    } else if !self.out.is_empty() && !self.glued_to_prev() {
                        self.out.push(' ');
                        if *line {
                            let line_start = self.out.rfind('\n').map_or(0, |n| n + 1);
                            self.trailing.push((self.line, self.out.len() - line_start));
                        }
                    }
                    self.out.push_str(text);
                    self.line += text.matches('\n').count();
                    self.after_open = false;
                    newlines = 0;
                    after_comment = true;
                    after_line_comment = *line;
                }
            }
        }
        let Some(i) = next else { return };
        let join = brk == Brk::Join && !after_line_comment;
        if self.out.is_empty() {
            return;
        }
        if (newlines > 0 && !join) || brk == Brk::Force || after_line_comment {
            self.newlines(newlines.max(1), next);
            let indent = self.indent_for(i);
            self.indent(indent);
        } else if after_comment
            || self
                .prev
                .is_some_and(|p| space_between(self.tok(p), self.tok(i)))
        {
            self.out.push(' ');
        }
    }

    /// A prefix `-` or `!` keeps even a comment glued: `- /* c */ x` at a line start would
    /// subtract from the line above.
    fn glued_to_prev(&self) -> bool {
        self.prev.is_some_and(|p| self.tok(p).kind == Kind::Unary) && self.out.ends_with(['-', '!'])
    }

    /// Ends the line (and at most one blank line; none at the start of the file, after an
    /// opener or before a closer).
    fn newlines(&mut self, n: usize, next: Option<usize>) {
        if self.out.is_empty() {
            return;
        }
        let closer = next.is_some_and(|i| matches!(self.tok(i).kind, Kind::Close(_)));
        let n = if self.after_open || closer {
            1
        } else {
            n.min(2)
        };
        let trimmed = self.out.trim_end_matches([' ', '\t']).len();
        self.out.truncate(trimmed);
        for _ in 0..n {
            self.out.push('\n');
        }
        self.line += n;
    }

    fn indent(&mut self, level: usize) {
        self.line_indent = level;
        for _ in 0..level {
            self.out.push_str(INDENT);
        }
    }

    /// The indent of a line starting with token `i`.
    fn indent_for(&self, i: usize) -> usize {
        let depth = self.stack.last().copied().unwrap_or(0);
        if matches!(self.tok(i).kind, Kind::Close(_)) {
            return depth.saturating_sub(1);
        }
        depth + usize::from(self.continues(i))
    }

    /// A comment line is indented like the token after it, or like the items when a closer
    /// follows.
    fn comment_indent(&self, next: Option<usize>) -> usize {
        match next {
            Some(i) if !matches!(self.tok(i).kind, Kind::Close(_)) => self.indent_for(i),
            Some(_) => self.stack.last().copied().unwrap_or(0),
            None => 0,
        }
    }

    /// A line starting with token `i` continues an expression: it starts with an operator,
    /// `.member` or `with`, or the line before ended with an operator, `=`, `:` or `->`.
    fn continues(&self, i: usize) -> bool {
        let t = self.tok(i);
        let starts = matches!(t.kind, Kind::Bin | Kind::Range | Kind::Dot)
            || (t.kind == Kind::Word && t.text == "with");
        let ended = self.prev.is_some_and(|p| {
            matches!(
                self.tok(p).kind,
                Kind::Bin | Kind::Range | Kind::Eq | Kind::Colon | Kind::Arrow
            )
        });
        starts || ended
    }
}

/// Aligns the `//` comments that follow code on consecutive lines one space after the longest
/// code among them (`trailing` holds each such line and its comment's byte in the line).
fn align_trailing(text: &str, trailing: &[(usize, usize)]) -> String {
    let mut lines: Vec<String> = text.split('\n').map(str::to_owned).collect();
    let mut k = 0;
    while k < trailing.len() {
        let mut end = k + 1;
        while end < trailing.len() && trailing[end].0 == trailing[end - 1].0 + 1 {
            end += 1;
        }
        let run = &trailing[k..end];
        let widths: Vec<usize> = run
            .iter()
            .map(|&(l, at)| lines[l][..at].chars().count())
            .collect();
        let column = widths.iter().copied().max().unwrap_or(0);
        for (&(l, at), w) in run.iter().zip(widths) {
            lines[l].insert_str(at, &" ".repeat(column - w));
        }
        k = end;
    }
    lines.join("\n")
}

/// Whether one space separates `a` and `b` on a line.
fn space_between(a: &Tok, b: &Tok) -> bool {
    use Kind::*;
    match (a.kind, b.kind) {
        (Open(_), Close(_)) => false,
        (_, Comma | Colon | Question | Dot | TypeOpen | TypeClose) => false,
        (Dot | Unary | TypeOpen, _) => false,
        (Range, _) | (_, Range) => false,
        (_, Close(br)) | (Open(br), _) => br.padded(),
        (
            _,
            Open(super::tokens::Br::Call | super::tokens::Br::Index | super::tokens::Br::Params),
        ) => false,
        _ => true,
    }
}
