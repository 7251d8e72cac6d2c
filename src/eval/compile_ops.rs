//! The operators of a compiled function (`eval::compile`): vectors of numbers, unary and binary
//! operators with the interpreter's type rules, and the errors for the combinations it refuses.

use glam::DVec3;

use crate::pattern::program::{Bin, Op, Reg, Un, VecOp};
use crate::source::Span;
use crate::syntax::ast::{BinOp, Expr, UnOp};

use super::compile::{Compiler, Ty, Val, nope};
use super::error::{EvalError, R, error};
use super::value::{Value, a_type};

impl Compiler {
    /// `[a, b, c]` of numbers: a vector.
    pub(super) fn vector(&mut self, items: &[Expr], span: Span) -> R<Val> {
        let mark = self.top;
        let mut parts = Vec::with_capacity(3);
        for it in items {
            let v = self.expr(it)?;
            parts.push((v, it.span));
        }
        let consts: Vec<f64> = parts
            .iter()
            .filter_map(|(v, _)| match v {
                Val::Const(c @ (Value::Int(_) | Value::Float(_))) => c.as_f64(),
                _ => None,
            })
            .collect();
        if let [x, y, z] = consts[..] {
            self.top = mark;
            return Ok(Val::Const(Value::Vec3(DVec3::new(x, y, z))));
        }
        let mut regs = [0; 3];
        for (i, (v, s)) in parts.into_iter().enumerate() {
            let (t, r) = self.reg(v, s)?;
            if !t.num() {
                return Err(nope(
                    s,
                    format!(
                        "`[a, b, c]` with {} is a list, which cannot be compiled",
                        a_type(t.name())
                    ),
                    format!("this is {}", a_type(t.name())),
                    "a vector's three elements are numbers",
                ));
            }
            regs[i] = r;
        }
        let dst = self.alloc(3, span)?;
        for (i, src) in regs.into_iter().enumerate() {
            let d = dst + i as Reg;
            self.emit(
                Op::Copy {
                    dst: d,
                    src,
                    width: 1,
                },
                span,
            )?;
        }
        self.settle(mark, Val::Reg(Ty::Vec3, dst), span)
    }

    /// `-a`, `!a`.
    pub(super) fn unary(&mut self, op: UnOp, a: &Expr, span: Span) -> R<Val> {
        let mark = self.top;
        let v = self.expr(a)?;
        let (t, r) = self.reg(v, a.span)?;
        self.top = mark;
        let dst = self.alloc(t.width(), span)?;
        let op = match (op, t) {
            (UnOp::Neg, Ty::Int | Ty::Float | Ty::Angle) => Op::Un {
                f: Un::Neg,
                dst,
                a: r,
            },
            (UnOp::Neg, Ty::Vec3) => Op::Vec {
                f: VecOp::Neg,
                dst,
                a: r,
                b: r,
            },
            (UnOp::Not, Ty::Bool) => Op::Un {
                f: Un::Not,
                dst,
                a: r,
            },
            (op, t) => {
                let sym = if op == UnOp::Neg { "-" } else { "!" };
                return Err(error(
                    "rtc::type::operator",
                    span,
                    format!("cannot apply `{sym}` to {}", a_type(t.name())),
                )
                .with_label(format!("this is {}", a_type(t.name())))
                .with_help(if op == UnOp::Neg {
                    "negate a number, angle or vector"
                } else {
                    "`!` needs a `Bool`"
                })
                .into());
            }
        };
        self.emit(op, span)?;
        Ok(Val::Reg(t, dst))
    }

