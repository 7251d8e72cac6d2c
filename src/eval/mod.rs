//! Evaluation of `.rtc` files to the IR. (Contract placeholder: the language branch replaces it.)

use std::path::Path;

use crate::diag::Diagnostic;
use crate::frontend::Loaded;
use crate::source::SourceMap;

/// Budgets that keep evaluation finite; each overrun is a clear error.
#[derive(Clone, Debug)]
pub struct EvalOptions {
    /// Total loop iterations over the whole evaluation.
    pub max_loop_iterations: u64,
    /// Depth of nested user-function calls.
    pub max_recursion_depth: u32,
    /// Objects in the scene.
    pub max_objects: u64,
    /// Elements in any one list.
    pub max_list_len: u64,
}

impl Default for EvalOptions {
    fn default() -> EvalOptions {
        EvalOptions {
            max_loop_iterations: 50_000_000,
            max_recursion_depth: 256,
            max_objects: 10_000_000,
            max_list_len: 10_000_000,
        }
    }
}

/// Parses and evaluates the scene file at `path` (already read into `sources` by the caller or not).
pub fn load_file(path: &Path, sources: &mut SourceMap, _options: &EvalOptions) -> Loaded {
    let _ = (path, sources);
    let mut loaded = Loaded::default();
    loaded.diagnostics.push(Diagnostic::new(
        crate::diag::Severity::Error,
        "rtc::unsupported",
        None,
        "the scene language is not built yet",
    ));
    loaded
}
