//! The calls and members of a compiled function (`eval::compile`): `obj.name`, built-in and
//! user calls (inlined, their arguments bound as the interpreter binds them).

use std::rc::Rc;

use glam::DVec3;

use crate::pattern::program::{Op, Reg};
use crate::source::Span;
use crate::syntax::ast::{Arg, Expr, ExprKind, FnDef, Name};

use super::compile::{Callable, Compiler, MAX_INLINE_DEPTH, Ty, Val, nope};
use super::error::{EvalError, R, error};
use super::value::Value;

impl Compiler {
    /// `obj.name`: a vector's component(s), a module's or a record's member.
    pub(super) fn member(&mut self, obj: &Expr, name: Name, span: Span) -> R<Val> {
        let v = self.expr(obj)?;
        let n = name.sym.as_str();
        let comps: Option<Vec<usize>> = (!n.is_empty() && n.len() != 2 && n.len() <= 3)
            .then(|| n.chars().map(|c| "xyz".find(c)).collect())
            .flatten();
        match (v, comps) {
            (Val::Const(Value::Module(m)), _) => match m.export(name.sym) {
                Ok(b) if !b.poisoned => Ok(Val::Const(b.value)),
                Ok(_) => Err(EvalError::Poisoned),
                Err(_) => Err(nope(
                    name.span,
                    format!("`{}` has no export `{n}`", m.name),
                    "not exported",
                    "check the name",
                )),
            },
            (Val::Const(Value::Record(r)), _) if r.get(name.sym).is_some() => {
                Ok(Val::Const(r.get(name.sym).cloned().unwrap_or(Value::Unit)))
            }
            (Val::Const(Value::Vec3(x)), Some(c)) => Ok(Val::Const(if c.len() == 1 {
                Value::Float(x[c[0]])
            } else {
                Value::Vec3(DVec3::new(x[c[0]], x[c[1]], x[c[2]]))
            })),
            (Val::Reg(Ty::Vec3, r), Some(c)) if c.len() == 1 => {
                Ok(Val::Reg(Ty::Float, r + c[0] as Reg))
            }
            (Val::Reg(Ty::Vec3, r), Some(c)) => {
                let dst = self.alloc(3, span)?;
                for (i, k) in c.into_iter().enumerate() {
                    let (d, src) = (dst + i as Reg, r + k as Reg);
                    self.emit(
                        Op::Copy {
                            dst: d,
                            src,
                            width: 1,
                        },
                        span,
                    )?;
                }
                Ok(Val::Reg(Ty::Vec3, dst))
            }
            _ => Err(nope(
                name.span,
                format!("`.{n}` cannot be compiled here"),
                "not compilable",
                "a compiled function reads a vector's `.x`, `.y`, `.z` (or `.xyz`, `.zyx`, ...), and members of modules and captured records",
            )),
        }
    }

    /// `f(args)`: a built-in compiled in place, a user function inlined.
    pub(super) fn call(&mut self, callee: &Expr, args: &[Arg], span: Span) -> R<Val> {
        let f = match &callee.kind {
            ExprKind::Member(obj, name) => match self.expr(obj)? {
                Val::Const(Value::Module(_)) => self.member(obj, *name, callee.span)?,
                _ => {
                    return Err(nope(
                        callee.span,
                        format!("the method call `.{}(..)` cannot be compiled", name.sym),
                        "a method call",
                        "call a function instead, e.g. `length(v)` or `normalize(v)`",
                    ));
                }
            },
            _ => self.expr(callee)?,
        };
        match f {
            Val::Const(Value::Builtin(b)) => self.builtin(b.name, args, span, callee.span),
            Val::Const(Value::Fn(c)) => self.inline(&Rc::new(Callable::of(&c)), args, span),
            Val::Fn(c) => self.inline(&c, args, span),
            _ => Err(error(
                "rtc::type::not_callable",
                callee.span,
                "this is not a function",
            )
            .with_label("called here")
            .with_help("remove the parentheses to use the value itself")
            .into()),
        }
    }