    /// `a op b`, typed as the interpreter's operators are (`eval::ops`).
    pub(super) fn binary(&mut self, op: BinOp, a: &Expr, b: &Expr, span: Span) -> R<Val> {
        use Ty::*;
        let mark = self.top;
        let l = self.expr(a)?;
        let r = self.expr(b)?;
        let (lt, lr) = self.reg(l, a.span)?;
        let (rt, rr) = self.reg(r, b.span)?;
        let scalar = |f: Bin| Some(Kind::S(f));
        let vector = |f: VecOp| Some(Kind::V(f));
        let (kind, ty) = match (op, lt, rt) {
            (BinOp::And, Bool, Bool) => (scalar(Bin::And), Bool),
            (BinOp::Or, Bool, Bool) => (scalar(Bin::Or), Bool),
            (BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Rem | BinOp::Pow, Int, Int) => {
                (scalar(arith(op)), Int)
            }
            (BinOp::IntDiv, Int, Int) => (scalar(Bin::IntDiv), Int),
            (BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Div | BinOp::Rem | BinOp::Pow, _, _)
                if lt.num() && rt.num() =>
            {
                (scalar(arith(op)), Float)
            }
            (BinOp::Add | BinOp::Sub, Angle, Angle) => (scalar(arith(op)), Angle),
            (BinOp::Mul, Angle, _) if rt.num() => (scalar(Bin::Mul), Angle),
            (BinOp::Mul, _, Angle) if lt.num() => (scalar(Bin::Mul), Angle),
            (BinOp::Div, Angle, _) if rt.num() => (scalar(Bin::Div), Angle),
            (BinOp::Div, Angle, Angle) => (scalar(Bin::Div), Float),
            (BinOp::Add, Vec3, Vec3) => (vector(VecOp::Add), Vec3),
            (BinOp::Sub, Vec3, Vec3) => (vector(VecOp::Sub), Vec3),
            (BinOp::Mul, Vec3, Vec3) => (vector(VecOp::Mul), Vec3),
            (BinOp::Mul | BinOp::Div, Vec3, _) if rt.num() => {
                let f = if op == BinOp::Mul {
                    VecOp::Scale
                } else {
                    VecOp::Div
                };
                (vector(f), Vec3)
            }
            (BinOp::Mul, _, Vec3) if lt.num() => {
                // `s * v`: the same products as `v * s`.
                self.top = mark;
                let dst = self.alloc(3, span)?;
                let f = VecOp::Scale;
                self.emit(
                    Op::Vec {
                        f,
                        dst,
                        a: rr,
                        b: lr,
                    },
                    span,
                )?;
                return Ok(Val::Reg(Vec3, dst));
            }
            (BinOp::Eq | BinOp::Ne, Vec3, Vec3) => {
                let f = if op == BinOp::Eq {
                    VecOp::Eq
                } else {
                    VecOp::Ne
                };
                (vector(f), Bool)
            }
            (BinOp::Eq | BinOp::Ne, _, _) if (lt.num() && rt.num()) || (lt == rt && lt != Vec3) => {
                (scalar(compare(op)), Bool)
            }
            (BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge, _, _)
                if (lt.num() && rt.num()) || (lt == Angle && rt == Angle) =>
            {
                (scalar(compare(op)), Bool)
            }
            _ => (None, Bool),
        };
        let Some(kind) = kind else {
            return Err(operator_error(op, lt, rt, a.span, b.span));
        };
        self.top = mark;
        let dst = self.alloc(ty.width(), span)?;
        let op = match kind {
            Kind::V(f) => Op::Vec {
                f,
                dst,
                a: lr,
                b: rr,
            },
            Kind::S(f) => Op::Bin {
                f,
                dst,
                a: lr,
                b: rr,
            },
        };
        self.emit(op, span)?;
        Ok(Val::Reg(ty, dst))
    }
}

/// The machine's operation for an arithmetic operator.
fn arith(op: BinOp) -> Bin {
    match op {
        BinOp::Add => Bin::Add,
        BinOp::Sub => Bin::Sub,
        BinOp::Mul => Bin::Mul,
        BinOp::Div => Bin::Div,
        BinOp::Rem => Bin::Rem,
        _ => Bin::Pow,
    }
}

/// The machine's operation for a comparison.
fn compare(op: BinOp) -> Bin {
    match op {
        BinOp::Eq => Bin::Eq,
        BinOp::Ne => Bin::Ne,
        BinOp::Lt => Bin::Lt,
        BinOp::Le => Bin::Le,
        BinOp::Gt => Bin::Gt,
        _ => Bin::Ge,
    }
}

/// A binary operator's operation: on numbers or on vectors.
enum Kind {
    S(Bin),
    V(VecOp),
}

/// `rtc::type::operator` for `lt op rt`, or `rtc::fn::not_compilable` for the operators of
/// objects and transforms.
fn operator_error(op: BinOp, lt: Ty, rt: Ty, ls: Span, rs: Span) -> EvalError {
    if matches!(op, BinOp::Then | BinOp::Union | BinOp::Inter) {
        return nope(
            rs,
            format!("`{}` cannot be compiled", op.as_str()),
            "not compilable",
            "a pattern's function computes with numbers, angles, booleans and vectors",
        );
    }
    let (l, r) = (lt.name(), rt.name());
    error(
        "rtc::type::operator",
        rs,
        format!("cannot apply `{}` to `{l}` and `{r}`", op.as_str()),
    )
    .with_label(format!("this is {}", a_type(r)))
    .with_secondary(ls, format!("this is {}", a_type(l)))
    .with_help(format!(
        "convert one side so both are the same type, e.g. `{l}`"
    ))
    .into()
}
