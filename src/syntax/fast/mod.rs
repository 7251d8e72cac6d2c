//! The fast statement path: a hand-written reader for the simplest one-line statements, the
//! ones generated files are made of (`sphere(center: [1, 2, 3], radius: 0.5).material(m)`,
//! `let r = 0.25`). It reads a line once, on any core, into a tape (tape.rs) from which the
//! evaluating thread builds exactly the AST that pest and the tree builder build, spans
//! included. It gives up (returns `None`) on anything else, which pest then parses: it never
//! reports an error, so every diagnostic still comes from the grammar.
//!
//! Why it exists: pest spends about 120 000 instructions on such a line (docs/benchmarks.md,
//! "Parse speed"), and even a stripped-down pest grammar without whitespace, keywords or
//! operators still spends 27 000, too many for issue 11's 30 MB/s. This reader spends about
//! 3 000 with its numbers converted, and building from the tape about 1 300.
//! `src/syntax/fast_tests.rs` proves it equal to pest on the whole corpus and on generated
//! statements.
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

mod tape;

pub(crate) use tape::{Mark, Memo, Tape, build as statement, build_into as statement_into};
use tape::{Op, Step};

use crate::syntax::errors::is_keyword;
use crate::syntax::numbers::{self, Number};

/// Reads the statement line starting at byte `pos` of `text`, with `end` as the end of input,
/// and appends what it read to `tape` (see [`tape`]). Returns the offset after its line (where
/// pest's `stmt_line` would end), or `None` (and `tape` unchanged) when the line is not of the
/// fast forms. Pure: the same text and position give the same steps on any thread.
pub(crate) fn read(text: &str, pos: usize, end: usize, tape: &mut Tape) -> Option<usize> {
    let mark = tape.mark();
    let next = Reader {
        text,
        // Cut at `end`, so one bounds check is the end-of-input test too.
        bytes: &text.as_bytes()[..end],
        at: pos,
        tape,
    }
    .line();
    if next.is_none() {
        tape.truncate(mark);
    }
    next
}

/// A cursor over the input with `end` as its end, writing what it reads to a tape.
struct Reader<'t, 'o> {
    text: &'t str,
    /// The input up to its end.
    bytes: &'t [u8],
    at: usize,
    tape: &'o mut Tape,
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

impl Reader<'_, '_> {
    /// The whole line: blank and comment lines, the statement, its trailing comment and
    /// newline. The offset after it, or `None` where pest must read it.
    fn line(&mut self) -> Option<usize> {
        self.blank_lines();
        self.spaces();
        let head = self.stmt()?;
        self.spaces();
        self.line_comment();
        // pest's `let_stmt` ends where its `expr` does, and that rule takes the whitespace and
        // comment after its last operand (they are skipped before its `(infix operand)*`, which
        // then matches nothing): a `let` statement's span runs to the end of the line's text.
        if let Some(h) = head {
            self.tape.values[h] = self.at as u64;
        }
        self.push(Step::End, self.at, self.at)?;
        match self.peek() {
            None => {}
            Some(b'\n') => {
                self.at += 1;
                if self.next_line_continues() {
                    return None;
                }
            }
            Some(_) => return None,
        }
        Some(self.at)
    }

