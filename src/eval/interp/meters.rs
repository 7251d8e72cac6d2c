//! The interpreter's meters: its list and string lengths, the bytes it charges to the memory
//! budget and its loop steps, each checked by `budgets` with the interpreter's counts. (No
//! other file imports this one: these are methods.)

use crate::ir::limits::Memory;
use crate::source::Span;

use super::super::budgets;
use super::super::error::R;
use super::super::value::VALUE_BYTES;
use super::Interp;

impl Interp<'_> {
    /// Checks a string length (bytes) against the budget.
    pub(crate) fn check_string_len(&self, len: usize, span: Span) -> R<()> {
        budgets::string_len(len, self.opts.max_string_len, span)
    }

    /// Checks a list length against the budget.
    pub(crate) fn check_list_len(&self, len: usize, span: Span) -> R<()> {
        budgets::list_len(len, self.opts.max_list_len, span)
    }

    /// A new string of `len` bytes is about to be made: its length and memory budgets.
    pub(crate) fn new_string(&self, len: usize, span: Span) -> R<()> {
        self.check_string_len(len, span)?;
        self.charge(len as u64, span, "this string")
    }

    /// A new list of `len` elements is about to be made: its length and memory budgets.
    pub(crate) fn new_list(&self, len: usize, span: Span) -> R<()> {
        self.check_list_len(len, span)?;
        self.charge((len as u64).saturating_mul(VALUE_BYTES), span, "this list")
    }

    /// Charges `bytes` that `what` (at `span`) is about to hold to the memory budget.
    pub(crate) fn charge(&self, bytes: u64, span: Span, what: &str) -> R<()> {
        let mut m = self.memory_used();
        budgets::charge(&mut m, bytes, span, what)?;
        self.memory.set(m.used);
        Ok(())
    }

    /// The memory budget with the values' bytes charged (objects are charged as the lowering
    /// counts them: [`Interp::object_budget`]).
    pub(crate) fn memory_used(&self) -> Memory {
        Memory {
            budget: self.opts.max_memory,
            used: self.memory.get(),
        }
    }

    /// What emitting objects may use now.
    pub(crate) fn object_budget(&self) -> budgets::ObjectBudget {
        budgets::ObjectBudget {
            max_objects: self.opts.max_objects,
            memory: self.memory_used(),
        }
    }

    /// Counts one loop iteration or call against the loop budget, and now and then looks at
    /// the deadline.
    pub(crate) fn step(&mut self, span: Span, kind: budgets::Step) -> R<()> {
        self.loop_iters += 1;
        let (max, deadline) = (self.opts.max_loop_iterations, self.opts.deadline);
        budgets::step(self.loop_iters, max, deadline, span, kind)
    }
}
