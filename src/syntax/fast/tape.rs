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
pub struct Op {
    pub(super) start: u32,
    pub(super) len: u16,
    pub(super) step: Step,
}

impl Op {
    /// A step over `start..end`, or `None` when the token is too long for a step (pest then
    /// reads the line).
    pub(super) fn new(step: Step, start: usize, end: usize) -> Option<Op> {
        Some(Op {
            start: u32::try_from(start).ok()?,
            len: u16::try_from(end - start).ok()?,
            step,
        })
    }

    fn end(&self) -> u32 {
        self.start + self.len as u32
    }
}

/// What the fast path read from some lines: their steps, and the values of their numbers.
#[derive(Clone, Default, Debug)]
pub struct Tape {
    pub(super) ops: Vec<Op>,
    pub(super) values: Vec<u64>,
}

/// Where a statement starts on its tape.
#[derive(Clone, Copy, Debug)]
pub struct Mark {
    /// Its first step.
    pub op: u32,
    /// Its first value.
    pub value: u32,
}

impl Tape {
    /// Where the next statement written starts.
    pub fn mark(&self) -> Mark {
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
pub struct Memo<'t> {
    /// Recent names: a generated file repeats a handful of names, and this small
    /// direct-mapped table finds them without hashing into the interner.
    names: [Option<(&'t str, Sym)>; 64],
    /// Operands being built (each with the name of the argument it is, if any); a call takes
    /// its arguments off the top, so each argument list is allocated once at its exact size.
    stack: Vec<Arg>,
}

impl Default for Memo<'_> {
    fn default() -> Self {
        Memo {
            names: [None; 64],
            stack: Vec::new(),
        }
    }
}

impl<'t> Memo<'t> {
    /// The interned name a step points at in `text`.
    fn sym_at(&mut self, text: &'t str, op: &Op) -> Sym {
        self.sym(&text[op.start as usize..op.end() as usize])
    }

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

/// Builds the statement the reader wrote at `at` (up to its `End`), reading only its names
/// from `text`: exactly the AST pest and the tree builder build for its line, spans included.
pub fn build<'t>(file: FileId, text: &'t str, tape: &Tape, at: Mark, memo: &mut Memo<'t>) -> Stmt {
    Replay::new(file, text, tape, at, memo).build()
}

/// Makes `stmt` the statement written at `at` ([`build`]). When both have the same shape (the
/// same calls, members and argument names in the same places; leaves may differ) it is
/// rewritten in place: the nodes of a generated file's previous line are reused, without
/// allocating or freeing any. Otherwise it is built afresh.
pub fn build_into<'t>(
    stmt: &mut Stmt,
    file: FileId,
    text: &'t str,
    tape: &Tape,
    at: Mark,
    memo: &mut Memo<'t>,
) {
    // A failed match leaves `stmt` partly rewritten: it is replaced whole.
    if !Replay::new(file, text, tape, at, memo).rebuild(stmt) {
        *stmt = build(file, text, tape, at, memo);
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
                e.kind = kind;
                e.span = self.span(op.start, op.end());
                true
            }
            _ => false,
        }
    }
}