    /// Writes a step over `start..end` (numbering it if it is a name); `None` when it does not
    /// fit one.
    fn push(&mut self, step: Step, start: usize, end: usize) -> Option<()> {
        let mut op = Op::new(step, start, end)?;
        if matches!(step, Step::Ident | Step::Named | Step::Member | Step::Name) {
            op.name = self.tape.names.number(self.text, op.start, op.len);
        }
        self.tape.ops.push(op);
        Some(())
    }

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.at).copied()
    }

    fn peek_at(&self, i: usize) -> Option<u8> {
        self.bytes.get(i).copied()
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

    /// The word at `s..e` as a name (a `step` over it), unless it is a keyword.
    fn name_at(&mut self, step: Step, s: usize, e: usize) -> Option<()> {
        if is_keyword(&self.text[s..e]) {
            return None;
        }
        self.push(step, s, e)
    }

    /// The statement; for a `let`, where its span's end goes in the value stream (the line
    /// sets it).
    fn stmt(&mut self) -> Option<Option<usize>> {
        let start = self.at;
        let text = self.text;
        if self.word().is_none_or(|(s, e)| &text[s..e] != "let") {
            self.at = start;
            // A line starting with `-` may draw pest's "does not subtract" warning.
            if self.peek() == Some(b'-') {
                return None;
            }
            self.operand()?;
            return Some(None);
        }
        if !matches!(self.peek(), Some(b' ' | b'\t')) {
            return None;
        }
        self.push(Step::Let, start, start)?;
        let head = self.tape.values.len();
        self.tape.values.push(0);
        self.spaces();
        let (s, e) = self.word()?;
        self.name_at(Step::Name, s, e)?;
        self.spaces();
        if self.peek() != Some(b'=') {
            return None;
        }
        self.at += 1;
        self.spaces();
        self.operand()?;
        Some(Some(head))
    }

    /// One operand: a negated number, or a primary with its calls and members.
    fn operand(&mut self) -> Option<()> {
        let start = self.at;
        match self.peek()? {
            b'-' => {
                self.at += 1;
                if !self.peek().is_some_and(|c| c.is_ascii_digit()) {
                    return None;
                }
                self.number()?;
                if matches!(self.peek(), Some(b'(' | b'[' | b'{' | b'.')) {
                    return None;
                }
                return self.push(Step::Neg, start, start);
            }
            c if c.is_ascii_digit() => self.number()?,
            b'[' => self.vec_lit()?,
            c if is_name_start(c) => {
                let (s, e) = self.word()?;
                let step = match &self.text[s..e] {
                    "true" | "false" => Step::Bool,
                    text if is_keyword(text) => return None,
                    _ => Step::Ident,
                };
                self.push(step, s, e)?;
            }
            _ => return None,
        }
        // A chain longer than the budget goes to pest, whose tree builder reports it.
        let mut suffixes = 0usize;
        loop {
            suffixes += 1;
            if suffixes > crate::syntax::build::MAX_CHAIN {
                return None;
            }
            match self.peek() {
                Some(b'(') => {
                    // A call's step holds its argument count and where it ends.
                    let args = u16::try_from(self.call_args()?).ok()?;
                    let end = u32::try_from(self.at).ok()?;
                    self.tape.ops.push(Op {
                        start: end,
                        len: args,
                        step: Step::Call,
                        name: tape::UNNUMBERED,
                    });
                }
                Some(b'.') => {
                    self.at += 1;
                    let (s, e) = self.word()?;
                    self.name_at(Step::Member, s, e)?;
                }
                Some(b'[' | b'{') => return None,
                _ => return Some(()),
            }
        }
    }

    /// `(args)` on one line, without a trailing comma: how many arguments.
    fn call_args(&mut self) -> Option<u64> {
        self.at += 1;
        self.spaces();
        if self.peek() == Some(b')') {
            self.at += 1;
            return Some(0);
        }
        let mut count = 0;
        loop {
            self.arg()?;
            count += 1;
            self.spaces();
            match self.peek()? {
                b',' => {
                    self.at += 1;
                    self.spaces();
                }
                b')' => {
                    self.at += 1;
                    return Some(count);
                }
                _ => return None,
            }
        }
    }

    /// `name: value` or `value`.
    fn arg(&mut self) -> Option<()> {
        let start = self.at;
        if let Some((s, e)) = self.word() {
            self.spaces();
            match self.peek() {
                Some(b':') => {
                    if is_keyword(&self.text[s..e]) {
                        return None;
                    }
                    self.at += 1;
                    self.spaces();
                    self.operand()?;
                    // After its value, which is on top when building reaches it.
                    return self.push(Step::Named, s, e);
                }
                // `name = value` is the `=`-for-`:` slip, which pest reports.
                Some(b'=') => return None,
                _ => {}
            }
            self.at = start;
        }
        self.operand()
    }

    /// The digits, fraction and exponent of a number (the grammar's `number` without its unit,
    /// and `vec_num` without its sign), with its value when one pass could tell it
    /// ([`numbers::unsigned`]). `None` where the grammar would read something else.
    fn unsigned_number(&mut self) -> Option<Option<Number>> {
        let (len, value) = numbers::unsigned(&self.bytes[self.at..])?;
        self.at += len;
        Some(value)
    }

    /// The grammar's `number` token: `3`, `0.5`, `2e6`, `30deg`, `1rad`, `0.25turn`, `45°`.
    fn number(&mut self) -> Option<()> {
        let start = self.at;
        let quick = self.unsigned_number()?;
        let digits = &self.text[start..self.at];
        let value = match quick {
            Some(n) => n,
            None => numbers::plain(digits).ok()?,
        };
        let unit = numbers::unit_at(&self.bytes[self.at..]).map(|(len, to_radians)| {
            self.at += len;
            to_radians
        });
        if self.peek().is_some_and(is_name_char) {
            return None;
        }
        let (step, bits) = match numbers::apply_unit(value, unit) {
            Number::Int(i) => (Step::Int, i as u64),
            Number::Float(f) => (Step::Float, f.to_bits()),
            Number::Angle(a) => (Step::Angle, a.to_bits()),
        };
        self.push(step, start, self.at)?;
        self.tape.values.push(bits);
        Some(())
    }

    /// The grammar's `vec_lit` token: `[x, y, z]` of plain numbers on one line.
    fn vec_lit(&mut self) -> Option<()> {
        let start = self.at;
        self.at += 1;
        let mut out = [0.0; 3];
        for (k, slot) in out.iter_mut().enumerate() {
            self.spaces();
            let s = self.at;
            let (len, quick) = numbers::signed(&self.bytes[s..])?;
            self.at += len;
            let value = match quick {
                Some(n) => n,
                None => numbers::plain(&self.text[s..self.at]).ok()?,
            };
            *slot = numbers::component(value);
            self.spaces();
            let closer = if k == 2 { b']' } else { b',' };
            if self.peek() != Some(closer) {
                return None;
            }
            self.at += 1;
        }
        self.push(Step::Vec3, start, self.at)?;
        self.tape.values.extend(out.map(f64::to_bits));
        Some(())
    }
}
