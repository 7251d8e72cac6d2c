//! The fast path's tape: what reading a line found, as a flat list of steps that building the
//! statement replays without looking at the text again (except to intern its names).
//!
//! Why a tape: reading a line (finding where it ends, converting its numbers) is a pure function
//! of the text, so it runs on every core; interning names is not (the interner belongs to the
//! evaluating thread), and neither is building, which allocates the nodes evaluation reads and
//! drops. So the parallel pass writes what it read here, and the evaluating thread builds each
//! statement from it: one reading of the text instead of two.
//!
//! A tape is two streams: steps of 8 bytes (a token's place and length) and the 64-bit values
//! of numbers, read in the same order. A sphere line of a generated file takes ~110 bytes;
//! compactness matters, since a generated file's tape is in memory while the file is.
//!
//! Names: the reader numbers the distinct names of its tape (a generated file repeats a
//! handful), and a name step carries its number, so building interns each distinct name once
//! a tape and then looks it up by number; finding the repeats is the reader's work, on every
//! core, instead of the evaluating thread's.

use crate::source::{FileId, Span};
use crate::syntax::ast::{Arg, Expr, ExprKind, Let, Name, Stmt, UnOp};
use crate::syntax::intern::Sym;

/// What a step does. Leaves push an operand; the others change the operands on top.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Step {
    /// An integer; its value (the `i64`) is next in the value stream.
    Int,
    /// A float; its value (the `f64`) is next in the value stream.
    Float,
    /// An angle in radians; its value (the `f64`) is next in the value stream.
    Angle,
    /// `true` or `false` (told apart by their length).
    Bool,
    /// `[x, y, z]`: its three components are next in the value stream.
    Vec3,
    /// A name used as a value.
    Ident,
    /// `-` at `start` negating the number on top.
    Neg,
    /// The argument on top is named by this step's name.
    Named,
    /// A call of the operand below the top `len` arguments; `start` is the offset after its `)`.
    Call,
    /// `.name` (this step's name) of the operand on top.
    Member,
    /// A `let` statement's head (first step of its line), at its start; the end of its span is
    /// next in the value stream, its name is the next step (`Name`), the rest its value.
    Let,
    /// The name a `let` binds.
    Name,
    /// The statement is complete.
    End,
}

/// One step: a token at `start..start + len` (except where [`Step`] says otherwise).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Op {
    pub(super) start: u32,
    pub(super) len: u16,
    pub(super) step: Step,
    /// A name step's number in its tape's [`Names`]; [`UNNUMBERED`] otherwise, or when the
    /// table was full.
    pub(super) name: u8,
}

/// The number of a step that is not a numbered name.
pub(super) const UNNUMBERED: u8 = u8::MAX;

impl Op {
    /// A step over `start..end`, or `None` when the token is too long for a step (pest then
    /// reads the line).
    pub(super) fn new(step: Step, start: usize, end: usize) -> Option<Op> {
        Some(Op {
            start: u32::try_from(start).ok()?,
            len: u16::try_from(end - start).ok()?,
            step,
            name: UNNUMBERED,
        })
    }

    fn end(&self) -> u32 {
        self.start + self.len as u32
    }
}

/// What the fast path read from some lines: their steps, the values of their numbers, and
/// their distinct names.
#[derive(Clone, Default, Debug)]
pub(crate) struct Tape {
    pub(super) ops: Vec<Op>,
    pub(super) values: Vec<u64>,
    pub(super) names: Names,
}

/// A tape's distinct names, numbered in the order first read: each is kept as the place of its
/// first occurrence in the text.
#[derive(Clone, Debug)]
pub(super) struct Names {
    first: Vec<(u32, u16)>,
    /// A direct-mapped index into `first` (plus one; zero is empty): the repeats of a generated
    /// file's few names are found without hashing.
    slots: [u8; NAME_SLOTS],
}

const NAME_SLOTS: usize = 64;

impl Default for Names {
    fn default() -> Self {
        Names {
            first: Vec::new(),
            slots: [0; NAME_SLOTS],
        }
    }
}

/// Where a name's slot is: a hash of its first and last bytes and its length.
fn slot_of(name: &[u8]) -> usize {
    (name[0] as usize * 31 + name[name.len() - 1] as usize + name.len() * 7) % NAME_SLOTS
}

