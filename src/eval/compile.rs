//! `pattern(f)`'s compiler: a user `fn(p)` turned once into a [`Program`], the flat register
//! machine of `pattern::program` that the renderer runs per sample (never this interpreter).
//!
//! What compiles: number, angle, boolean and vector arithmetic with the language's operators
//! and types; comparisons, `&&`, `||`, `!`; `let`; `if`/`else`; `.x`, `.y`, `.z` (and
//! three-letter swizzles); `[a, b, c]` of numbers; the maths and noise built-ins
//! (`compile_builtins`); calls of other user functions, inlined (recursion is an error); and
//! values from outside the function (captured locals, module items), folded in as constants.
//! Anything else is `rtc::fn::not_compilable` at the expression, with what to do instead.
//!
//! Registers are allocated as a stack: an expression's value lands at the first free register
//! when it began (`mark`), or is an existing register (a name, a component); a block's `let`s
//! live above its mark until its end. Every operation of the machine reads its inputs before it
//! writes, so a result may overwrite its own operands.

use std::rc::Rc;

use glam::DVec3;

use crate::pattern::program::{MAX_OPS, Op, Program, REGISTERS, Reg};
use crate::source::Span;
use crate::syntax::ast::{Block, Expr, ExprKind, FnDef, Stmt, TypeAnn};
use crate::syntax::intern::Sym;

use super::error::{EvalError, Quote, R, error};
use super::modules::Scope;
use super::value::{Closure, Value, a_type};

/// The code of every construct that cannot be compiled.
pub(crate) const CODE: &str = "rtc::fn::not_compilable";
/// How deep calls may be inlined.
pub(super) const MAX_INLINE_DEPTH: usize = 32;

/// The static type of a value in registers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Ty {
    /// An `Int` (held as an `f64`).
    Int,
    /// A `Float`.
    Float,
    /// An `Angle`, in radians.
    Angle,
    /// A `Bool`: 0 or 1.
    Bool,
    /// A `Vec3`: three registers.
    Vec3,
}

impl Ty {
    /// Registers it takes.
    pub(super) fn width(self) -> u16 {
        if self == Ty::Vec3 { 3 } else { 1 }
    }

    /// Its name in the language.
    pub(super) fn name(self) -> &'static str {
        match self {
            Ty::Int => "Int",
            Ty::Float => "Float",
            Ty::Angle => "Angle",
            Ty::Bool => "Bool",
            Ty::Vec3 => "Vec3",
        }
    }

    /// An `Int` or a `Float`.
    pub(super) fn num(self) -> bool {
        matches!(self, Ty::Int | Ty::Float)
    }
}

/// A value while compiling: in registers, a constant, or a function to inline.
#[derive(Clone, Debug)]
pub(super) enum Val {
    /// Computed per point, in registers from the given one.
    Reg(Ty, Reg),
    /// Known when the pattern is made.
    Const(Value),
    /// A user function, inlined where it is called.
    Fn(Rc<Callable>),
}

/// A user function with what it sees: its captured values and its module.
#[derive(Debug)]
pub(super) struct Callable {
    pub(super) def: Rc<FnDef>,
    pub(super) captured: Vec<(Sym, Val)>,
    pub(super) module: Rc<Scope>,
}

impl Callable {
    pub(super) fn of(c: &Closure) -> Callable {
        Callable {
            def: c.def.clone(),
            captured: c
                .captured
                .iter()
                .map(|(s, v)| (*s, Val::Const(v.clone())))
                .collect(),
            module: c.module.clone(),
        }
    }
}

/// The program of the argument `f` of `pattern(f)` (at `span`): a user function's, or the
/// error for any other value.
pub(crate) fn compile_value(q: &(impl Quote + ?Sized), f: Value, span: Span) -> R<Program> {
    match f {
        Value::Fn(c) => compile(&c),
        Value::Builtin(b) => Err(nope(
            span,
            format!("the built-in `{}` is not a function of the point", b.name),
            "a built-in",
            format!(
                "wrap it in a function: `pattern(fn(p) {{ {}(p) }})`",
                b.name
            ),
        )),
        other => Err(super::types::mismatch(q, "Fn", &other, span).into()),
    }
}

