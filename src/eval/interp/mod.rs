//! The tree-walking evaluator: its state, names and expressions (blocks and loops are in `blocks.rs`).

mod blocks;
mod call;
mod host_impl;
mod meters;
mod names;
mod param_stmt;
mod program;
mod split;

use std::collections::{HashMap, HashSet};
use std::path::PathBuf;
use std::rc::Rc;

use crate::diag::Diagnostic;
use crate::source::{SourceMap, Span};
use crate::syntax::ast::*;
use crate::syntax::intern::Sym;

use super::error::{R, error};
use super::lower::Sink;
use super::modules::{Module, Scope};
use super::ops::Num;
use super::options::EvalOptions;
use super::value::{Closure, Record, Value};

/// Most operator nodes one try of the pure arithmetic path visits (`Interp::pure_num`).
const PURE_NODES: u32 = 16;

/// Evaluation state for one run (the scene file and everything it imports).
///
/// Its fields are private to `eval/interp/` (this file and the files that extend it with
/// statements, calls, modules, meters and loop splitting); the rest of the evaluator asks
/// through methods, and built-ins through [`Host`](super::host::Host).
///
/// **The replay rule.** A long top-level loop may be evaluated in parts on other threads, each
/// replaying the file up to the loop (`split.rs`). A replay must reach the loop in the state
/// the main thread reached it in, so every field here that an iteration can change and that
/// is not scoped to the iteration (`made`, `loop_iters`, `memory`, `diags`, and what the
/// lowerer emitted) is recorded in [`Mark`](super::parts::Mark) and compared; a new field of
/// that kind must be added to `Mark` and to the merge of a helper's `Part`, or splitting
/// would change what a scene makes.
pub(crate) struct Interp<'a> {
    /// Budgets.
    opts: &'a EvalOptions,
    /// Every file read so far.
    sources: &'a mut SourceMap,
    /// Findings recorded so far (errors recovered at statement boundaries, warnings, prints).
    diags: Vec<Diagnostic>,
    warned: HashSet<(&'static str, Span)>,
    /// Local bindings of all active frames; the current frame starts at `frame_base`.
    locals: Vec<(Sym, Value)>,
    /// First local of the current function frame.
    frame_base: usize,
    /// The module whose items are visible.
    scope: Rc<Scope>,
    /// Loop iterations so far (budget).
    loop_iters: u64,
    /// Bytes of strings and lists made so far, charged to the memory budget (`budgets.rs`).
    memory: std::cell::Cell<u64>,
    /// Nested user calls (budget).
    depth: u32,
    /// Evaluated modules by key (`std.x` or resolved path).
    modules: HashMap<PathBuf, Rc<Module>>,
    /// Modules being evaluated, outermost first, with the import that started each (cycles).
    loading: Vec<(PathBuf, Span)>,
    /// The command line's `--set` values.
    overrides: Vec<super::params::Override>,
    /// The `param` names the scene file declared so far.
    params: Vec<Sym>,
    /// The variables of the `for` loops running over a `Vec3` (their values are Floats), for
    /// the help of a `Float` index.
    vec3_loops: Vec<Sym>,
    /// Where objects come from, when asked (`EvalOptions::provenance`).
    prov: Option<Box<super::provenance::Builder>>,
    /// Material and texture values made so far ([`Interp::next_made`]).
    made: u64,
    /// This thread's part in evaluating long loops on several threads.
    split: super::parts::Role,
}

impl Drop for Interp<'_> {
    /// A module's functions keep its scope (`Closure::module`) and the scope keeps them: an `Rc`
    /// cycle. Emptying every scope when evaluation ends breaks them, so a process that
    /// evaluates many scenes (the test suites, the fuzzers, a watcher) frees each one.
    fn drop(&mut self) {
        let scopes = std::iter::once(&self.scope).chain(self.modules.values().map(|m| &m.scope));
        for scope in scopes {
            let items = std::mem::take(&mut *scope.items.borrow_mut());
            drop(items);
        }
    }
}

impl<'a> Interp<'a> {
    /// The current module's item `name` (tests read what a scene bound).
    #[cfg(test)]
    pub(crate) fn item(&self, name: &str) -> Option<Value> {
        let sym = crate::syntax::intern::Sym::new(name);
        self.scope.items.borrow().get(&sym).map(|b| b.value.clone())
    }

