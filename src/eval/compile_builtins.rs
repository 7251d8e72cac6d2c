//! The built-ins a compiled function may call (`eval::compile`): the maths of numbers, angles
//! and vectors, and the noises, each compiled to the machine operation that computes what the
//! built-in computes. The noises' options (`octaves`, `seed`, ...) must be known when the
//! pattern is made.

use crate::pattern::Fractal;
use crate::pattern::program::{Bin, NoiseFn, Op, Reg, Un, VecOp};
use crate::source::Span;
use crate::syntax::ast::{Arg, Expr};

use super::builtins::noise as sigs;
use super::compile::{Compiler, Ty, Val, mismatch, nope};
use super::error::{R, error};
use super::schema::Sig;
use super::value::Value;

/// Every built-in a compiled function may call (for the help of one that cannot).
pub(crate) const COMPILABLE: &[&str] = &[
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "atan2",
    "sqrt",
    "abs",
    "floor",
    "ceil",
    "round",
    "int",
    "float",
    "exp",
    "ln",
    "pow",
    "min",
    "max",
    "dot",
    "cross",
    "length",
    "distance",
    "normalize",
    "noise",
    "snoise",
    "vnoise",
    "fbm",
    "turbulence",
    "worley",
];

impl Compiler {
    /// A call of the built-in `name`.
    pub(super) fn builtin(&mut self, name: &str, args: &[Arg], span: Span, at: Span) -> R<Val> {
        let mark = self.top;
        let v = match name {
            "sin" | "cos" | "tan" => {
                let (t, r, s) = self.arg1(name, "angle", args, span)?;
                if t != Ty::Angle {
                    return Err(mismatch(s, "Angle", t.name()));
                }
                let f = match name {
                    "sin" => Un::Sin,
                    "cos" => Un::Cos,
                    _ => Un::Tan,
                };
                self.un(mark, f, r, Ty::Float, span)?
            }
            "asin" | "acos" | "atan" | "sqrt" | "exp" | "ln" | "floor" | "ceil" | "round"
            | "int" | "float" => {
                let (t, r, s) = self.arg1(name, "x", args, span)?;
                if !t.num() {
                    return Err(mismatch(s, "Float", t.name()));
                }
                let (f, ty) = match name {
                    "asin" => (Un::Asin, Ty::Angle),
                    "acos" => (Un::Acos, Ty::Angle),
                    "atan" => (Un::Atan, Ty::Angle),
                    "sqrt" => (Un::Sqrt, Ty::Float),
                    "exp" => (Un::Exp, Ty::Float),
                    "ln" => (Un::Ln, Ty::Float),
                    "floor" => (Un::Floor, Ty::Int),
                    "ceil" => (Un::Ceil, Ty::Int),
                    "round" => (Un::Round, Ty::Int),
                    "int" => (Un::Trunc, Ty::Int),
                    _ => return Ok(Val::Reg(Ty::Float, r)),
                };
                self.un(mark, f, r, ty, span)?
            }
            "abs" => {
                let (t, r, s) = self.arg1(name, "x", args, span)?;
                if !(t.num() || t == Ty::Angle) {
                    return Err(mismatch(s, "Float", t.name()));
                }
                self.un(mark, Un::Abs, r, t, span)?
            }
            "atan2" | "pow" => {
                let names: &[&str] = if name == "pow" {
                    &["base", "exponent"]
                } else {
                    &["y", "x"]
                };
                let [(at, ar, as_), (bt, br, bs)] = self.args2(name, names, args, span)?;
                for (t, s) in [(at, as_), (bt, bs)] {
                    if !t.num() {
                        return Err(mismatch(s, "Float", t.name()));
                    }
                }
                let (f, ty) = if name == "pow" {
                    (Bin::Pow, Ty::Float)
                } else {
                    (Bin::Atan2, Ty::Angle)
                };
                self.top = mark;
                let dst = self.alloc(1, span)?;
                self.emit(
                    Op::Bin {
                        f,
                        dst,
                        a: ar,
                        b: br,
                    },
                    span,
                )?;
                Val::Reg(ty, dst)
            }
            "dot" | "cross" | "distance" => {
                let [(at, ar, as_), (bt, br, bs)] = self.args2(name, &["a", "b"], args, span)?;
                for (t, s) in [(at, as_), (bt, bs)] {
                    if t != Ty::Vec3 {
                        return Err(mismatch(s, "Vec3", t.name()));
                    }
                }
                let (f, ty) = match name {
                    "dot" => (VecOp::Dot, Ty::Float),
                    "cross" => (VecOp::Cross, Ty::Vec3),
                    _ => (VecOp::Distance, Ty::Float),
                };
                self.top = mark;
                let dst = self.alloc(ty.width(), span)?;
                self.emit(
                    Op::Vec {
                        f,
                        dst,
                        a: ar,
                        b: br,
                    },
                    span,
                )?;
                Val::Reg(ty, dst)
            }
            "length" | "normalize" => {
                let (t, r, s) = self.arg1(name, "v", args, span)?;
                if t != Ty::Vec3 {
                    return Err(mismatch(s, "Vec3", t.name()));
                }
                let (f, ty) = if name == "length" {
                    (VecOp::Length, Ty::Float)
                } else {
                    (VecOp::Normalize, Ty::Vec3)
                };
                self.top = mark;
                let dst = self.alloc(ty.width(), span)?;
                self.emit(Op::Vec { f, dst, a: r, b: r }, span)?;
                Val::Reg(ty, dst)
            }
            "min" | "max" => self.min_max(name == "min", args, span)?,
            "noise" | "snoise" | "vnoise" | "fbm" | "turbulence" | "worley" => {
                self.noise(name, args, span)?
            }
            _ => {
                return Err(nope(
                    at,
                    format!("the built-in `{name}` cannot be compiled"),
                    "not compilable",
                    format!(
                        "a compiled function may call: {}, and user functions",
                        COMPILABLE.join(", ")
                    ),
                ));
            }
        };
        self.settle(mark, v, span)
    }

