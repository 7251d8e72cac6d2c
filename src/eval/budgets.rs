//! The evaluation's budgets on what it builds and how long it runs (docs/language.md §24):
//! list and string lengths, the memory budget its strings, lists and objects are charged to,
//! the loop steps, and the `--time-limit` deadline. Plain functions of the counts, so this
//! file stands below the interpreter (whose methods in `interp.rs` call them with its state).

use std::time::Instant;

use crate::diag::Diagnostic;
use crate::ir::limits::Memory;
use crate::source::Span;

use super::error::{R, error};

/// Bytes one object of the scene is charged: its IR form, which the scene keeps to the end,
/// twice over, for the list that holds them grows by doubling (measured: a grid of 2.8 million
/// spheres peaks at 425 bytes an object, this charges 2 × 190).
pub(crate) const OBJECT_BYTES: u64 = 2 * std::mem::size_of::<crate::ir::Object>() as u64;

/// How often (in loop steps) the deadline is looked at: reading the clock is far dearer than
/// a step.
const CLOCK_EVERY: u64 = 1024;

/// What a loop step is, for the loop budget's error.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Step {
    /// An iteration of a `for`.
    Loop,
    /// A step of `iterate`.
    Iterate,
    /// A call of a user function (recursion is a loop too: `f(n - 1) + f(n - 1)` doubles).
    Call,
}

/// What emitting objects may use: their count and the bytes left after the values made.
pub(crate) struct ObjectBudget {
    /// Most objects.
    pub(crate) max_objects: u64,
    /// The memory budget with the values' bytes charged.
    pub(crate) memory: Memory,
}

impl ObjectBudget {
    /// The error when the scene's `objects` no longer fit the memory budget, if they do not.
    pub(crate) fn check_memory(&self, objects: usize, span: Span) -> Result<(), Diagnostic> {
        let mut m = self.memory;
        m.charge((objects as u64).saturating_mul(OBJECT_BYTES))
            .map_err(|over| over.diagnostic(span, &format!("the scene's {objects} objects")))
    }
}

/// A string of `len` bytes against the budget of `max`.
pub(crate) fn string_len(len: usize, max: u64, span: Span) -> R<()> {
    if len as u64 > max {
        return Err(error("rtc::budget::string", span, "string is too long")
            .with_label(format!("this string grows past {max} bytes"))
            .with_help("build shorter text; strings label and report, they do not hold data")
            .into());
    }
    Ok(())
}

/// A list of `len` elements against the budget of `max`.
pub(crate) fn list_len(len: usize, max: u64, span: Span) -> R<()> {
    if len as u64 > max {
        return Err(error("rtc::budget::list", span, "list is too long")
            .with_label(format!("this list grows past {max} elements"))
            .with_help("build fewer elements, e.g. with a coarser `step`")
            .into());
    }
    Ok(())
}

/// Charges `bytes` that `what` (at `span`) is about to hold to `memory`.
pub(crate) fn charge(memory: &mut Memory, bytes: u64, span: Span, what: &str) -> R<()> {
    memory
        .charge(bytes)
        .map_err(|over| over.diagnostic(span, what).into())
}

/// Step number `steps` (counted already) against the loop budget of `max`, and now and then
/// against the deadline.
pub(crate) fn step(
    steps: u64,
    max: u64,
    deadline: Option<Instant>,
    span: Span,
    kind: Step,
) -> R<()> {
    if steps > max {
        let (label, help) = match kind {
            Step::Loop => (
                format!("the scene's loops ran more than {max} iterations in total"),
                "reduce the ranges of the loops",
            ),
            Step::Iterate => (
                format!("`iterate` ran past the budget of {max} iterations"),
                "make sure `while` becomes false",
            ),
            Step::Call => (
                format!("the scene's loops and calls ran more than {max} steps in total"),
                "make sure the recursion reaches a base case, and that it does not branch into more calls at every level",
            ),
        };
        return Err(error("rtc::budget::loop", span, "loop budget exhausted")
            .with_label(label)
            .with_help(help)
            .into());
    }
    if steps.is_multiple_of(CLOCK_EVERY)
        && let Some(deadline) = deadline
        && Instant::now() >= deadline
    {
        return Err(error(
            "rtc::render::time_limit",
            span,
            "the scene did not finish evaluating within the time limit; no image was written",
        )
        .with_label("still evaluating here")
        .with_help("allow more time (`--time-limit`), or make the loops shorter")
        .into());
    }
    Ok(())
}