impl Names {
    /// The number of the name `text[start..start + len]` (not empty), numbering it if it is new;
    /// [`UNNUMBERED`] once 254 names are numbered and its slot holds another.
    pub(super) fn number(&mut self, text: &str, start: u32, len: u16) -> u8 {
        let name = &text.as_bytes()[start as usize..start as usize + len as usize];
        let slot = slot_of(name);
        let held = self.slots[slot];
        if held != 0 {
            let (s, l) = self.first[held as usize - 1];
            if &text.as_bytes()[s as usize..s as usize + l as usize] == name {
                return held - 1;
            }
        }
        // A name whose slot another holds is numbered again (a second number for the same
        // name is harmless: both intern to the same `Sym`).
        if self.first.len() >= UNNUMBERED as usize {
            return UNNUMBERED;
        }
        self.first.push((start, len));
        self.slots[slot] = self.first.len() as u8;
        self.first.len() as u8 - 1
    }
}

/// Where a statement starts on its tape.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Mark {
    /// Its first step.
    op: u32,
    /// Its first value.
    value: u32,
}

impl Tape {
    /// An empty tape with room for what reading `bytes` of generated lines writes (a sphere
    /// line of ~60 bytes writes ~10 steps and 4 values), so it is not copied as it grows.
    pub(crate) fn for_bytes(bytes: usize) -> Tape {
        Tape {
            ops: Vec::with_capacity(bytes / 5),
            values: Vec::with_capacity(bytes / 12),
            names: Names::default(),
        }
    }

    /// Where the next statement written starts.
    pub(crate) fn mark(&self) -> Mark {
        Mark {
            op: self.ops.len() as u32,
            value: self.values.len() as u32,
        }
    }

    /// Forgets what was written since `mark`.
    pub(super) fn truncate(&mut self, mark: Mark) {
        self.ops.truncate(mark.op as usize);
        self.values.truncate(mark.value as usize);
    }
}

/// Reads a tape from a statement's mark on: steps and values in order.
struct Cursor<'a> {
    ops: &'a [Op],
    values: &'a [u64],
}

impl<'a> Cursor<'a> {
    fn new(tape: &'a Tape, at: Mark) -> Self {
        Cursor {
            ops: &tape.ops[at.op as usize..],
            values: &tape.values[at.value as usize..],
        }
    }

    fn peek(&self) -> Step {
        self.ops[0].step
    }

    fn op(&mut self) -> Op {
        let (first, rest) = self
            .ops
            .split_first()
            .expect("tape: a statement ends in `End`");
        self.ops = rest;
        *first
    }

    fn value(&mut self) -> u64 {
        let (first, rest) = self.values.split_first().expect("tape: a value is missing");
        self.values = rest;
        *first
    }

    /// The leaf a leaf step makes (taking its values); `None` for other steps.
    fn leaf<'t>(&mut self, op: &Op, text: &'t str, memo: &mut Memo<'t>) -> Option<ExprKind> {
        Some(match op.step {
            Step::Int => ExprKind::Int(self.value() as i64),
            Step::Float => ExprKind::Float(f64::from_bits(self.value())),
            Step::Angle => ExprKind::Angle(f64::from_bits(self.value())),
            Step::Bool => ExprKind::Bool(op.len == 4),
            Step::Vec3 => {
                ExprKind::Vec3([self.value(), self.value(), self.value()].map(f64::from_bits))
            }
            Step::Ident => ExprKind::Ident(memo.sym_at(text, op)),
            _ => return None,
        })
    }
}

/// What building keeps between the statements of one file.
pub(crate) struct Memo<'t> {
    /// The interned names of the tape being built from, by number, and which tape that is.
    numbered: Vec<Sym>,
    tape: Option<u32>,
    /// Recent names that have no number: a small direct-mapped table finds the repeats
    /// without hashing into the interner.
    names: [Option<(&'t str, Sym)>; NAME_SLOTS],
    /// Operands being built (each with the name of the argument it is, if any); a call takes
    /// its arguments off the top, so each argument list is allocated once at its exact size.
    stack: Vec<Arg>,
}

impl Default for Memo<'_> {
    fn default() -> Self {
        Memo {
            numbered: Vec::new(),
            tape: None,
            names: [None; NAME_SLOTS],
            stack: Vec::new(),
        }
    }
}