    /// `dst = f(r)` at the mark.
    fn un(&mut self, mark: usize, f: Un, r: Reg, ty: Ty, span: Span) -> R<Val> {
        self.top = mark;
        let dst = self.alloc(1, span)?;
        self.emit(Op::Un { f, dst, a: r }, span)?;
        Ok(Val::Reg(ty, dst))
    }

    /// The one argument `param` of `name`, in registers.
    fn arg1(&mut self, name: &str, param: &str, args: &[Arg], span: Span) -> R<(Ty, Reg, Span)> {
        let [e] = self.required(name, &[param], args, span)?;
        let v = self.expr(e)?;
        let (t, r) = self.reg(v, e.span)?;
        Ok((t, r, e.span))
    }

    /// The two arguments `names` of `name`, in registers.
    fn args2(
        &mut self,
        name: &str,
        names: &[&str],
        args: &[Arg],
        span: Span,
    ) -> R<[(Ty, Reg, Span); 2]> {
        let [a, b] = self.required(name, names, args, span)?;
        let va = self.expr(a)?;
        let vb = self.expr(b)?;
        let (at, ar) = self.reg(va, a.span)?;
        let (bt, br) = self.reg(vb, b.span)?;
        Ok([(at, ar, a.span), (bt, br, b.span)])
    }