/// The program of `c`, a `fn(p)` of the pattern-space point giving a number.
pub(crate) fn compile(c: &Closure) -> R<Program> {
    let def = &c.def;
    let mut k = Compiler {
        ops: Vec::new(),
        top: 3,
        locals: Vec::new(),
        frame_base: 0,
        module: c.module.clone(),
        inlining: vec![def.clone()],
    };
    let Some(first) = def.params.first() else {
        return Err(nope(
            def.name.span,
            "a pattern's function takes the point",
            "this function has no parameter",
            "write `fn(p) ...`: `p` is the point in the pattern's space",
        ));
    };
    k.locals
        .extend(c.captured.iter().map(|(s, v)| (*s, Val::Const(v.clone()))));
    if def.name.sym.as_str() != "<fn>" {
        let me = Rc::new(Callable::of(c));
        k.locals.push((def.name.sym, Val::Fn(me)));
    }
    let point = k.annotate(first.ty.as_ref(), Val::Reg(Ty::Vec3, 0), first.name.span)?;
    k.locals.push((first.name.sym, point));
    for p in &def.params[1..] {
        let Some(d) = &p.default else {
            return Err(nope(
                p.name.span,
                "a pattern's function takes one argument, the point",
                format!("`{}` has no default", p.name.sym),
                format!(
                    "give `{}` a default (`{}: ... = 1`) or capture the value from outside",
                    p.name.sym, p.name.sym
                ),
            ));
        };
        let v = k.expr(d)?;
        let v = k.annotate(p.ty.as_ref(), v, d.span)?;
        k.locals.push((p.name.sym, v));
    }
    let v = k.block(&def.body)?;
    let v = k.annotate(def.ret.as_ref(), v, def.body.span)?;
    let at = result_span(&def.body);
    let (ty, reg) = k.reg(v, at)?;
    if !ty.num() {
        return Err(nope(
            at,
            format!(
                "a pattern's function must give a number, not {}",
                a_type(ty.name())
            ),
            format!("this is {}", a_type(ty.name())),
            "give a `Float`: e.g. `length(v)` of a vector, `v.x` of one component",
        ));
    }
    Program::new(k.ops, reg).map_err(|_| too_large(def.body.span))
}

/// The span of a block's result: its last expression, or the block.
fn result_span(b: &Block) -> Span {
    match b.stmts.last() {
        Some(Stmt::Expr(e)) => e.span,
        _ => b.span,
    }
}

/// `rtc::fn::not_compilable` at `span`.
pub(super) fn nope(
    span: Span,
    message: impl Into<String>,
    label: impl Into<String>,
    help: impl Into<String>,
) -> EvalError {
    error(CODE, span, message)
        .with_label(label)
        .with_help(help)
        .into()
}

/// The function is beyond the machine's registers or operations.
fn too_large(span: Span) -> EvalError {
    nope(
        span,
        format!(
            "this function is too large to compile (at most {MAX_OPS} operations and {REGISTERS} registers)"
        ),
        "too large",
        "split the work: fewer inlined calls, or a built-in pattern with `.colors(..)`",
    )
}

/// `rtc::type::mismatch`: `expected` wanted at `span`, `found` given.
pub(super) fn mismatch(span: Span, expected: &str, found: &str) -> EvalError {
    let help = match (expected, found) {
        ("Angle", "Int" | "Float") => {
            "give the number a unit: `x * 1rad` or `x * 1deg`".to_string()
        }
        _ => format!("give {} here", a_type(expected)),
    };
    error(
        "rtc::type::mismatch",
        span,
        format!("expected `{expected}`, found `{found}`"),
    )
    .with_label(format!("this is {}", a_type(found)))
    .with_help(help)
    .into()
}

/// The compiler's state: the operations so far, the first free register, the names in scope.
pub(super) struct Compiler {
    pub(super) ops: Vec<Op>,
    pub(super) top: usize,
    pub(super) locals: Vec<(Sym, Val)>,
    pub(super) frame_base: usize,
    pub(super) module: Rc<Scope>,
    pub(super) inlining: Vec<Rc<FnDef>>,
}

impl Compiler {
    /// Appends an operation.
    pub(super) fn emit(&mut self, op: Op, span: Span) -> R<()> {
        if self.ops.len() >= MAX_OPS {
            return Err(too_large(span));
        }
        self.ops.push(op);
        Ok(())
    }

    /// `w` fresh registers.
    pub(super) fn alloc(&mut self, w: u16, span: Span) -> R<Reg> {
        let r = self.top;
        if r + usize::from(w) > REGISTERS {
            return Err(too_large(span));
        }
        self.top += usize::from(w);
        Ok(r as Reg)
    }

    /// The value in registers (a constant is loaded), with its type.
    pub(super) fn reg(&mut self, v: Val, span: Span) -> R<(Ty, Reg)> {
        let (ty, xs) = match v {
            Val::Reg(t, r) => return Ok((t, r)),
            Val::Fn(_) => {
                return Err(nope(
                    span,
                    "a function is not a value a pattern can compute with",
                    "a function",
                    "call it: `f(p)`",
                ));
            }
            Val::Const(c) => match c {
                Value::Int(i) => (Ty::Int, [i as f64; 3]),
                Value::Float(f) => (Ty::Float, [f; 3]),
                Value::Angle(a) => (Ty::Angle, [a; 3]),
                Value::Bool(b) => (Ty::Bool, [if b { 1.0 } else { 0.0 }; 3]),
                Value::Vec3(v) => (Ty::Vec3, v.to_array()),
                other => {
                    let t = other.type_name();
                    return Err(nope(
                        span,
                        format!("{} cannot be used in a compiled function", a_type(t)),
                        format!("this is {}", a_type(t)),
                        "a pattern's function computes with numbers, angles, booleans and vectors",
                    ));
                }
            },
        };
        let r = self.alloc(ty.width(), span)?;
        for (i, value) in xs.iter().take(usize::from(ty.width())).enumerate() {
            let dst = r + i as Reg;
            self.emit(Op::Const { dst, value: *value }, span)?;
        }
        Ok((ty, r))
    }

