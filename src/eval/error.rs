//! Evaluation errors: a diagnostic on its way out, or a marker that one was already reported.

use crate::diag::Diagnostic;
use crate::source::Span;

/// Why evaluation of an expression stopped.
#[derive(Debug)]
pub(crate) enum EvalError {
    /// A new error, unwinding to the statement that will record it (frames are added on the way).
    Diag(Box<Diagnostic>),
    /// The value depends on a statement that already failed; nothing more to say.
    Poisoned,
}

/// The result type of evaluation.
pub(crate) type R<T> = Result<T, EvalError>;

impl From<Diagnostic> for EvalError {
    fn from(d: Diagnostic) -> EvalError {
        EvalError::Diag(Box::new(d))
    }
}

/// Most trace frames kept on one error: the innermost half and the outermost half, so a deep
/// (mutual) recursion shows both where it failed and where it started.
const MAX_FRAMES: usize = 8;

/// The note on a trace whose middle frames were dropped.
const ELIDED: &str =
    "the trace shows the innermost and the outermost calls; the calls in between are left out";

impl EvalError {
    /// Adds an outer trace frame (no-op for poisoned values and once the trace is long).
    pub(crate) fn frame(self, span: Span, message: impl FnOnce() -> String) -> EvalError {
        match self {
            EvalError::Diag(mut d) => {
                let msg = message();
                // Recursion repeats one frame; show it once.
                let repeat = d
                    .trace
                    .last()
                    .is_some_and(|f| f.span == span && f.message == msg);
                if !repeat {
                    if d.trace.len() >= MAX_FRAMES {
                        // Drop the oldest of the outer half: the outermost frames keep coming.
                        d.trace.remove(MAX_FRAMES / 2);
                        if !d.notes.iter().any(|n| n == ELIDED) {
                            d.notes.push(ELIDED.to_string());
                        }
                    }
                    d.trace.push(crate::diag::TraceFrame { span, message: msg });
                }
                EvalError::Diag(d)
            }
            p => p,
        }
    }
}

/// Shorthand for an error diagnostic.
pub(crate) fn error(code: &'static str, span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::error(code, span, message)
}

/// "did you mean" help text, if a candidate is close.
/// A single transposition or edit (`fvo` for `fov`) counts as close even for short names.
pub(crate) fn suggest<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<String> {
    let cands: Vec<&str> = candidates.into_iter().collect();
    let near = cands
        .iter()
        .find(|c| name.len() >= 2 && strsim::osa_distance(name, c) == 1);
    near.copied()
        .or_else(|| crate::diag::did_you_mean(name, cands.iter().copied()))
        .map(|c| format!("a similar name exists: `{c}`"))
}

/// What the type and error helpers need of the evaluation: the source text a span covers, to
/// quote it in a help line. The interpreter is one; so is a source map. Taking this instead of
/// the interpreter keeps the helpers (`types`) below it in the import graph.
pub(crate) trait Quote {
    /// The text `span` covers.
    fn snippet(&self, span: Span) -> &str;
}

impl Quote for crate::source::SourceMap {
    fn snippet(&self, span: Span) -> &str {
        crate::source::SourceMap::snippet(self, span)
    }
}
