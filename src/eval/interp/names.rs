//! Names: a lookup goes through the locals of the current frame, then the module's items,
//! then the built-ins; an unknown name gets the did-you-mean and the std module that has it.

use crate::diag::Diagnostic;
use crate::source::Span;
use crate::syntax::intern::Sym;

use super::super::error::{EvalError, R, error, suggest};
use super::super::value::Value;
use super::Interp;

impl Interp<'_> {
    /// Looks a name up: locals of this frame, then module items, then built-ins.
    #[inline]
    pub(crate) fn lookup(&self, sym: Sym, span: Span) -> R<Value> {
        match self.local(sym) {
            // Numbers (loop variables, mostly) copied without the out-of-line `clone`.
            Some(Value::Int(i)) => Ok(Value::Int(*i)),
            Some(Value::Float(f)) => Ok(Value::Float(*f)),
            Some(v) => Ok(v.clone()),
            None => self.lookup_global(sym, span),
        }
    }

    /// The innermost local named `sym` in the current frame.
    #[inline(always)]
    pub(super) fn local(&self, sym: Sym) -> Option<&Value> {
        self.locals[self.frame_base..]
            .iter()
            .rev()
            .find(|(k, _)| *k == sym)
            .map(|(_, v)| v)
    }

    /// Looks up a name that is not a local: module items, then built-ins.
    #[inline(never)]
    fn lookup_global(&self, sym: Sym, span: Span) -> R<Value> {
        if let Some(b) = self.scope.items.borrow().get(&sym) {
            return if b.poisoned {
                Err(EvalError::Poisoned)
            } else {
                Ok(b.value.clone())
            };
        }
        if let Some(v) = super::super::builtins::global(sym) {
            return Ok(v);
        }
        if let Some(v) = super::super::params::frame_builtin(self.opts, sym.as_str()) {
            return Ok(v);
        }
        Err(self.unknown_name(sym, span).into())
    }

    #[cold]
    #[inline(never)]
    fn unknown_name(&self, sym: Sym, span: Span) -> Diagnostic {
        let mut names: Vec<&'static str> = self.locals[self.frame_base..]
            .iter()
            .map(|(k, _)| k.as_str())
            .collect();
        names.extend(self.scope.items.borrow().keys().map(|k| k.as_str()));
        names.extend(super::super::builtins::global_names());
        names.extend(super::super::params::FRAME_BUILTINS);
        names.sort_unstable();
        let d = error("rtc::name::unknown", span, format!("unknown name `{sym}`"))
            .with_label("not defined here");
        if let Some(m) = super::super::modules::std_modules_exporting(sym.as_str()).first() {
            return d.with_help(format!(
                "`{sym}` is in `std.{m}`: add `import std.{m} {{ {sym} }}` at the top of the file"
            ));
        }
        match suggest(sym.as_str(), names) {
            Some(h) => d.with_help(h),
            None => d.with_help(format!("define it first, e.g. `let {sym} = ...`")),
        }
    }
}