    /// Frees the registers above `mark` but `v`'s, which moves to `mark` if it was above it.
    pub(super) fn settle(&mut self, mark: usize, v: Val, span: Span) -> R<Val> {
        match v {
            Val::Reg(t, r) if usize::from(r) >= mark => {
                if usize::from(r) != mark {
                    let (dst, width) = (mark as Reg, t.width() as u8);
                    self.emit(Op::Copy { dst, src: r, width }, span)?;
                }
                self.top = mark + usize::from(t.width());
                Ok(Val::Reg(t, mark as Reg))
            }
            // A function may capture registers above the mark: they stay allocated.
            Val::Fn(f) => Ok(Val::Fn(f)),
            other => {
                self.top = mark;
                Ok(other)
            }
        }
    }

    /// `v` checked against the annotation `t` (an `Int` widens to a `Float` where one is
    /// declared), as the interpreter checks it.
    pub(super) fn annotate(&mut self, t: Option<&TypeAnn>, v: Val, span: Span) -> R<Val> {
        let Some(t) = t else { return Ok(v) };
        let want = t.name.sym.as_str();
        let found = match &v {
            Val::Reg(ty, _) => ty.name(),
            Val::Const(c) => c.type_name(),
            Val::Fn(_) => "Fn",
        };
        let ok = want == "Any"
            || want == found
            || (want == "Float" && found == "Int")
            || (want == "List" && found == "Vec3");
        if !ok {
            return Err(mismatch(span, want, found));
        }
        Ok(match v {
            Val::Reg(Ty::Int, r) if want == "Float" => Val::Reg(Ty::Float, r),
            Val::Const(Value::Int(i)) if want == "Float" => Val::Const(Value::Float(i as f64)),
            other => other,
        })
    }

    /// A name: the frame's locals, the module's items, then the built-ins.
    fn lookup(&self, sym: Sym, span: Span) -> R<Val> {
        if let Some((_, v)) = self.locals[self.frame_base..]
            .iter()
            .rev()
            .find(|(k, _)| *k == sym)
        {
            return Ok(v.clone());
        }
        if let Some(b) = self.module.items.borrow().get(&sym) {
            return if b.poisoned {
                Err(EvalError::Poisoned)
            } else {
                Ok(Val::Const(b.value.clone()))
            };
        }
        if let Some(v) = super::builtins::global(sym) {
            return Ok(Val::Const(v));
        }
        Err(nope(
            span,
            format!("`{sym}` is not known inside a compiled function"),
            "not defined here",
            format!(
                "define it before the function (`let {sym} = ...`) so the function captures it"
            ),
        ))
    }

