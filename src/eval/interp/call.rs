//! Calls: argument matching for user functions and dispatch to built-ins and methods.

use std::rc::Rc;

use crate::source::Span;
use crate::syntax::ast::{Arg, Expr, ExprKind};

use super::super::args::{ArgVal, CallSite, args_vec};
use super::super::error::{EvalError, R, error, suggest};
use super::super::value::{Closure, Value};
use super::Interp;

impl Interp<'_> {
    fn eval_args(&mut self, args: &[Arg]) -> R<Vec<ArgVal>> {
        let mut out = args_vec(args.len());
        for a in args {
            out.push(ArgVal {
                name: a.name,
                value: self.operand(&a.value)?,
                span: a.value.span,
            });
        }
        Ok(out)
    }

    /// Evaluates `callee(args)`, including method calls `x.m(args)` and module functions.
    pub(crate) fn call_expr(&mut self, callee: &Expr, args: &[Arg], span: Span) -> R<Value> {
        if let ExprKind::Member(obj, name) = &callee.kind {
            let recv = self.eval(obj)?;
            let field = match &recv {
                Value::Module(_) | Value::Record(_) => Some(super::super::members::member(
                    self,
                    recv.clone(),
                    *name,
                    obj.span,
                )?),
                _ => None,
            };
            let argv = self.eval_args(args)?;
            return match field {
                Some(f) => self.call_value(f, argv, span, callee.span),
                None => super::super::methods::call_method(self, recv, *name, argv, span),
            };
        }
        let f = self.eval(callee)?;
        let argv = self.eval_args(args)?;
        self.call_value(f, argv, span, callee.span)
    }

    /// Calls a function value with evaluated arguments.
    pub(crate) fn call_value(
        &mut self,
        f: Value,
        args: Vec<ArgVal>,
        span: Span,
        callee_span: Span,
    ) -> R<Value> {
        match f {
            Value::Fn(c) => self.call_closure(&c, args, span),
            Value::Builtin(b) => {
                let f = super::super::builtins::function(b.id);
                let mut v = f(self, CallSite { span, name: b.name }, args)?;
                if let (Some(p), Value::Object(o)) = (&mut self.prov, &mut v) {
                    // An object a built-in just made (`sphere`, `group`, ...) is owned by the
                    // result alone and has no origin yet: it was made here.
                    if let Some(o) = Rc::get_mut(o).filter(|o| o.origin == 0) {
                        o.origin = p.origin();
                    }
                }
                Ok(v)
            }
            other => Err(error(
                "rtc::type::not_callable",
                callee_span,
                format!(
                    "{} is not a function",
                    super::super::value::a_type(other.type_name())
                ),
            )
            .with_label("called here")
            .with_help("remove the parentheses to use the value itself")
            .into()),
        }
    }

    /// Calls a user function: matches arguments to parameters, checks types, runs the body.
    fn call_closure(&mut self, c: &Rc<Closure>, args: Vec<ArgVal>, span: Span) -> R<Value> {
        let def = &c.def;
        let fname = def.name.sym;
        if self.depth >= self.opts.max_recursion_depth {
            return Err(error(
                "rtc::budget::recursion",
                span,
                format!("calls nested deeper than {}", self.opts.max_recursion_depth),
            )
            .with_label(format!("this call to `{fname}` exceeds the depth budget"))
            .with_help("make sure the recursion reaches a base case")
            .into());
        }
        self.step(span, super::super::budgets::Step::Call)?;
        let mut slots: Vec<Option<(crate::syntax::intern::Sym, Value, Span)>> =
            vec![None; def.params.len()];
        let mut next_pos = 0;
        let mut seen_named: Option<Span> = None;
        for a in args {
            let idx = match a.name {
                Some(n) => {
                    seen_named.get_or_insert(n.span);
                    let Some(i) = def.params.iter().position(|p| p.name.sym == n.sym) else {
                        let names = def.params.iter().map(|p| p.name.sym.as_str());
                        let d = error(
                            "rtc::arg::unknown",
                            n.span,
                            format!("`{fname}` has no parameter named `{}`", n.sym),
                        )
                        .with_label("unknown argument")
                        .with_secondary(def.name.span, format!("`{fname}` is defined here"));
                        let list: Vec<&str> =
                            def.params.iter().map(|p| p.name.sym.as_str()).collect();
                        let help = suggest(n.sym.as_str(), names)
                            .unwrap_or_else(|| format!("its parameters are: {}", list.join(", ")));
                        return Err(d.with_help(help).into());
                    };
                    i
                }
                None => {
                    if let Some(ns) = seen_named {
                        return Err(error(
                            "rtc::arg::positional_after_named",
                            a.span,
                            "positional argument after a named one",
                        )
                        .with_label("positional")
                        .with_secondary(ns, "named argument before it")
                        .with_help("put positional arguments first, or name this one too")
                        .into());
                    }
                    next_pos += 1;
                    if next_pos > def.params.len() {
                        return Err(error(
                            "rtc::arg::too_many",
                            a.span,
                            format!(
                                "`{fname}` takes {} argument{} but more were given",
                                def.params.len(),
                                if def.params.len() == 1 { "" } else { "s" }
                            ),
                        )
                        .with_label("unexpected argument")
                        .with_secondary(def.name.span, format!("`{fname}` is defined here"))
                        .with_help("remove this argument")
                        .into());
                    }
                    next_pos - 1
                }
            };
            if slots[idx].is_some() {
                return Err(error(
                    "rtc::arg::duplicate",
                    a.span,
                    format!("parameter `{}` is given twice", def.params[idx].name.sym),
                )
                .with_label("second value")
                .with_help("remove one of the two arguments")
                .into());
            }
            slots[idx] = Some((def.params[idx].name.sym, a.value, a.span));
        }
        let base = self.locals.len();
        let saved_base = std::mem::replace(&mut self.frame_base, base);
        let saved_scope = std::mem::replace(&mut self.scope, c.module.clone());
        self.locals.extend(c.captured.iter().cloned());
        if fname.as_str() != "<fn>" {
            self.locals.push((fname, Value::Fn(c.clone())));
        }
        self.depth += 1;
        let saved = self.prov.as_mut().map(|p| {
            p.enter(crate::ir::provenance::StepKind::Call {
                name: fname.as_str().to_string(),
                at: span,
            })
        });
        let r = self.run_body(c, slots, span);
        if let (Some(p), Some(s)) = (&mut self.prov, saved) {
            p.leave(s);
        }
        self.depth -= 1;
        self.locals.truncate(base);
        self.frame_base = saved_base;
        self.scope = saved_scope;
        r
    }

    fn run_body(
        &mut self,
        c: &Rc<Closure>,
        slots: Vec<Option<(crate::syntax::intern::Sym, Value, Span)>>,
        span: Span,
    ) -> R<Value> {
        let def = &c.def;
        let fname = def.name.sym;
        for (p, slot) in def.params.iter().zip(slots) {
            let (v, vspan) = match slot {
                Some((_, v, s)) => (v, s),
                None => match &p.default {
                    Some(d) => (self.eval(d)?, d.span),
                    None => {
                        return Err(EvalError::from(
                            error(
                                "rtc::arg::missing",
                                span,
                                format!("missing argument `{}` in call of `{fname}`", p.name.sym),
                            )
                            .with_label(format!("`{}` is required", p.name.sym))
                            .with_secondary(p.name.span, "declared here without a default")
                            .with_help(format!("add `{}: ...` to the call", p.name.sym)),
                        ));
                    }
                },
            };
            let v = match &p.ty {
                Some(t) => super::super::types::check_ann(self, t, v, vspan)?,
                None => v,
            };
            self.locals.push((p.name.sym, v));
        }
        let frame = |e: EvalError| {
            if fname.as_str() == "<fn>" {
                e.frame(span, || "in call of a `fn` literal".to_owned())
            } else {
                e.frame(span, || format!("in call of `{fname}`"))
            }
        };
        let v = self.block(&def.body).map_err(frame)?;
        match &def.ret {
            Some(t) => super::super::types::check_ann(self, t, v, def.body.span).map_err(frame),
            None => Ok(v),
        }
    }
}
