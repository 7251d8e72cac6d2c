//! What a built-in may ask of the evaluator that calls it: budgets, warnings, value numbers,
//! provenance, the current file's folder and calls of function values. Built-ins, operators,
//! methods and the shape, transform and motion constructors take a `&mut dyn Host`, never the
//! interpreter, so they sit below it: the interpreter implements this trait (`host_impl.rs`)
//! and reaches them through their tables, and no built-in reaches back into it.

use std::path::Path;

use crate::diag::Diagnostic;
use crate::source::Span;

use super::args::{ArgVal, CallSite};
use super::budgets::Step;
use super::error::{Quote, R};
use super::value::Value;

/// The signature of every built-in function.
pub(crate) type BuiltinFn = fn(&mut dyn Host, CallSite, Vec<ArgVal>) -> R<Value>;

/// The evaluator's services to the code it calls (implemented by `Interp`).
pub(crate) trait Host: Quote {
    /// Records a warning once per (code, span), however often a loop reaches it.
    fn warn(&mut self, d: Diagnostic);
    /// Records a finding every time (`print`'s notes).
    fn report(&mut self, d: Diagnostic);
    /// Numbers a new material or texture value (values are told apart by these numbers).
    fn next_made(&mut self) -> u64;
    /// The provenance origin of an object made now (0 when provenance is off).
    fn origin(&mut self) -> u32;
    /// The provenance origin of an object derived now from one of origin `from`.
    fn derive(&mut self, from: u32) -> u32;
    /// Counts one loop iteration or call against the loop budget.
    fn step(&mut self, span: Span, kind: Step) -> R<()>;
    /// Checks a list length against the budget.
    fn check_list_len(&self, len: usize, span: Span) -> R<()>;
    /// A new list of `len` elements is about to be made: its length and memory budgets.
    fn new_list(&self, len: usize, span: Span) -> R<()>;
    /// A new string of `len` bytes is about to be made: its length and memory budgets.
    fn new_string(&self, len: usize, span: Span) -> R<()>;
    /// Charges `bytes` that `what` (at `span`) is about to hold to the memory budget.
    fn charge(&self, bytes: u64, span: Span, what: &str) -> R<()>;
    /// Calls a function value (user, literal or built-in) with evaluated arguments.
    fn call_value(&mut self, f: Value, args: Vec<ArgVal>, span: Span, callee: Span) -> R<Value>;
    /// The function value `f` (the argument at `span`) compiled into a pattern's program
    /// (`pattern(f)`; `eval::compile`, which sits above the built-ins).
    fn compile_pattern(&mut self, f: Value, span: Span) -> R<crate::pattern::Program>;
    /// The folder relative asset paths of the current module resolve against.
    fn dir(&self) -> &Path;
    /// The path of the current module's file (for messages).
    fn file_path(&self) -> &Path;
}