    /// Compiles an expression.
    pub(super) fn expr(&mut self, e: &Expr) -> R<Val> {
        let span = e.span;
        Ok(match &e.kind {
            ExprKind::Int(i) => Val::Const(Value::Int(*i)),
            ExprKind::Float(f) => Val::Const(Value::Float(*f)),
            ExprKind::Angle(a) => Val::Const(Value::Angle(*a)),
            ExprKind::Bool(b) => Val::Const(Value::Bool(*b)),
            ExprKind::Vec3(x) => Val::Const(Value::Vec3(DVec3::from_array(*x))),
            ExprKind::Color(c) => Val::Const(Value::Color(DVec3::from_array(*c))),
            ExprKind::StrLit(s) => Val::Const(Value::Str(s.clone())),
            ExprKind::Ident(s) => self.lookup(*s, span)?,
            ExprKind::List(items, false) if items.len() == 3 => self.vector(items, span)?,
            ExprKind::Unary(op, a) => self.unary(*op, a, span)?,
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, span)?,
            ExprKind::Call(callee, args) => self.call(callee, args, span)?,
            ExprKind::Member(obj, name) => self.member(obj, *name, span)?,
            ExprKind::If(c, then, els) => self.if_else(c, then, els.as_deref(), span)?,
            ExprKind::Block(b) => self.block(b)?,
            ExprKind::Lambda(def) => Val::Fn(Rc::new(Callable {
                def: def.clone(),
                captured: self.locals[self.frame_base..].to_vec(),
                module: self.module.clone(),
            })),
            ExprKind::For(..) => {
                return Err(nope(
                    span,
                    "a `for` loop cannot be compiled",
                    "a loop",
                    "write the steps out, or sum octaves with `fbm(p, octaves: n)`",
                ));
            }
            ExprKind::Str(_) => {
                return Err(nope(
                    span,
                    "strings cannot be computed in a compiled function",
                    "a string",
                    "compute a number",
                ));
            }
            _ => {
                return Err(nope(
                    span,
                    "lists, records, ranges and indexing cannot be compiled",
                    "not compilable",
                    "a pattern's function computes with numbers, angles, booleans and vectors: `[x, y, z]` of numbers is a vector, `v.x` a component",
                ));
            }
        })
    }

    /// `if c { a } else { b }`: a constant condition compiles one branch, a computed one both,
    /// with a jump round the branch not taken.
    fn if_else(&mut self, c: &Expr, then: &Block, els: Option<&Expr>, span: Span) -> R<Val> {
        let mark = self.top;
        let cond = self.expr(c)?;
        let Some(els) = els else {
            return Err(nope(
                span,
                "an `if` without `else` has no value when its condition is false",
                "no `else`",
                "add an `else` branch giving a number",
            ));
        };
        if let Val::Const(Value::Bool(b)) = cond {
            self.top = mark;
            return if b { self.block(then) } else { self.expr(els) };
        }
        let (ct, cr) = self.reg(cond, c.span)?;
        if ct != Ty::Bool {
            return Err(mismatch(c.span, "Bool", ct.name()));
        }
        let jump = self.ops.len();
        self.emit(Op::JumpUnless { cond: cr, to: 0 }, span)?;
        self.top = mark;
        let tv = self.block(then)?;
        let (tt, tr) = self.reg(tv, result_span(then))?;
        if usize::from(tr) != mark {
            let (dst, width) = (mark as Reg, tt.width() as u8);
            self.emit(
                Op::Copy {
                    dst,
                    src: tr,
                    width,
                },
                span,
            )?;
        }
        let skip = self.ops.len();
        self.emit(Op::Jump { to: 0 }, span)?;
        self.ops[jump] = Op::JumpUnless {
            cond: cr,
            to: self.ops.len() as u32,
        };
        self.top = mark;
        let ev = self.expr(els)?;
        let (et, er) = self.reg(ev, els.span)?;
        let ty = if tt == et {
            tt
        } else if tt.num() && et.num() {
            Ty::Float
        } else {
            return Err(nope(
                els.span,
                format!(
                    "the branches of this `if` give {} and {}",
                    a_type(tt.name()),
                    a_type(et.name())
                ),
                format!("this is {}", a_type(et.name())),
                "give both branches the same type",
            ));
        };
        if usize::from(er) != mark {
            let (dst, width) = (mark as Reg, et.width() as u8);
            self.emit(
                Op::Copy {
                    dst,
                    src: er,
                    width,
                },
                span,
            )?;
        }
        self.ops[skip] = Op::Jump {
            to: self.ops.len() as u32,
        };
        self.top = mark + usize::from(ty.width());
        Ok(Val::Reg(ty, mark as Reg))
    }

    /// A `{ ... }` block: `let`s and local `fn`s, then the value.
    pub(super) fn block(&mut self, b: &Block) -> R<Val> {
        let mark = self.top;
        let names = self.locals.len();
        let mut last = None;
        for (i, s) in b.stmts.iter().enumerate() {
            match s {
                Stmt::Let(l) => {
                    let v = self.expr(&l.value)?;
                    let v = self.annotate(l.ty.as_deref(), v, l.value.span)?;
                    self.locals.push((l.name.sym, v));
                }
                Stmt::Fn(def) => {
                    let c = Callable {
                        def: def.clone(),
                        captured: self.locals[self.frame_base..].to_vec(),
                        module: self.module.clone(),
                    };
                    self.locals.push((def.name.sym, Val::Fn(Rc::new(c))));
                }
                Stmt::Expr(e) if i + 1 == b.stmts.len() => last = Some((self.expr(e)?, e.span)),
                Stmt::Expr(e) => {
                    return Err(nope(
                        e.span,
                        "only `let` and `fn` may come before a compiled function's result",
                        "not the result",
                        "remove it: a compiled function has no effects (no `print` or `assert`)",
                    ));
                }
                Stmt::Import(im) => {
                    return Err(nope(
                        im.span,
                        "`import` cannot be compiled",
                        "an import",
                        "import at the top of the file",
                    ));
                }
            }
        }
        self.locals.truncate(names);
        let Some((v, at)) = last else {
            return Err(nope(
                b.span,
                "this block gives no value",
                "no result",
                "end the block with the number it gives",
            ));
        };
        self.settle(mark, v, at)
    }
}
