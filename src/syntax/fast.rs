//! The fast statement path: a hand-written reader for the simplest one-line statements, the
//! ones generated files are made of (`sphere(center: [1, 2, 3], radius: 0.5).material(m)`,
//! `let r = 0.25`). It builds exactly the AST that pest and the tree builder build, spans
//! included, and gives up (returns `None`) on anything else, which pest then parses: it never
//! reports an error, so every diagnostic still comes from the grammar.
//!
//! Why it exists: pest spends about 120 000 instructions on such a line (docs/benchmarks.md,
//! "Parse speed"), and even a stripped-down pest grammar without whitespace, keywords or
//! operators still spends 27 000, too many for issue 11's 30 MB/s. This reader spends about
//! 1 500. `src/syntax/fast_tests.rs` proves it equal to pest on the whole corpus and on
//! generated statements.
//!
//! What it reads, in the grammar's terms (`ws` is spaces and tabs only):
//!
//! ```text
//! line     = (ws comment? "\n")* ws stmt ws comment? ("\n" | end)   -- and the next line must
//!            not continue the statement (see `next_line_continues`)
//! stmt     = "let" ws1 name ws "=" ws operand | operand            -- not starting with `-`
//! operand  = "-" number | primary suffix*
//! primary  = name | number | vec_lit | "true" | "false"
//! suffix   = "(" ws (arg (ws "," ws arg)*)? ws ")" | "." name      -- no space before them
//! arg      = (name ws ":" ws)? operand
//! comment  = "//" up to the end of the line
//! ```
//!
//! `number` and `vec_lit` are the grammar's tokens; `name` is an identifier that is not a
//! keyword. No operators, strings, lists, records, blocks, newlines inside a statement or
//! carriage returns: those lines go to pest.

use crate::source::{FileId, Span};
use crate::syntax::ast::{Arg, Expr, ExprKind, Let, Name, Stmt, UnOp};
use crate::syntax::errors::is_keyword;
use crate::syntax::intern::Sym;
use crate::syntax::numbers;

/// Reads the statement line starting at byte `pos` of `text`, with `end` as the end of input.
/// Returns the statement and the offset after its line (where pest's `stmt_line` would end),
/// or `None` when the line is not of the fast forms.
pub fn statement<'t>(
    file: FileId,
    text: &'t str,
    pos: usize,
    end: usize,
    memo: &mut Memo<'t>,
) -> Option<(Stmt, usize)> {
    read::<true>(file, text, pos, end, memo)
}

/// What [`statement`] would return, without building the statement: the offset after its line,
/// or `None` when the line is not of the fast forms. The same reader runs (allocating no nodes),
/// so `statement` reads every line this accepts, to the same end.
pub fn line_end<'t>(
    file: FileId,
    text: &'t str,
    pos: usize,
    end: usize,
    memo: &mut Memo<'t>,
) -> Option<usize> {
    read::<false>(file, text, pos, end, memo).map(|(_, next)| next)
}

/// [`statement`] when `BUILD`; otherwise the statement returned is a placeholder (its
/// expressions are their first operand).
fn read<'t, const BUILD: bool>(
    file: FileId,
    text: &'t str,
    pos: usize,
    end: usize,
    memo: &mut Memo<'t>,
) -> Option<(Stmt, usize)> {
    memo.args.clear();
    let mut r = Reader::<BUILD> {
        text,
        // Cut at `end`, so one bounds check is the end-of-input test too.
        bytes: &text.as_bytes()[..end],
        at: pos,
        file,
        memo,
    };
    r.blank_lines();
    r.spaces();
    let mut stmt = r.stmt()?;
    r.spaces();
    r.line_comment();
    // pest's `let_stmt` ends where its `expr` does, and that rule takes the whitespace and
    // comment after its last operand (they are skipped before its `(infix operand)*`, which
    // then matches nothing): a `let` statement's span runs to the end of the line's text.
    if let Stmt::Let(l) = &mut stmt {
        l.span.end = r.at as u32;
    }
    match r.peek() {
        None => {}
        Some(b'\n') => {
            r.at += 1;
            if r.next_line_continues() {
                return None;
            }
        }
        Some(_) => return None,
    }
    Some((stmt, r.at))
}