    /// The `N` arguments `names` of `name`, all required.
    fn required<'e, const N: usize>(
        &self,
        name: &str,
        names: &[&str],
        args: &'e [Arg],
        span: Span,
    ) -> R<[&'e Expr; N]> {
        let slots = self.bind(name, names, args, span)?;
        let mut out = Vec::with_capacity(N);
        for (s, p) in slots.into_iter().zip(names) {
            out.push(s.ok_or_else(|| missing(name, p, span))?);
        }
        out.try_into().map_err(|_| missing(name, names[0], span))
    }

    /// `min(a, b, ..)`, `max(..)`: the first of the smallest (largest), of numbers or angles;
    /// one vector is its three components.
    fn min_max(&mut self, min: bool, args: &[Arg], span: Span) -> R<Val> {
        let mut regs = Vec::new();
        let mut tys = Vec::new();
        for a in args {
            if let Some(n) = a.name {
                return Err(error(
                    "rtc::arg::unknown",
                    n.span,
                    "`min` and `max` take their values without names",
                )
                .with_label("named")
                .with_help("remove the name")
                .into());
            }
            let v = self.expr(&a.value)?;
            let (t, r) = self.reg(v, a.value.span)?;
            if t == Ty::Vec3 && args.len() == 1 {
                for i in 0..3 {
                    regs.push(r + i);
                    tys.push(Ty::Float);
                }
                continue;
            }
            if !(t.num() || t == Ty::Angle) {
                return Err(mismatch(a.value.span, "Float", t.name()));
            }
            regs.push(r);
            tys.push(t);
        }
        let Some(&first) = regs.first() else {
            return Err(missing(if min { "min" } else { "max" }, "values", span));
        };
        let ty = if tys.iter().all(|t| *t == Ty::Int) {
            Ty::Int
        } else if tys.iter().all(|t| t.num()) {
            Ty::Float
        } else if tys.iter().all(|t| *t == Ty::Angle) {
            Ty::Angle
        } else {
            return Err(nope(
                span,
                "`min` and `max` of numbers and angles together cannot be compiled",
                "numbers and angles",
                "give all numbers or all angles",
            ));
        };
        // Into a fresh register, so no operand is overwritten before it is read.
        let dst = self.alloc(1, span)?;
        let f = if min { Bin::Min } else { Bin::Max };
        self.emit(
            Op::Copy {
                dst,
                src: first,
                width: 1,
            },
            span,
        )?;
        for &r in &regs[1..] {
            self.emit(
                Op::Bin {
                    f,
                    dst,
                    a: dst,
                    b: r,
                },
                span,
            )?;
        }
        Ok(Val::Reg(ty, dst))
    }

    /// A noise built-in: the point computed, the options constant.
    fn noise(&mut self, name: &str, args: &[Arg], span: Span) -> R<Val> {
        let sig: &Sig = match name {
            "noise" => &sigs::NOISE,
            "snoise" => &sigs::SNOISE,
            "vnoise" => &sigs::VNOISE,
            "fbm" => &sigs::FBM,
            "turbulence" => &sigs::TURBULENCE,
            _ => &sigs::WORLEY,
        };
        let names: Vec<&str> = sig.params.iter().map(|p| p.name).collect();
        let slots = self.bind(name, &names, args, span)?;
        let Some(pe) = slots[0] else {
            return Err(missing(name, "p", span));
        };
        let pv = self.expr(pe)?;
        let (pt, pr) = self.reg(pv, pe.span)?;
        if pt != Ty::Vec3 {
            return Err(mismatch(pe.span, "Vec3", pt.name()));
        }
        let mut consts = Vec::new();
        for (i, s) in slots.iter().enumerate().skip(1) {
            consts.push(match s {
                Some(e) => Some((self.constant(sig, names[i], e)?, e.span)),
                None => None,
            });
        }
        let get = |n: &str| {
            let i = names.iter().position(|x| *x == n)?;
            consts[i - 1].clone()
        };
        let int = |n: &str, default: i64| match get(n) {
            Some((Value::Int(i), _)) => i,
            _ => default,
        };
        let float = |n: &str, default: f64| get(n).and_then(|(v, _)| v.as_f64()).unwrap_or(default);
        let seed = int("seed", 0) as u32;
        let fractal = Fractal {
            octaves: int("octaves", 6) as u32,
            omega: float("omega", 0.5),
            lambda: float("lambda", 2.0),
        };
        let f = match name {
            "noise" => NoiseFn::Unit { seed },
            "snoise" => NoiseFn::Signed { seed },
            "vnoise" => NoiseFn::Vector { seed },
            "fbm" => NoiseFn::Fbm { fractal, seed },
            "turbulence" => NoiseFn::Turbulence { fractal, seed },
            _ => {
                let form = match get("form") {
                    None => crate::pattern::Crackle::F1,
                    Some((Value::Str(f), at)) => sigs::form_of(&f).ok_or_else(|| {
                        super::texture_methods::bad_choice("form", &f, sigs::FORMS, at)
                    })?,
                    Some((v, at)) => return Err(mismatch(at, "String", v.type_name())),
                };
                NoiseFn::Worley { form, seed }
            }
        };
        let dst = self.alloc(f.width() as u16, span)?;
        self.emit(Op::Noise { f, dst, p: pr }, span)?;
        let ty = if f.width() == 3 { Ty::Vec3 } else { Ty::Float };
        Ok(Val::Reg(ty, dst))
    }

    /// The option `param` of the noise `sig`: a constant of its type and range.
    fn constant(&mut self, sig: &Sig, param: &str, e: &Expr) -> R<Value> {
        let v = match self.expr(e)? {
            Val::Const(v) => v,
            _ => {
                return Err(nope(
                    e.span,
                    format!(
                        "`{param}` of `{}` must be known when the pattern is made",
                        sig.name
                    ),
                    "computed per point",
                    "give a number written here or a value from outside the function",
                ));
            }
        };
        let Some(p) = sig.param(param) else {
            return Ok(v);
        };
        let ok = match (&v, p.ty) {
            (Value::Int(i), super::schema::Ty::Int) => p.range.holds_int(*i),
            (Value::Int(_) | Value::Float(_), super::schema::Ty::Float) => {
                p.range.holds(v.as_f64().unwrap_or(0.0))
            }
            (Value::Str(_), super::schema::Ty::String) => true,
            (other, ty) => {
                let want = match ty {
                    super::schema::Ty::Int => "Int",
                    super::schema::Ty::String => "String",
                    _ => "Float",
                };
                return Err(mismatch(e.span, want, other.type_name()));
            }
        };
        if !ok {
            return Err(error(
                "rtc::param::out_of_range",
                e.span,
                format!("`{param}` must be {}", p.range.rule(p.ty)),
            )
            .with_label(format!("`{param}` is {}", v.show()))
            .with_help(format!("give `{param}` a value {}", p.range.rule(p.ty)))
            .into());
        }
        Ok(v)
    }
}

/// `rtc::arg::missing`: `param` of `name` not given.
fn missing(name: &str, param: &str, span: Span) -> super::error::EvalError {
    error(
        "rtc::arg::missing",
        span,
        format!("missing argument `{param}` in call of `{name}`"),
    )
    .with_label(format!("`{param}` is required"))
    .with_help(format!("add `{param}: ...` to the call"))
    .into()
}
