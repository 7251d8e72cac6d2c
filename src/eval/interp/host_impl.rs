//! The interpreter as the [`Host`] of the built-ins it calls: each service delegates to the
//! interpreter's own method of the same name. That method must be visible here (declared in
//! `interp/mod.rs`, or `pub(crate)` in a sibling file): were it private to a sibling,
//! `Interp::name(self, ..)` would resolve to this trait method and recurse forever (rustc's
//! `unconditional_recursion` warning).

use std::path::Path;

use crate::diag::Diagnostic;
use crate::source::Span;

use super::super::args::ArgVal;
use super::super::budgets::Step;
use super::super::error::R;
use super::super::host::Host;
use super::super::value::Value;
use super::Interp;

impl Host for Interp<'_> {
    fn warn(&mut self, d: Diagnostic) {
        Interp::warn(self, d);
    }

    fn report(&mut self, d: Diagnostic) {
        Interp::report(self, d);
    }

    fn next_made(&mut self) -> u64 {
        Interp::next_made(self)
    }

    fn origin(&mut self) -> u32 {
        Interp::origin(self)
    }

    fn derive(&mut self, from: u32) -> u32 {
        Interp::derive(self, from)
    }

    fn step(&mut self, span: Span, kind: Step) -> R<()> {
        Interp::step(self, span, kind)
    }

    fn check_list_len(&self, len: usize, span: Span) -> R<()> {
        Interp::check_list_len(self, len, span)
    }

    fn new_list(&self, len: usize, span: Span) -> R<()> {
        Interp::new_list(self, len, span)
    }

    fn new_string(&self, len: usize, span: Span) -> R<()> {
        Interp::new_string(self, len, span)
    }

    fn charge(&self, bytes: u64, span: Span, what: &str) -> R<()> {
        Interp::charge(self, bytes, span, what)
    }

    fn call_value(&mut self, f: Value, args: Vec<ArgVal>, span: Span, callee: Span) -> R<Value> {
        Interp::call_value(self, f, args, span, callee)
    }

    fn compile_pattern(&mut self, f: Value, span: Span) -> R<crate::pattern::Program> {
        super::super::compile::compile_value(self, f, span)
    }

    fn dir(&self) -> &Path {
        Interp::dir(self)
    }

    fn file_path(&self) -> &Path {
        Interp::file_path(self)
    }
}