/// What the fast path keeps between the statements of one file.
pub struct Memo<'t> {
    /// Recent names: a generated file repeats a handful of names, and this small
    /// direct-mapped table finds them without hashing into the interner.
    names: [Option<(&'t str, Sym)>; 64],
    /// Arguments being read (nested calls stack theirs on top), so that each call's argument
    /// list is allocated once at its exact size.
    args: Vec<Arg>,
}

impl Default for Memo<'_> {
    fn default() -> Self {
        Memo {
            names: [None; 64],
            args: Vec::new(),
        }
    }
}

impl<'t> Memo<'t> {
    /// The interned name `text` (not empty).
    fn sym(&mut self, text: &'t str) -> Sym {
        let b = text.as_bytes();
        let slot = (b[0] as usize * 31 + b[b.len() - 1] as usize + b.len() * 7) % 64;
        match self.names[slot] {
            Some((known, sym)) if known == text => sym,
            _ => {
                let sym = Sym::new(text);
                self.names[slot] = Some((text, sym));
                sym
            }
        }
    }
}

/// A cursor over the input with `end` as its end; it builds the nodes it reads when `BUILD`.
struct Reader<'t, 'n, const BUILD: bool> {
    text: &'t str,
    /// The input up to its end.
    bytes: &'t [u8],
    at: usize,
    file: FileId,
    memo: &'n mut Memo<'t>,
}

/// Bit 0: a name may start with the byte; bit 1: a name may continue with it. A table, since
/// names are most of a generated line's bytes and each is read twice.
const NAME_BYTES: [u8; 256] = {
    let mut t = [0u8; 256];
    let mut c = 0;
    while c < 256 {
        let b = c as u8;
        if b.is_ascii_alphabetic() || b == b'_' {
            t[c] = 0b11;
        } else if b.is_ascii_digit() {
            t[c] = 0b10;
        }
        c += 1;
    }
    t
};

fn is_name_start(c: u8) -> bool {
    NAME_BYTES[c as usize] & 1 != 0
}

fn is_name_char(c: u8) -> bool {
    NAME_BYTES[c as usize] & 2 != 0
}

