//! Blocks and `for` loops: scopes of local bindings, loop headers with their filters, and the
//! iteration budget (the statement side of the interpreter; expressions are in `interp.rs`).

use std::rc::Rc;

use crate::diag::Diagnostic;
use crate::source::Span;
use crate::syntax::ast::*;

use super::super::error::{R, error};
use super::super::lower::Sink;
use super::super::value::{Closure, Value};
use super::Interp;

impl Interp<'_> {
    /// Evaluates a block in a new scope; its value is its last expression (`Unit` if none).
    pub(crate) fn block(&mut self, b: &Block) -> R<Value> {
        let mark = self.locals.len();
        let r = self.block_inner(b, mark);
        self.locals.truncate(mark);
        r
    }

    fn block_inner(&mut self, b: &Block, mark: usize) -> R<Value> {
        let mut last = Value::Unit;
        let n = b.stmts.len();
        for (i, st) in b.stmts.iter().enumerate() {
            match st {
                Stmt::Let(l) => {
                    if l.param {
                        return Err(super::super::params::misplaced(l).into());
                    }
                    let v = self.eval(&l.value)?;
                    let v = match &l.ty {
                        Some(t) => super::super::types::check_ann(self, t, v, l.value.span)?,
                        None => v,
                    };
                    self.bind_local(l.name, v, mark)?;
                }
                Stmt::Fn(def) => {
                    let c = Closure {
                        def: def.clone(),
                        captured: self.locals[self.frame_base..].to_vec(),
                        module: self.scope.clone(),
                    };
                    self.bind_local(def.name, Value::Fn(Rc::new(c)), mark)?;
                }
                Stmt::Import(im) => {
                    return Err(error(
                        "rtc::module::import_position",
                        im.span,
                        "`import` inside a block",
                    )
                    .with_label("imports belong at the top of a file")
                    .with_help("move this `import` to the top level of the file")
                    .into());
                }
                Stmt::Expr(e) => {
                    let v = self.eval(e)?;
                    if i + 1 == n {
                        last = v;
                    } else if !matches!(v, Value::Unit) {
                        return Err(error("rtc::value::discarded", e.span, "this value is discarded")
                            .with_label(format!("{} that goes nowhere", super::super::value::a_type(v.type_name())))
                            .with_help("only the last expression of a block is its value; collect several values in a list `[a, b]`")
                            .into());
                    }
                }
            }
        }
        Ok(last)
    }

    fn bind_local(&mut self, name: Name, v: Value, mark: usize) -> R<()> {
        if self.locals[mark..].iter().any(|(k, _)| *k == name.sym) {
            return Err(error(
                "rtc::name::duplicate",
                name.span,
                format!("`{}` is already defined in this block", name.sym),
            )
            .with_label("second definition")
            .with_help(format!(
                "choose another name, or remove the earlier `let {}`",
                name.sym
            ))
            .into());
        }
        let outer = self.locals[self.frame_base..mark]
            .iter()
            .any(|(k, _)| *k == name.sym)
            || self.scope.items.borrow().contains_key(&name.sym);
        if outer && !name.sym.as_str().starts_with('_') {
            self.warn(
                Diagnostic::warning(
                    "rtc::name::shadowed",
                    name.span,
                    format!("`{}` shadows an outer binding", name.sym),
                )
                .with_label("this hides the outer value in this block")
                .with_help(format!(
                    "rename it, or write `_{}` if the shadowing is intended",
                    name.sym
                )),
            );
        }
        self.locals.push((name.sym, v));
        Ok(())
    }

    pub(super) fn for_level(
        &mut self,
        gens: &[Generator],
        level: usize,
        filter: Option<&Expr>,
        body: &Block,
        span: Span,
        out: &mut Sink,
    ) -> R<()> {
        if level == gens.len() {
            let saved = self
                .prov
                .is_some()
                .then(|| self.enter_iteration(gens.len(), span));
            let r = self.for_body(filter, body, out, span);
            if let (Some(p), Some(s)) = (&mut self.prov, saved) {
                p.leave(s);
            }
            return r.map_err(|e| {
                let vars = &self.locals[self.locals.len() - gens.len()..];
                let desc: Vec<String> = vars
                    .iter()
                    .map(|(k, v)| format!("{k} = {}", v.show()))
                    .collect();
                e.frame(span, || {
                    format!("in iteration {} of this `for`", desc.join(", "))
                })
            });
        }
        let g = &gens[level];
        let it = self.eval(&g.iter)?;
        let n = self.loop_len(&it, g)?;
        self.for_steps(gens, level, &it, 0..n, filter, body, span, out)
    }

    /// How many elements a loop's generator value `it` has; an error for a value that is not
    /// a range, a list or a vector.
    pub(super) fn loop_len(&self, it: &Value, g: &Generator) -> R<u64> {
        match it {
            Value::Range(r) => Ok(r.len()),
            Value::List(l) => Ok(l.len() as u64),
            Value::Vec3(_) => Ok(3),
            other => {
                let d = error(
                    "rtc::type::mismatch",
                    g.iter.span,
                    format!(
                        "cannot loop over {}",
                        super::super::value::a_type(other.type_name())
                    ),
                )
                .with_label("not a range or a list");
                let d = if matches!(other, Value::Int(_)) {
                    d.with_help(format!("write a range: `0..{}`", self.snippet(g.iter.span)))
                } else {
                    d.with_help("loop over a range such as `0..5` or a list")
                };
                Err(d.into())
            }
        }
    }

    /// Runs the iterations `steps` of loop level `level`, whose generator's value is `it`
    /// (checked by [`Interp::loop_len`]), with the deeper levels for each.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn for_steps(
        &mut self,
        gens: &[Generator],
        level: usize,
        it: &Value,
        steps: std::ops::Range<u64>,
        filter: Option<&Expr>,
        body: &Block,
        span: Span,
        out: &mut Sink,
    ) -> R<()> {
        // The variable of a loop over a `Vec3` holds Floats: the help of a `Float` index says so.
        let vec3 = matches!(it, Value::Vec3(_));
        if vec3 {
            self.vec3_loops.push(gens[level].var.sym);
        }
        let r = self.for_steps_in(gens, level, it, steps, filter, body, span, out);
        if vec3 {
            self.vec3_loops.pop();
        }
        r
    }

    /// [`Interp::for_steps`] itself.
    #[allow(clippy::too_many_arguments)]
    fn for_steps_in(
        &mut self,
        gens: &[Generator],
        level: usize,
        it: &Value,
        steps: std::ops::Range<u64>,
        filter: Option<&Expr>,
        body: &Block,
        span: Span,
        out: &mut Sink,
    ) -> R<()> {
        let g = &gens[level];
        for i in steps {
            let v = match it {
                Value::Range(r) => r.get(i),
                Value::List(l) => l[i as usize].clone(),
                Value::Vec3(v) => Value::Float(v.to_array()[i as usize]),
                _ => return Ok(()),
            };
            self.step(span, super::super::budgets::Step::Loop)?;
            self.locals.push((g.var.sym, v));
            let r = self.for_level(gens, level + 1, filter, body, span, out);
            self.locals.pop();
            r?;
        }
        Ok(())
    }

    /// Enters the provenance step of the current iteration of the `for` at `header` (its
    /// variables are the last `vars` locals).
    #[cold]
    #[inline(never)]
    fn enter_iteration(&mut self, vars: usize, header: Span) -> u32 {
        let bindings = self.locals[self.locals.len() - vars..]
            .iter()
            .map(|(k, v)| format!("{k} = {}", v.show()))
            .collect::<Vec<_>>()
            .join(", ");
        let kind = crate::ir::provenance::StepKind::Iteration {
            at: header,
            bindings,
        };
        self.prov.as_mut().map_or(0, |p| p.enter(kind))
    }

    fn for_body(
        &mut self,
        filter: Option<&Expr>,
        body: &Block,
        out: &mut Sink,
        span: Span,
    ) -> R<()> {
        if let Some(f) = filter {
            match self.eval(f)? {
                Value::Bool(true) => {}
                Value::Bool(false) => return Ok(()),
                other => {
                    return Err(super::super::types::mismatch(self, "Bool", &other, f.span).into());
                }
            }
        }
        let v = self.block(body)?;
        if matches!(v, Value::Unit) {
            return Ok(());
        }
        match out {
            Sink::List(list) => {
                self.check_list_len(list.len() + 1, span)?;
                self.charge(super::super::value::VALUE_BYTES, span, "this loop's list")?;
                list.push(v);
            }
            Sink::Emit(lowerer, stmt) => lowerer.emit(&v, &self.object_budget(), *stmt)?,
        }
        Ok(())
    }

    /// Evaluates a top-level `for` statement of a scene file (its statement `stmt`, counted
    /// from 0), emitting each element as it is made instead of building the whole list first
    /// (a million objects never coexist as values). A long loop may be split over threads
    /// (`split`).
    pub(crate) fn emit_for(
        &mut self,
        e: &Expr,
        stmt: usize,
        lowerer: &mut super::super::lower::Lowerer,
    ) -> R<bool> {
        let ExprKind::For(gens, filter, body) = &e.kind else {
            return Ok(false);
        };
        let lp = super::split::Loop {
            gens,
            filter: filter.as_deref(),
            body,
            header: self.header_span(e.span, body.span),
            span: e.span,
        };
        lowerer.reserve_for(gens, lp.filter, self.opts.max_objects);
        if self.split.helper_stmt() == Some(stmt) {
            self.emit_part(&lp, lowerer);
            return Ok(true);
        }
        if matches!(self.split, super::super::parts::Role::Main(_)) {
            self.emit_split_for(&lp, stmt, lowerer)?;
            return Ok(true);
        }
        let mut sink = Sink::Emit(lowerer, e.span);
        self.for_level(gens, 0, lp.filter, body, lp.header, &mut sink)?;
        Ok(true)
    }
}