    /// A user function's body in place of its call, its parameters bound to the arguments.
    fn inline(&mut self, c: &Rc<Callable>, args: &[Arg], span: Span) -> R<Val> {
        let def = &c.def;
        let fname = def.name.sym;
        if self.inlining.iter().any(|d| Rc::ptr_eq(d, def)) {
            return Err(nope(
                span,
                format!("`{fname}` calls itself: recursion cannot be compiled"),
                "recursive call",
                "write the function without recursion (a fixed number of steps)",
            ));
        }
        if self.inlining.len() >= MAX_INLINE_DEPTH {
            return Err(nope(
                span,
                format!("calls nested deeper than {MAX_INLINE_DEPTH} cannot be compiled"),
                "too deep",
                "call fewer functions within one another",
            ));
        }
        let names: Vec<&str> = def.params.iter().map(|p| p.name.sym.as_str()).collect();
        let slots = self.bind(fname.as_str(), &names, args, span)?;
        let mark = self.top;
        let mut vals = Vec::with_capacity(slots.len());
        for s in slots {
            vals.push(match s {
                Some(e) => Some((self.expr(e)?, e.span)),
                None => None,
            });
        }
        let saved_base = std::mem::replace(&mut self.frame_base, self.locals.len());
        let saved_module = std::mem::replace(&mut self.module, c.module.clone());
        self.locals.extend(c.captured.iter().cloned());
        if fname.as_str() != "<fn>" {
            self.locals.push((fname, Val::Fn(c.clone())));
        }
        self.inlining.push(def.clone());
        let r = self.body(def, vals, span);
        self.inlining.pop();
        self.locals.truncate(self.frame_base);
        self.frame_base = saved_base;
        self.module = saved_module;
        let v = r.map_err(|e| {
            if fname.as_str() == "<fn>" {
                e.frame(span, || "in call of a `fn` literal".to_owned())
            } else {
                e.frame(span, || format!("in call of `{fname}`"))
            }
        })?;
        self.settle(mark, v, span)
    }

    /// The parameters bound, then the body.
    fn body(&mut self, def: &FnDef, vals: Vec<Option<(Val, Span)>>, span: Span) -> R<Val> {
        for (p, v) in def.params.iter().zip(vals) {
            let (v, at) = match (v, &p.default) {
                (Some(v), _) => v,
                (None, Some(d)) => (self.expr(d)?, d.span),
                (None, None) => {
                    return Err(error(
                        "rtc::arg::missing",
                        span,
                        format!(
                            "missing argument `{}` in call of `{}`",
                            p.name.sym, def.name.sym
                        ),
                    )
                    .with_label(format!("`{}` is required", p.name.sym))
                    .with_help(format!("add `{}: ...` to the call", p.name.sym))
                    .into());
                }
            };
            let v = self.annotate(p.ty.as_ref(), v, at)?;
            self.locals.push((p.name.sym, v));
        }
        let v = self.block(&def.body)?;
        self.annotate(def.ret.as_ref(), v, def.body.span)
    }

    /// The arguments matched to the parameters `names` (positional first, then named).
    pub(super) fn bind<'e>(
        &self,
        fname: &str,
        names: &[&str],
        args: &'e [Arg],
        span: Span,
    ) -> R<Vec<Option<&'e Expr>>> {
        let mut slots = vec![None; names.len()];
        let mut next = 0;
        for a in args {
            let i = match a.name {
                Some(n) => names
                    .iter()
                    .position(|p| *p == n.sym.as_str())
                    .ok_or_else(|| {
                        EvalError::from(
                            error(
                                "rtc::arg::unknown",
                                n.span,
                                format!("`{fname}` has no parameter named `{}`", n.sym),
                            )
                            .with_label("unknown argument")
                            .with_help(format!("its parameters are: {}", names.join(", "))),
                        )
                    })?,
                None => {
                    next += 1;
                    next - 1
                }
            };
            if i >= names.len() {
                return Err(error(
                    "rtc::arg::too_many",
                    a.value.span,
                    format!(
                        "`{fname}` takes {} arguments but more were given",
                        names.len()
                    ),
                )
                .with_label("unexpected argument")
                .with_help("remove this argument")
                .into());
            }
            if slots[i].is_some() {
                return Err(error(
                    "rtc::arg::duplicate",
                    a.value.span,
                    format!("parameter `{}` is given twice", names[i]),
                )
                .with_label("second value")
                .with_help("remove one of the two arguments")
                .into());
            }
            slots[i] = Some(&a.value);
        }
        let _ = span;
        Ok(slots)
    }
}