impl<'t, const BUILD: bool> Reader<'t, '_, BUILD> {
    /// `e` wrapped by `kind` (a call, member or negation) at `span`; `e` itself when only
    /// checking, which saves the box.
    fn wrap(e: Expr, kind: impl FnOnce(Box<Expr>) -> ExprKind, span: Span) -> Expr {
        if BUILD {
            Expr {
                kind: kind(Box::new(e)),
                span,
            }
        } else {
            e
        }
    }

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.at).copied()
    }

    fn peek_at(&self, i: usize) -> Option<u8> {
        self.bytes.get(i).copied()
    }

    /// The interned name `text`; only checking, a placeholder (interning is a third of the
    /// check pass's name cost, and its nodes are dropped unread).
    fn sym(&mut self, text: &'t str) -> Sym {
        if BUILD {
            self.memo.sym(text)
        } else {
            Sym::UNREAD
        }
    }

    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, start, end)
    }

    fn spaces(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t')) {
            self.at += 1;
        }
    }

    /// Skips a `//` comment up to (not over) the end of its line.
    fn line_comment(&mut self) {
        if self.peek() == Some(b'/') && self.peek_at(self.at + 1) == Some(b'/') {
            while !matches!(self.peek(), None | Some(b'\n')) {
                self.at += 1;
            }
        }
    }

    /// Skips lines holding only spaces, tabs and a `//` comment (pest's leading `nls`).
    fn blank_lines(&mut self) {
        loop {
            let line = self.at;
            self.spaces();
            self.line_comment();
            if self.peek() != Some(b'\n') {
                self.at = line;
                return;
            }
            self.at += 1;
        }
    }

    /// Whether the text after a statement's newline continues it: pest's operand and `infix`
    /// rules look past newlines (and blank and comment lines) for a member `.`, `with`, and a
    /// line operator (`||` `&&` `>>` comparisons `..` `step` `|` `**` `+` `- ` `&` `*` `/` `%`
    /// `div`). Any line starting with one of their first characters counts (a `-x` or `!x`
    /// statement too, which only sends the line before to pest).
    fn next_line_continues(&self) -> bool {
        let mut i = self.at;
        loop {
            match self.peek_at(i) {
                None => return false,
                Some(b' ' | b'\t' | b'\r' | b'\n') => i += 1,
                Some(b'/') if self.peek_at(i + 1) == Some(b'/') => {
                    while !matches!(self.peek_at(i), None | Some(b'\n')) {
                        i += 1;
                    }
                }
                // Only `with`, `step` and `div` continue: no other name needs reading.
                Some(c) if is_name_start(c) && !matches!(c, b'w' | b's' | b'd') => return false,
                Some(c) if is_name_start(c) => {
                    let start = i;
                    while self.peek_at(i).is_some_and(is_name_char) {
                        i += 1;
                    }
                    return matches!(&self.text[start..i], "with" | "step" | "div");
                }
                Some(c) => return b"|&>=!<.*+-/%".contains(&c),
            }
        }
    }

    /// `[A-Za-z_][A-Za-z0-9_]*` at the cursor: its range.
    fn word(&mut self) -> Option<(usize, usize)> {
        let start = self.at;
        if !self.peek().is_some_and(is_name_start) {
            return None;
        }
        while self.peek().is_some_and(is_name_char) {
            self.at += 1;
        }
        Some((start, self.at))
    }

    /// A name that is not a keyword.
    fn name(&mut self) -> Option<Name> {
        let (s, e) = self.word()?;
        self.name_at(s, e)
    }

    /// The word at `s..e` as a name, unless it is a keyword.
    fn name_at(&mut self, s: usize, e: usize) -> Option<Name> {
        let text = &self.text[s..e];
        if is_keyword(text) {
            return None;
        }
        Some(Name {
            sym: self.sym(text),
            span: self.span(s, e),
        })
    }

    fn stmt(&mut self) -> Option<Stmt> {
        let start = self.at;
        let text = self.text;
        if self.word().is_none_or(|(s, e)| &text[s..e] != "let") {
            self.at = start;
            // A line starting with `-` may draw pest's "does not subtract" warning.
            if self.peek() == Some(b'-') {
                return None;
            }
            return self.operand().map(Stmt::Expr);
        }
        if !matches!(self.peek(), Some(b' ' | b'\t')) {
            return None;
        }
        self.spaces();
        let name = self.name()?;
        self.spaces();
        if self.peek() != Some(b'=') {
            return None;
        }
        self.at += 1;
        self.spaces();
        let value = self.operand()?;
        let span = self.span(start, value.span.end as usize);
        Some(Stmt::Let(Let {
            public: false,
            param: false,
            name,
            ty: None,
            value,
            span,
        }))
    }

    /// One operand: a negated number, or a primary with its calls and members.
    fn operand(&mut self) -> Option<Expr> {
        let start = self.at;
        let mut e = match self.peek()? {
            b'-' => {
                self.at += 1;
                if !self.peek().is_some_and(|c| c.is_ascii_digit()) {
                    return None;
                }
                let n = self.number()?;
                if matches!(self.peek(), Some(b'(' | b'[' | b'{' | b'.')) {
                    return None;
                }
                let span = self.span(start, n.span.end as usize);
                return Some(Self::wrap(n, |n| ExprKind::Unary(UnOp::Neg, n), span));
            }
            c if c.is_ascii_digit() => self.number()?,
            b'[' => self.vec_lit()?,
            c if is_name_start(c) => {
                let (s, e) = self.word()?;
                let text = &self.text[s..e];
                let kind = match text {
                    "true" => ExprKind::Bool(true),
                    "false" => ExprKind::Bool(false),
                    _ if is_keyword(text) => return None,
                    _ => ExprKind::Ident(self.sym(text)),
                };
                Expr {
                    kind,
                    span: self.span(s, e),
                }
            }
            _ => return None,
        };
        loop {
            match self.peek() {
                Some(b'(') => {
                    let args = self.call_args()?;
                    let span = self.span(start, self.at);
                    e = Self::wrap(e, |e| ExprKind::Call(e, args), span);
                }
                Some(b'.') => {
                    self.at += 1;
                    let name = self.name()?;
                    let span = self.span(start, self.at);
                    e = Self::wrap(e, |e| ExprKind::Member(e, name), span);
                }
                Some(b'[' | b'{') => return None,
                _ => return Some(e),
            }
        }
    }

    /// `(args)` on one line, without a trailing comma.
    fn call_args(&mut self) -> Option<Vec<Arg>> {
        self.at += 1;
        self.spaces();
        if self.peek() == Some(b')') {
            self.at += 1;
            return Some(Vec::new());
        }
        let mark = self.memo.args.len();
        loop {
            let arg = self.arg()?;
            if BUILD {
                self.memo.args.push(arg);
            }
            self.spaces();
            match self.peek()? {
                b',' => {
                    self.at += 1;
                    self.spaces();
                }
                b')' => {
                    self.at += 1;
                    // Only checking: no vector (`Vec::new` does not allocate).
                    return Some(if BUILD {
                        self.memo.args.drain(mark..).collect()
                    } else {
                        Vec::new()
                    });
                }
                _ => return None,
            }
        }
    }

    /// `name: value` or `value`.
    fn arg(&mut self) -> Option<Arg> {
        let start = self.at;
        if let Some((s, e)) = self.word() {
            self.spaces();
            match self.peek() {
                Some(b':') => {
                    let name = self.name_at(s, e)?;
                    self.at += 1;
                    self.spaces();
                    let value = self.operand()?;
                    return Some(Arg {
                        name: Some(name),
                        value,
                    });
                }
                // `name = value` is the `=`-for-`:` slip, which pest reports.
                Some(b'=') => return None,
                _ => {}
            }
            self.at = start;
        }
        Some(Arg {
            name: None,
            value: self.operand()?,
        })
    }

    fn digits(&mut self) -> bool {
        let start = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.at += 1;
        }
        self.at > start
    }

    /// The digits, fraction and exponent of a number (the grammar's `number` without its unit,
    /// and `vec_num` without its sign). `None` where the grammar would read something else.
    fn unsigned_number(&mut self) -> Option<()> {
        if !self.digits() {
            return None;
        }
        if self.peek() == Some(b'.') {
            self.at += 1;
            if !self.digits() {
                return None;
            }
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            self.at += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.at += 1;
            }
            if !self.digits() {
                return None;
            }
        }
        Some(())
    }

    /// The grammar's `number` token: `3`, `0.5`, `2e6`, `30deg`, `1rad`, `0.25turn`, `45°`.
    fn number(&mut self) -> Option<Expr> {
        let start = self.at;
        self.unsigned_number()?;
        let digits = &self.text[start..self.at];
        let unit = numbers::unit_at(&self.bytes[self.at..]).map(|(len, to_radians)| {
            self.at += len;
            to_radians
        });
        if self.peek().is_some_and(is_name_char) {
            return None;
        }
        if !BUILD {
            // Only checking: whether it has a value (its placeholder is dropped unread).
            return numbers::has_value(digits).then(|| Expr {
                kind: ExprKind::Int(0),
                span: self.span(start, self.at),
            });
        }
        let kind = numbers::apply_unit(numbers::plain(digits).ok()?, unit);
        Some(Expr {
            kind,
            span: self.span(start, self.at),
        })
    }

    /// The grammar's `vec_lit` token: `[x, y, z]` of plain numbers on one line.
    fn vec_lit(&mut self) -> Option<Expr> {
        let start = self.at;
        self.at += 1;
        let mut out = [0.0; 3];
        for (k, slot) in out.iter_mut().enumerate() {
            self.spaces();
            let s = self.at;
            if self.peek() == Some(b'-') {
                self.at += 1;
            }
            self.unsigned_number()?;
            let text = &self.text[s..self.at];
            if BUILD {
                *slot = numbers::component(&numbers::plain(text).ok()?);
            } else if !numbers::has_value(text) {
                return None;
            }
            self.spaces();
            let closer = if k == 2 { b']' } else { b',' };
            if self.peek() != Some(closer) {
                return None;
            }
            self.at += 1;
        }
        Some(Expr {
            kind: ExprKind::Vec3(out),
            span: self.span(start, self.at),
        })
    }
}