    /// A fresh evaluator whose current module is `scope`.
    pub(crate) fn new(
        opts: &'a EvalOptions,
        sources: &'a mut SourceMap,
        scope: Rc<Scope>,
    ) -> Interp<'a> {
        Interp {
            opts,
            sources,
            diags: Vec::new(),
            warned: HashSet::new(),
            locals: Vec::new(),
            frame_base: 0,
            scope,
            loop_iters: 0,
            memory: std::cell::Cell::new(0),
            depth: 0,
            modules: HashMap::new(),
            loading: Vec::new(),
            overrides: Vec::new(),
            params: Vec::new(),
            vec3_loops: Vec::new(),
            prov: opts.provenance.then(Box::default),
            made: 0,
            split: super::parts::Role::Off,
        }
    }

    /// Starts evaluating the file `root` (its canonical path: the first module being loaded)
    /// with the `--set` values `overrides` and this thread's part in splitting loops.
    pub(in crate::eval) fn begin(
        &mut self,
        root: PathBuf,
        overrides: Vec<super::params::Override>,
        split: super::parts::Role,
    ) {
        self.loading.push((root, Span::default()));
        self.overrides = overrides;
        self.split = split;
    }

    /// The findings so far, taken out (evaluation is over).
    pub(in crate::eval) fn take_findings(&mut self) -> Vec<Diagnostic> {
        std::mem::take(&mut self.diags)
    }

    /// The provenance recorded, taken out (evaluation is over).
    pub(in crate::eval) fn take_provenance(&mut self) -> Option<Box<super::provenance::Builder>> {
        self.prov.take()
    }

    /// A helper's part of a split loop, once evaluated.
    pub(in crate::eval) fn take_part(&mut self) -> Option<super::parts::Part> {
        self.split.take_part()
    }

    /// Numbers a new material or texture value: values are told apart by these numbers, which
    /// a replay of the evaluation on another thread gives out alike (`split`).
    fn next_made(&mut self) -> u64 {
        self.made += 1;
        self.made
    }

    /// The provenance origin of an object made now (0 when provenance is off).
    fn origin(&mut self) -> u32 {
        self.prov.as_mut().map_or(0, |p| p.origin())
    }

    /// The provenance origin of an object derived now from one of origin `from`.
    fn derive(&mut self, from: u32) -> u32 {
        self.prov.as_mut().map_or(from, |p| p.derive(from))
    }

    /// Records a finding every time (`print`'s notes).
    fn report(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }

    /// The folder relative asset paths of the current module resolve against.
    fn dir(&self) -> &std::path::Path {
        &self.scope.dir
    }

    /// The path of the current module's file (for messages).
    fn file_path(&self) -> &std::path::Path {
        &self.sources.get(self.scope.file).path
    }

    /// Records a warning once per (code, span), however often a loop reaches it.
    fn warn(&mut self, d: Diagnostic) {
        let Some(span) = d.span else {
            return self.diags.push(d);
        };
        if self.warned.insert((d.code, span)) {
            self.split.note_warning(self.diags.len());
            self.diags.push(d);
        }
    }

    /// The source text under a span.
    fn snippet(&self, span: Span) -> &str {
        self.sources.snippet(span)
    }
}

impl super::error::Quote for Interp<'_> {
    fn snippet(&self, span: Span) -> &str {
        self.sources.snippet(span)
    }
}