impl<'t> Memo<'t> {
    /// Makes `tape` (number `id` of its file) the one numbered names are looked up in,
    /// interning its names when it was not.
    fn enter(&mut self, id: u32, tape: &Tape, text: &'t str) {
        if self.tape == Some(id) {
            return;
        }
        self.tape = Some(id);
        self.numbered.clear();
        for &(s, l) in &tape.names.first {
            let sym = self.sym(&text[s as usize..s as usize + l as usize]);
            self.numbered.push(sym);
        }
    }

    /// The interned name a step points at in `text`.
    fn sym_at(&mut self, text: &'t str, op: &Op) -> Sym {
        match self.numbered.get(op.name as usize) {
            Some(&sym) => sym,
            None => self.sym(&text[op.start as usize..op.end() as usize]),
        }
    }

    /// The interned name `text` (not empty).
    fn sym(&mut self, text: &'t str) -> Sym {
        let slot = slot_of(text.as_bytes());
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

/// Builds the statement the reader wrote at `at` (up to its `End`), reading only its names
/// from `text`: exactly the AST pest and the tree builder build for its line, spans included.
/// `id` is the tape's number in its file (names are looked up by it).
pub(crate) fn build<'t>(
    file: FileId,
    text: &'t str,
    (id, tape): (u32, &Tape),
    at: Mark,
    memo: &mut Memo<'t>,
) -> Stmt {
    memo.enter(id, tape, text);
    Replay::new(file, text, tape, at, memo).build()
}

/// Makes `stmt` the statement written at `at` ([`build`]). When both have the same shape (the
/// same calls, members and argument names in the same places; leaves may differ) it is
/// rewritten in place: the nodes of a generated file's previous line are reused, without
/// allocating or freeing any. Otherwise it is built afresh.
pub(crate) fn build_into<'t>(
    stmt: &mut Stmt,
    file: FileId,
    text: &'t str,
    (id, tape): (u32, &Tape),
    at: Mark,
    memo: &mut Memo<'t>,
) {
    memo.enter(id, tape, text);
    // A failed match leaves `stmt` partly rewritten: it is replaced whole.
    if !Replay::new(file, text, tape, at, memo).rebuild(stmt) {
        *stmt = build(file, text, (id, tape), at, memo);
    }
}

/// The operand on top of this statement's part of the stack.
fn pop(memo: &mut Memo<'_>, base: usize) -> Expr {
    debug_assert!(memo.stack.len() > base, "tape: an operand is missing");
    memo.stack.pop().expect("tape: an operand is missing").value
}

/// An unnamed operand.
fn wrap(kind: ExprKind, span: Span) -> Arg {
    Arg {
        name: None,
        value: Expr { kind, span },
    }
}

/// One statement's steps replayed: built into new nodes, or matched node by node against a
/// statement in the order they were written (operands before what applies to them).
struct Replay<'t, 'a, 'm> {
    file: FileId,
    text: &'t str,
    c: Cursor<'a>,
    memo: &'m mut Memo<'t>,
}

impl<'t, 'a, 'm> Replay<'t, 'a, 'm> {
    fn new(file: FileId, text: &'t str, tape: &'a Tape, at: Mark, memo: &'m mut Memo<'t>) -> Self {
        Replay {
            file,
            text,
            c: Cursor::new(tape, at),
            memo,
        }
    }