impl Interp<'_> {
    /// Evaluates an expression. The common kinds are handled here, in tail position (no
    /// re-wrapping of results); the others are in `eval_other`, out of line. Every kind that
    /// evaluates sub-expressions is out of line too, so this function, entered for every node,
    /// needs no stack frame of its own: a literal or a local costs a few instructions, not a
    /// frame of every arm's temporaries (a million spheres from a loop evaluate ~30 nodes each).
    fn eval(&mut self, e: &Expr) -> R<Value> {
        match &e.kind {
            ExprKind::Int(i) => Ok(Value::Int(*i)),
            ExprKind::Float(f) => Ok(Value::Float(*f)),
            ExprKind::Angle(a) => Ok(Value::Angle(*a)),
            ExprKind::Bool(b) => Ok(Value::Bool(*b)),
            ExprKind::Color(c) => Ok(Value::Color((*c).into())),
            ExprKind::Vec3(v) => Ok(Value::Vec3((*v).into())),
            ExprKind::StrLit(s) => Ok(Value::Str(s.clone())),
            ExprKind::Ident(s) => self.lookup(*s, e.span),
            ExprKind::List(items, trailing) => self.list(items, *trailing, e.span),
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, e.span),
            ExprKind::Call(callee, args) => self.call_expr(callee, args, e.span),
            ExprKind::Member(obj, name) => self.member(obj, *name),
            _ => self.eval_other(e),
        }
    }

    /// [`Interp::eval`] with the leaves (numbers, locals) taken here, without a call: the
    /// operands of arithmetic, the elements of `[x, y, z]` and arguments are mostly leaves.
    #[inline(always)]
    pub(in crate::eval) fn operand(&mut self, e: &Expr) -> R<Value> {
        match &e.kind {
            ExprKind::Int(i) => Ok(Value::Int(*i)),
            ExprKind::Float(f) => Ok(Value::Float(*f)),
            ExprKind::Ident(s) => self.lookup(*s, e.span),
            _ => self.eval(e),
        }
    }

    #[inline(never)]
    fn member(&mut self, obj: &Expr, name: Name) -> R<Value> {
        let v = self.eval(obj)?;
        super::members::member(self, v, name, obj.span)
    }

    /// The expression kinds `eval` does not handle itself.
    #[inline(never)]
    fn eval_other(&mut self, e: &Expr) -> R<Value> {
        Ok(match &e.kind {
            ExprKind::Str(parts) => self.string(parts)?,
            ExprKind::Record(fields) => self.record(fields)?,
            ExprKind::Unary(op, x) => {
                let v = self.eval(x)?;
                super::ops::unary(*op, v, e.span)?
            }
            ExprKind::Range {
                start,
                end,
                inclusive,
                step,
            } => self.range(start, end, *inclusive, step.as_deref(), e.span)?,
            ExprKind::Index(obj, idx) => {
                let v = self.eval(obj)?;
                let i = self.eval(idx)?;
                let from_vec3 =
                    matches!(&idx.kind, ExprKind::Ident(s) if self.vec3_loops.contains(s));
                super::members::index(v, i, (idx.span, from_vec3))?
            }
            ExprKind::With(base, fields) => {
                let v = self.eval(base)?;
                let mut upd = Vec::with_capacity(fields.len());
                for f in fields {
                    upd.push((f.name, self.eval(&f.value)?, f.value.span));
                }
                super::with::with(self, v, base.span, upd)?
            }
            ExprKind::If(cond, then, els) => {
                let c = self.eval(cond)?;
                match c {
                    Value::Bool(true) => self.block(then)?,
                    Value::Bool(false) => match els {
                        Some(e) => self.eval(e)?,
                        None => Value::List(Rc::new(Vec::new())),
                    },
                    other => {
                        return Err(super::types::mismatch(self, "Bool", &other, cond.span).into());
                    }
                }
            }
            ExprKind::For(gens, filter, body) => {
                let mut out = Vec::new();
                let header = self.header_span(e.span, body.span);
                let mut sink = Sink::List(&mut out);
                self.for_level(gens, 0, filter.as_deref(), body, header, &mut sink)?;
                Value::List(Rc::new(out))
            }
            ExprKind::Lambda(def) => Value::Fn(Rc::new(Closure {
                def: def.clone(),
                captured: self.locals[self.frame_base..].to_vec(),
                module: self.scope.clone(),
            })),
            ExprKind::Block(b) => self.block(b)?,
            ExprKind::Int(_)
            | ExprKind::Float(_)
            | ExprKind::Angle(_)
            | ExprKind::Bool(_)
            | ExprKind::Color(_)
            | ExprKind::Vec3(_)
            | ExprKind::StrLit(_)
            | ExprKind::Ident(_)
            | ExprKind::List(..)
            | ExprKind::Binary(..)
            | ExprKind::Call(..)
            | ExprKind::Member(..) => return self.eval(e),
        })
    }

    /// `for i in 0..5` without its body: what traces and budget errors point at.
    pub(in crate::eval) fn header_span(&self, whole: Span, body: Span) -> Span {
        let text = self.sources.get(whole.file).text.as_bytes();
        let mut end = body.start.max(whole.start);
        while end > whole.start
            && text
                .get(end as usize - 1)
                .is_some_and(|c| c.is_ascii_whitespace())
        {
            end -= 1;
        }
        Span { end, ..whole }
    }

    fn string(&mut self, parts: &[StrPart]) -> R<Value> {
        let mut s = String::new();
        for p in parts {
            match p {
                StrPart::Text(t) => s.push_str(t),
                StrPart::Interp(e, prec) => {
                    let before = s.len();
                    let v = self.eval(e)?;
                    match (prec, v.as_f64(), &v) {
                        (Some(p), Some(f), _) => s.push_str(&format!("{f:.p$}")),
                        (_, _, Value::Str(t)) => s.push_str(t),
                        _ => s.push_str(&v.show()),
                    }
                    self.check_string_len(s.len(), e.span)?;
                    self.charge((s.len() - before) as u64, e.span, "this string")?;
                }
            }
        }
        Ok(Value::Str(s.into()))
    }

    #[inline(never)]
    /// `[...]`: three numbers make a `Vec3`, unless a trailing comma (`trailing`) keeps a `List`.
    fn list(&mut self, items: &[Expr], trailing: bool, span: Span) -> R<Value> {
        if let ([a, b, c], false) = (items, trailing) {
            // `[x, y, z]` of numbers is a Vec3: pure arithmetic in registers first (as in
            // `binary`), then each element evaluated without a heap list.
            let budget = &mut { PURE_NODES };
            if let (Some(x), Some(y), Some(z)) = (
                self.pure_num(a, budget),
                self.pure_num(b, budget),
                self.pure_num(c, budget),
            ) {
                return Ok(Value::Vec3(glam::DVec3::new(x.f64(), y.f64(), z.f64())));
            }
            let vals = [self.operand(a)?, self.operand(b)?, self.operand(c)?];
            if let (Some(x), Some(y), Some(z)) =
                (vals[0].as_f64(), vals[1].as_f64(), vals[2].as_f64())
            {
                return Ok(Value::Vec3(glam::DVec3::new(x, y, z)));
            }
            return Ok(Value::List(Rc::new(vals.into())));
        }
        let mut out = Vec::with_capacity(items.len());
        for it in items {
            out.push(self.eval(it)?);
        }
        self.new_list(out.len(), span)?;
        Ok(Value::List(Rc::new(out)))
    }

    fn record(&mut self, fields: &[Field]) -> R<Value> {
        let mut r = Record::default();
        for f in fields {
            if let Some(prev) = r.fields.iter().find(|x| x.name == f.name.sym) {
                return Err(error(
                    "rtc::field::duplicate",
                    f.name.span,
                    format!("field `{}` is given twice", f.name.sym),
                )
                .with_label("second value")
                .with_secondary(prev.name_span, "first value")
                .with_help("remove one of them")
                .into());
            }
            let v = self.eval(&f.value)?;
            r.fields.push(super::value::FieldVal {
                name: f.name.sym,
                value: v,
                span: f.value.span,
                name_span: f.name.span,
            });
        }
        Ok(Value::Record(Rc::new(r)))
    }

    #[inline(never)]
    fn binary(&mut self, op: BinOp, a: &Expr, b: &Expr, span: Span) -> R<Value> {
        if matches!(op, BinOp::And | BinOp::Or) {
            let l = self.eval(a)?;
            let Value::Bool(lb) = l else {
                return Err(super::types::mismatch(self, "Bool", &l, a.span).into());
            };
            if (op == BinOp::And) != lb {
                return Ok(Value::Bool(lb));
            }
            let r = self.eval(b)?;
            return match r {
                Value::Bool(rb) => Ok(Value::Bool(rb)),
                other => Err(super::types::mismatch(self, "Bool", &other, b.span).into()),
            };
        }
        // Arithmetic over numbers and names of numbers, nested or not, is computed in registers
        // first; anything else, or an operation `num_op` leaves to the general path (overflow,
        // division by zero), is evaluated below as before. The fast path only reads, so
        // evaluating a subtree again there repeats no effect, and its node budget keeps the
        // repeated work linear however deep a tree that fails is.
        if let Some(n) = self.pure_binary(op, a, b, &mut { PURE_NODES }) {
            return Ok(n.value());
        }
        let l = self.operand(a)?;
        let r = self.operand(b)?;
        if let Some(v) = super::ops::arithmetic(op, &l, &r) {
            // Both are numbers (`arithmetic` takes nothing else), which own nothing: skip the
            // two out-of-line drops.
            std::mem::forget(l);
            std::mem::forget(r);
            return Ok(v);
        }
        super::ops::binary(self, op, l, r, a.span, b.span, span)
    }

    /// `a op b` when both sides are pure arithmetic (see [`Interp::pure_num`]).
    #[inline(always)]
    fn pure_binary(&self, op: BinOp, a: &Expr, b: &Expr, budget: &mut u32) -> Option<Num> {
        if matches!(op, BinOp::And | BinOp::Or) {
            return None;
        }
        let l = self.pure_num(a, budget)?;
        let r = self.pure_num(b, budget)?;
        super::ops::num_op(op, l, r)
    }

    /// The number `e` evaluates to, when it is built from number literals, names bound to
    /// numbers, negation and the four arithmetic operators (plus `%`) alone, with ordinary
    /// results, within `budget` operator nodes; `None` otherwise (then [`Interp::eval`] gives
    /// the value or the error). Reads names only: nothing is evaluated for effect. The leaves
    /// (numbers, locals) are taken here, without a call, as [`Interp::operand`] does for
    /// [`Interp::eval`].
    #[inline(always)]
    fn pure_num(&self, e: &Expr, budget: &mut u32) -> Option<Num> {
        match &e.kind {
            ExprKind::Int(i) => Some(Num::Int(*i)),
            ExprKind::Float(f) => Some(Num::Float(*f)),
            ExprKind::Ident(s) => self.pure_name(*s),
            _ => self.pure_operation(e, budget),
        }
    }

    /// [`Interp::pure_num`] of an operator node (out of line: it recurses).
    fn pure_operation(&self, e: &Expr, budget: &mut u32) -> Option<Num> {
        match &e.kind {
            ExprKind::Binary(op, a, b) if *budget > 0 => {
                *budget -= 1;
                self.pure_binary(*op, a, b, budget)
            }
            ExprKind::Unary(UnOp::Neg, x) if *budget > 0 => {
                *budget -= 1;
                match self.pure_num(x, budget)? {
                    Num::Int(i) => Some(Num::Int(i.checked_neg()?)),
                    Num::Float(f) => Some(Num::Float(-f)),
                }
            }
            _ => None,
        }
    }

    /// The number a name is bound to (a local, else a module item), as [`Interp::lookup`]
    /// would find it; `None` for anything else.
    #[inline]
    fn pure_name(&self, sym: Sym) -> Option<Num> {
        match self.local(sym) {
            Some(v) => Num::of(v),
            None => self.pure_item(sym),
        }
    }

    /// [`Interp::pure_name`] for a module item (out of line: loop arithmetic reads locals).
    #[inline(never)]
    fn pure_item(&self, sym: Sym) -> Option<Num> {
        let items = self.scope.items.borrow();
        let b = items.get(&sym).filter(|b| !b.poisoned)?;
        Num::of(&b.value)
    }

    fn range(
        &mut self,
        s: &Expr,
        e: &Expr,
        inclusive: bool,
        step: Option<&Expr>,
        span: Span,
    ) -> R<Value> {
        let sv = self.eval(s)?;
        let ev = self.eval(e)?;
        let stv = match step {
            Some(x) => Some((self.eval(x)?, x.span)),
            None => None,
        };
        let num = |me: &Self, v: &Value, sp: Span| -> R<f64> {
            v.as_f64()
                .ok_or_else(|| super::types::mismatch(me, "Int", v, sp).into())
        };
        let start = num(self, &sv, s.span)?;
        let end = num(self, &ev, e.span)?;
        let (step, step_int) = match &stv {
            Some((v, sp)) => (num(self, v, *sp)?, matches!(v, Value::Int(_))),
            None => (1.0, true),
        };
        if step == 0.0 || !step.is_finite() || !start.is_finite() || !end.is_finite() {
            let sp = stv.as_ref().map_or(span, |x| x.1);
            return Err(error(
                "rtc::value::range_step",
                sp,
                "a range needs a finite, non-zero step",
            )
            .with_label("this range would never end")
            .with_help("use a positive `step`, e.g. `step 0.1`")
            .into());
        }
        let ints = matches!(sv, Value::Int(_)) && matches!(ev, Value::Int(_)) && step_int;
        Ok(Value::Range(super::value::Range {
            start,
            end,
            step,
            inclusive,
            ints,
        }))
    }
}