    /// The statement, in new nodes.
    fn build(mut self) -> Stmt {
        let mut head = None;
        if self.c.peek() == Step::Let {
            let start = self.c.op().start;
            let end = self.c.value() as u32;
            let n = self.c.op();
            head = Some((self.span(start, end), self.name(&n)));
        }
        let base = self.memo.stack.len();
        loop {
            let op = self.c.op();
            if let Some(kind) = self.c.leaf(&op, self.text, self.memo) {
                let s = self.span(op.start, op.end());
                self.memo.stack.push(wrap(kind, s));
                continue;
            }
            let node = match op.step {
                Step::Neg => {
                    let n = pop(self.memo, base);
                    let s = self.span(op.start, n.span.end);
                    wrap(ExprKind::Unary(UnOp::Neg, Box::new(n)), s)
                }
                Step::Named => {
                    let n = self.name(&op);
                    if let Some(top) = self.memo.stack.last_mut() {
                        top.name = Some(n);
                    }
                    continue;
                }
                Step::Call => {
                    let first = self.memo.stack.len() - op.len as usize;
                    let args: Vec<Arg> = self.memo.stack.drain(first..).collect();
                    let callee = pop(self.memo, base);
                    let s = self.span(callee.span.start, op.start);
                    wrap(ExprKind::Call(Box::new(callee), args), s)
                }
                Step::Member => {
                    let n = self.name(&op);
                    let object = pop(self.memo, base);
                    let s = self.span(object.span.start, op.end());
                    wrap(ExprKind::Member(Box::new(object), n), s)
                }
                Step::End => break,
                _ => unreachable!("tape: {op:?} out of place"),
            };
            self.memo.stack.push(node);
        }
        let value = pop(self.memo, base);
        match head {
            Some((span, name)) => Stmt::Let(Let {
                public: false,
                param: false,
                name,
                ty: None,
                value,
                span,
            }),
            None => Stmt::Expr(value),
        }
    }

    /// Rewrites `stmt` step by step; `false` at the first step its shape does not match.
    fn rebuild(&mut self, stmt: &mut Stmt) -> bool {
        let value = match (stmt, self.c.peek()) {
            (Stmt::Let(l), Step::Let) => {
                let start = self.c.op().start;
                let end = self.c.value() as u32;
                l.span = self.span(start, end);
                match self.take(Step::Name) {
                    Some(op) => l.name = self.name(&op),
                    None => return false,
                }
                &mut l.value
            }
            (Stmt::Expr(e), step) if step != Step::Let => e,
            _ => return false,
        };
        self.expr(value) && self.c.peek() == Step::End
    }

    fn span(&self, start: u32, end: u32) -> Span {
        Span::new(self.file, start as usize, end as usize)
    }

    fn name(&mut self, op: &Op) -> Name {
        Name {
            sym: self.memo.sym_at(self.text, op),
            span: self.span(op.start, op.end()),
        }
    }

    /// The next step when it is `step`.
    fn take(&mut self, step: Step) -> Option<Op> {
        (self.c.peek() == step).then(|| self.c.op())
    }

    fn expr(&mut self, e: &mut Expr) -> bool {
        match &mut e.kind {
            ExprKind::Call(callee, args) => {
                if !self.expr(callee) {
                    return false;
                }
                for a in args.iter_mut() {
                    if !self.expr(&mut a.value) {
                        return false;
                    }
                    match (&mut a.name, self.take(Step::Named)) {
                        (Some(n), Some(op)) => *n = self.name(&op),
                        (None, None) => {}
                        _ => return false,
                    }
                }
                match self.take(Step::Call) {
                    Some(op) if op.len as usize == args.len() => {
                        e.span = self.span(callee.span.start, op.start);
                        true
                    }
                    _ => false,
                }
            }
            ExprKind::Member(object, n) => {
                if !self.expr(object) {
                    return false;
                }
                let Some(op) = self.take(Step::Member) else {
                    return false;
                };
                *n = self.name(&op);
                e.span = self.span(object.span.start, op.end());
                true
            }
            ExprKind::Unary(UnOp::Neg, n) => {
                if !self.expr(n) {
                    return false;
                }
                let Some(op) = self.take(Step::Neg) else {
                    return false;
                };
                e.span = self.span(op.start, n.span.end);
                true
            }
            ExprKind::Int(_)
            | ExprKind::Float(_)
            | ExprKind::Angle(_)
            | ExprKind::Bool(_)
            | ExprKind::Vec3(_)
            | ExprKind::Ident(_) => {
                // A leaf holds nothing on the heap: it is overwritten by the leaf step here.
                let op = self.c.ops[0];
                let Some(kind) = self.c.leaf(&op, self.text, self.memo) else {
                    return false;
                };
                self.c.op();
                // The kind replaced is a leaf (matched above), which owns nothing: forgetting
                // it skips the drop glue's dispatch on every leaf of every line.
                std::mem::forget(std::mem::replace(&mut e.kind, kind));
                e.span = self.span(op.start, op.end());
                true
            }
            _ => false,
        }
    }
}
